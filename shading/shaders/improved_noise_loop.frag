// The ProcTexGen articles, "Crazy 8s": texShaderNoise, improved noise looping every 8 cells (repeat
// 8, base 0, the articles' values), 8 cells per object unit: a unit sphere spans two periods.
varying vec3 P;
void main(void) {
    gl_FragColor = vec4(vec3(0.5 + 0.5 * texShaderNoise(P, 8, 0)), 1.0);
}
