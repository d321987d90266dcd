// Figure 1.2 wave, anti-aliased with aastep (Listing 1.1).
varying vec2 st;
void main(void) {
    gl_FragColor = vec4(vec3(aastep(0.0, 0.2 - 0.1 * sin(30.0 * st.s) - st.t)), 1.0);
}
