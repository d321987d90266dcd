// Noise is Beautiful (notes), "Simplex Noise: Sample Code": the simplex noise
// (noise/simplex2d_skew.glsl) as the notes give it, without mainImage; main() is ours: 10 units
// across the Table 1.1 plane.
varying vec2 st;
void main(void) {
    gl_FragColor = vec4(vec3(noise(st * 10.0)), 1.0);
}
