// Table 1.1 "Worley noise" (Figure 1.5 top left): F1 of 2D cellular noise.
varying vec2 st;
void main(void) {
    vec2 F = cellular(st * 10.0);
    gl_FragColor = vec4(vec3(F.x), 1.0);
}
