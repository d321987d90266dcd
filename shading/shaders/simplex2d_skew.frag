// Seed 002 ("Noise is Beautiful"), line 138: its simplex noise (noise/simplex2d_skew.glsl) as the
// seed gives it, without mainImage; main() is ours: 10 units across the Table 1.1 plane.
varying vec2 st;
void main(void) {
    gl_FragColor = vec4(vec3(noise(st * 10.0)), 1.0);
}
