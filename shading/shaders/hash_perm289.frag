// Noise is Beautiful (notes), "Permutation Polynomials": the polynomial (34h + 10)h mod 289
// and cellnoise_perm, unchanged (`289.0f` is GLSL 1.20). The notes do not floor the input:
// shown on the corners of 32 cells across the plane.
varying vec2 st;
float permute(float x) {
    float h = mod(x, 289.0f);
    return mod((34.0 * h + 10.0) * h, 289.0);
}
// As always, we can generalize this to higher dimensions by chaining
float cellnoise_perm(vec2 p) {
    // The division by 288.0 normalizes to [0,1].
    return permute(permute(p.x) + p.y) / 288.0;
}
void main(void) {
    gl_FragColor = vec4(vec3(cellnoise_perm(floor(st * 32.0))), 1.0);
}
