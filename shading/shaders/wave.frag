// Figure 1.2: a sine wave edge with a fixed blend width.
varying vec2 st;
void main(void) {
    gl_FragColor = vec4(vec3(smoothstep(-0.01, 0.01, 0.2 - 0.1 * sin(30.0 * st.s) - st.t)), 1.0);
}
