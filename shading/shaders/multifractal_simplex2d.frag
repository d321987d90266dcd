// Noise is Beautiful (notes), "Multifractal Combinations": "weigh later terms on a value dependent
// on previous terms ... One example of this is setting [a formula, an image, lost], which gives
// good results for terrain." A reconstruction: octave i weighted by 2^-i times the previous
// octave's noise (1 for the first), so detail grows where the coarser octave is high;
// fbm_simplex2d's loop otherwise (5 octaves, xy 4 units across, divided by 2).
varying vec2 st;
void main(void) {
    vec2 xy = st * 4.0;
    float k = 5.;
    float c = 0.;
    float previous = 1.;
    for (float i = 0.; i < k; i++) {
        float n = noise(pow(2., i) * xy);
        c += pow(2., -i) * previous * n;
        previous = n;
    }
    c /= 2.;
    gl_FragColor = vec4(vec3(c), 1.0);
}
