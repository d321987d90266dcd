// Figure 1.5: rings between two anti-aliased thresholds of F1.
varying vec2 st;
void main(void) {
    vec2 F = cellular(st * 10.0);
    gl_FragColor = vec4(vec3(1.0 - aastep(0.45, F.x) + aastep(0.55, F.x)), 1.0);
}
