// The GLSL unheld_loop translates (tests/check/wrong_translations.cpp): 0.5 steps until x
// passes 4 s, counted.
varying vec2 st;
void main(void) {
    float x = 0.0, t = st.x * 4.0;
    int n = 0;
    for (int i = 0; i < 16; i++) {
        if (x > t) break;
        x += 0.5;
        n++;
    }
    gl_FragColor = vec4(float(n) / 16.0, x / 8.0, 0.0, 1.0);
}
