// Figure 1.5: blobs, 1 - F1^2.
varying vec2 st;
void main(void) {
    vec2 F = cellular(st * 10.0);
    gl_FragColor = vec4(vec3(1.0 - F.x * F.x), 1.0);
}
