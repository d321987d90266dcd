// Noise is Beautiful (notes), "Generating Noise (3D)" of "Simplex Noise": 3D simplex noise with
// Fibonacci-sphere gradients (noise/simplex3d_fibonacci.glsl) as a solid texture, 4 cells per
// object unit.
varying vec3 P;
void main(void) {
    vec3 grad;
    gl_FragColor = vec4(vec3(noise3(P, grad)), 1.0);
}
