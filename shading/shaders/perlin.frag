// Table 1.1 "Perlin noise" (Figure 1.4 top left): one octave of 3D simplex noise in a 2D slice.
varying vec2 st;
void main(void) {
    float n = snoise(vec3(10.0 * st, 60.0));
    gl_FragColor = vec4(vec3(0.5 * n + 0.5), 1.0);
}
