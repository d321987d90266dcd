// Noise is Beautiful (notes), "Derivatives of Simplex Noise": "And for 3D noise, we can find the
// derivative by summing" (the sum was an image): the gradient noise3 returns
// (noise/simplex3d_fibonacci.glsl) as colour around 0.5, a solid texture (4 cells per object unit).
varying vec3 P;
void main(void) {
    vec3 grad;
    noise3(P, grad);
    gl_FragColor = vec4(0.5 + 0.15 * grad, 1.0);
}
