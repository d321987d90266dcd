// Figure 1.2: checkerboard.
varying vec2 st;
void main(void) {
    gl_FragColor = vec4(vec3(mod(floor(10.0 * st.s) + floor(10.0 * st.t), 2.0)), 1.0);
}
