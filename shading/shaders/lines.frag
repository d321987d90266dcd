// Figure 1.2: saw-tooth lines.
varying vec2 st;
void main(void) { gl_FragColor = vec4(vec3(fract(10.0 * st.s)), 1.0); }
