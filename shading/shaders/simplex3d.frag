// Figure 1.1 sphere 1: grey 3D simplex noise.
varying vec3 P;
void main(void) {
    float n = snoise(P);
    gl_FragColor = vec4(vec3(0.5 + 0.6 * n), 1.0);
}
