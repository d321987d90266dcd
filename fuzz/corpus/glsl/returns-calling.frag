varying vec2 st;
float f3(float x) { return x * x + 1.0; }
float f2(float x) { return f3(x) - f3(x + 1.0); }
float f1(float x) { return f2(x) * f2(st.y); }
void main() { gl_FragColor = vec4(f1(st.x)); }
