// Figure 1.5: facets, F2 - F1 of 2D cellular noise.
varying vec2 st;
void main(void) {
    vec2 F = cellular(st * 10.0);
    gl_FragColor = vec4(vec3(0.1 + (F.y - F.x)), 1.0);
}
