// Table 1.1 "5x Perlin" (Figure 1.4 bottom left): five octaves of fractal noise.
varying vec2 st;
void main(void) {
    float n = snoise(vec3(5.0 * st, 50.0));
    n += 0.5 * snoise(vec3(10.0 * st, 60.0));
    n += 0.25 * snoise(vec3(20.0 * st, 70.0));
    n += 0.125 * snoise(vec3(40.0 * st, 80.0));
    n += 0.0625 * snoise(vec3(80.0 * st, 90.0));
    gl_FragColor = vec4(vec3(0.4 * n + 0.5), 1.0);
}
