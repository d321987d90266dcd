// Figure 1.1 sphere 3: anti-aliased rings around Worley feature points (fwidth-wide blend).
varying vec3 P;
void main(void) {
    vec2 F = cellular2x2x2(P);
    float s = fwidth(F.x);
    float n1 = smoothstep(0.4 - s, 0.4 + s, F.x);
    float n2 = smoothstep(0.5 - s, 0.5 + s, F.x);
    gl_FragColor = vec4(n1, n2, n2, 1.0);
}
