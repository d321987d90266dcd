// Noise is Beautiful (notes), "Derivatives of Simplex Noise": "For 2D noise, we can find the
// derivatives by summing" (the sum was an image): dnoise (noise/simplex2d_skew.glsl) shown as
// colour, 10 units across the Table 1.1 plane: red and green the gradient's x and y around 0.5,
// blue the noise.
varying vec2 st;
void main(void) {
    vec2 p = st * 10.0;
    gl_FragColor = vec4(0.5 + 0.15 * dnoise(p), noise(p), 1.0);
}
