// noise_bumps' height as grey: the height map `quadshade bake --maps height` writes is this
// shader's atlas.
varying vec3 P;
void main(void) {
    gl_FragColor = vec4(vec3(height(P)), 1.0);
}
