// Figure 1.1 sphere 3: anti-aliased rings around Worley feature points (fwidth-wide blend).
// quadshade's error study also builds it with SPOTS_LENGTH (the gradient's length instead of
// fwidth) or SPOTS_STEP (no anti-aliasing).
varying vec3 P;
void main(void) {
    vec2 F = cellular2x2x2(P);
#if defined(SPOTS_STEP)
    float n1 = step(0.4, F.x);
    float n2 = step(0.5, F.x);
#else
#if defined(SPOTS_LENGTH)
    float s = length(vec2(dFdx(F.x), dFdy(F.x)));
#else
    float s = fwidth(F.x);
#endif
    float n1 = smoothstep(0.4 - s, 0.4 + s, F.x);
    float n2 = smoothstep(0.5 - s, 0.5 + s, F.x);
#endif
    gl_FragColor = vec4(n1, n2, n2, 1.0);
}
