// Listing 1.2: anti-aliasing a noise contour with its analytic gradient, mapped from texture
// space to window space by the Jacobian of the coordinates. The listing writes `Jacobian2 * G2_st`;
// the window-space gradient is the row vector times the matrix, `G2_st * Jacobian2`
// (dn/dx = dn/ds ds/dx + dn/dt dt/dx), which is what this shader computes.
varying vec2 st;
void main(void) {
    vec2 p = st * 10.0;
    vec2 G2_st;
    float n = srdnoise(p, 0.0, G2_st);
    mat2 Jacobian2 = mat2(dFdx(p), dFdy(p));
    vec2 G2_xy = G2_st * Jacobian2;
    float afwidth = 0.7 * length(G2_xy);
    gl_FragColor = vec4(vec3(smoothstep(-afwidth, afwidth, n)), 1.0);
}
