// Noise is Beautiful (notes), "Multifractal Combinations": "The most generic way this can be done
// is as follows: [the sum, an image] Make sure to divide by 2 after if you want to normalize back
// to [0,1]." Written as the notes' warping code writes its loop (a float counter, pow(2., i)): the
// sum over 5 octaves of 2^-i noise(2^i xy), simplex2d_skew's noise, xy 4 units across the Table 1.1
// plane. The octaves are neither rotated nor translated (the notes' "Properties and Defects of
// Perlin Noise" suggest both against artefacts at the origin): this is the plain form.
varying vec2 st;
void main(void) {
    vec2 xy = st * 4.0;
    float k = 5.;
    float c = 0.;
    for (float i = 0.; i < k; i++) {
        c += pow(2., -i) * noise(pow(2., i) * xy);
    }
    c /= 2.;
    gl_FragColor = vec4(vec3(c), 1.0);
}
