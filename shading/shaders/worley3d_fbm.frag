// The ProcTexGen articles, "Cellular Noise": "it still looks pretty cool if you use fBm on it. For
// instance: 4 octaves of F1 Worley noise" (no code given): F1 at frequencies 1, 2, 4, 8 with
// weights 1, 1/2, 1/4, 1/8, divided by their sum 1.875. Euclidean, jitter .9; 4 cells per unit.
varying vec3 P;
void main(void) {
    float sum = 0.0, amplitude = 1.0, frequency = 1.0;
    for (int octave = 0; octave < 4; octave++) {
        float f1, f2;
        vec3 pos1, pos2;
        voronoi(P * frequency, f1, pos1, f2, pos2, .9, false);
        sum += amplitude * f1;
        frequency *= 2.0;
        amplitude *= 0.5;
    }
    gl_FragColor = vec4(vec3(sum / 1.875), 1.0);
}
