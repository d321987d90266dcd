// Probe of smoothstep with equal edges (undefined in GLSL), as aastep meets it: the edges are
// e -/+ w with a width w that is zero only at run time (the derivatives of a value constant over
// each quad), and every fourth pixel centre sits exactly on e.
// Measured on llvmpipe (Mesa 22.3.6): this gives x > e ? 1 : 0. Writing literally
// smoothstep(e, e, x) instead lets the compiler fold e - e and yields tiny garbage values.
void main(void) {
    float e = floor(gl_FragCoord.x / 4.0) * 4.0 + 2.5;
    float w = 0.7 * length(vec2(dFdx(e), dFdy(e)));
    gl_FragColor = vec4(smoothstep(e - w, e + w, gl_FragCoord.x), step(e, gl_FragCoord.x), w, 1.0);
}
