// Figure 1.2: triangle-wave ridges.
varying vec2 st;
void main(void) { gl_FragColor = vec4(vec3(abs(fract(5.0 * st.s) * 2.0 - 1.0)), 1.0); }
