varying vec2 st;
float f(float x) { return x < 1.0 ? x : f(x - 1.0); }
void main() { gl_FragColor = vec4(f(st.x)); }
