// The ProcTexGen articles, "Cellular Noise": one of their eight displays of voronoi()
// ("Left: F1 Right: F2",
// "Left: F2-F1 Right: (F1+F2)/2", "the same 4 calculations, using manhattan distance"), chosen by
// the defines WORLEY3D_MANHATTAN and WORLEY3D_SHOW(f1, f2); grey, Manhattan distances halved
// (WORLEY3D_SCALE: they run to about 1.8). Jitter .9, the articles' default; 4 cells per unit.
varying vec3 P;
void main(void) {
    float f1, f2;
    vec3 pos1, pos2;
    voronoi(P, f1, pos1, f2, pos2, .9, WORLEY3D_MANHATTAN);
    gl_FragColor = vec4(vec3(WORLEY3D_SCALE * WORLEY3D_SHOW(f1, f2)), 1.0);
}
