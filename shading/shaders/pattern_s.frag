// Figure 1.2: the s coordinate as a grey ramp.
varying vec2 st;
void main(void) { gl_FragColor = vec4(vec3(st.s), 1.0); }
