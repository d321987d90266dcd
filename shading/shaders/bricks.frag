// Figure 1.2: bricks, every other row offset by half a brick.
varying vec2 st;
void main(void) {
    float b = max(abs(fract(8.0 * st.s - 0.5 * mod(floor(8.0 * st.t), 2.0)) - 0.5),
                  abs(fract(8.0 * st.t) - 0.5));
    gl_FragColor = vec4(vec3(smoothstep(0.4, 0.5, b)), 1.0);
}
