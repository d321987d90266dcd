// The ProcTexGen articles: Ken Perlin's improved noise as a solid texture, 4 lattice cells per
// object unit.
varying vec3 P;
void main(void) {
    gl_FragColor = vec4(vec3(0.5 + 0.5 * inoise(P)), 1.0);
}
