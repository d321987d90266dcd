// Probe of the derivatives of an interpolated varying: d(st)/dx in red and green, d(st)/dy in
// blue and alpha, written to a float target. On a GPU these are quad differences; quadshade also
// gives them analytically (Dual2: plane derivatives, or ray differentials when ray casting).
varying vec2 st;
void main(void) {
    gl_FragColor = vec4(dFdx(st), dFdy(st));
}
