// Figure 1.2 bricks, anti-aliased with aastep (Listing 1.1) at the mortar edge.
varying vec2 st;
void main(void) {
    float b = max(abs(fract(8.0 * st.s - 0.5 * mod(floor(8.0 * st.t), 2.0)) - 0.5),
                  abs(fract(8.0 * st.t) - 0.5));
    gl_FragColor = vec4(vec3(aastep(0.45, b)), 1.0);
}
