// Gustavson, Procedural Textures in GLSL, Listing 1.2: the analytic gradient of 3D noise in texture
// space taken to window space through the Jacobian of the texture coordinates, for an anti-aliased
// contour line of 3D simplex noise (noise/simplex3d.glsl, the Figure 1.1 demo constants, and its
// gradient noise/simplex3d_grad.glsl) on a solid. "stp is a vec3 of texcoords, G3_stp is a vec3 in
// texcoord space": here stp is the object position P (4 cells per unit). Changed: the listing's
// `Jacobian3 * G3_stp` does not compile (mat2x3 * vec3: "size mismatch for matrix multiplication");
// the window-space gradient is G3_stp * Jacobian3, (dot(G, dFdx stp), dot(G, dFdy stp)), as
// gradient_aa already turns Jacobian2's product around.
varying vec3 P;
void main(void) {
    vec3 stp = P;
    vec3 G3_stp;
    float n = snoise_grad(stp, G3_stp);
    mat2x3 Jacobian3 = mat2x3(dFdx(stp), dFdy(stp));
    vec2 G3_xy = G3_stp * Jacobian3;
    // The noise's change over about a pixel, and the contour n = 0 as a line 0.1 wide in noise
    // units, its edges smoothed over that change.
    float afwidth = 0.7 * length(G3_xy);
    float line = smoothstep(0.1 - afwidth, 0.1 + afwidth, abs(n));
    gl_FragColor = vec4(mix(vec3(0.1, 0.2, 0.5), vec3(1.0, 0.95, 0.8), line), 1.0);
}
