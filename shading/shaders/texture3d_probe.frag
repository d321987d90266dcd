// probe: a 3D texture lookup with the quad's level of detail, r running diagonally across the
// plane's st.
uniform sampler3D volume;
varying vec2 st;
void main(void) {
    gl_FragColor = texture3D(volume, vec3(st, st.x * 0.75 - st.y * 0.5));
}
