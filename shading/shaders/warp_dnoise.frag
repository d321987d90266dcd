// Noise is Beautiful (notes), "Warping": "displacing each term of the noise
// sum with the summed gradients of the previous terms". The notes' loop unchanged; it is cut off
// around it (no xy, no output): xy is 4 units across the Table 1.1 plane, noise and dnoise are
// noise/simplex2d_skew.glsl's, c is shown as grey.
varying vec2 st;
void main(void) {
    vec2 xy = st * 4.0;
    float k = 3.;
    float c = 0.;
    vec2 disp = vec2(0);
    for (float i = 0.; i < k; i++) {
    // We displace what we're sampling from the noise function here
    vec2 trans_xy = pow(2., i) * (xy + disp);
    c += pow(2., -i) * noise(trans_xy);
    // Update our displacement based on the sampled gradient
    disp += dnoise(trans_xy);
    }
    c /= 2.;
    gl_FragColor = vec4(vec3(c), 1.0);
}
