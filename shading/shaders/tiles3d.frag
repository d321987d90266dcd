// Figure 1.1 sphere 4: Worley F2 - F1 "facets" on the warped domain, green tint.
varying vec3 P;
void main(void) {
    vec2 F = cellular(P);
    float n = 0.1 + F.y - F.x;
    gl_FragColor = vec4(0.6 * n, 1.1 * n, 0.5 * n, 1.0);
}
