// Figure 1.1 sphere 2: four octaves of |noise| (turbulence), fire-like colours.
varying vec3 P;
void main(void) {
    float n = abs(snoise(P));
    n += 0.5 * abs(snoise(P * 2.0));
    n += 0.25 * abs(snoise(P * 4.0));
    n += 0.125 * abs(snoise(P * 8.0));
    gl_FragColor = vec4(vec3(1.5 - n, 1.0 - n, 0.5 - n), 1.0);
}
