// Chained assignments, plain and compound, to variables and swizzles, and under a condition that
// varies per fragment: each assigns the inner target first, then the outer from it.
varying vec2 st;

void main() {
    float a, b;
    a = b = st.x * 2.0;
    float d = a += b *= 0.5;
    vec3 c = vec3(0.25);
    c.xy = c.zx = vec2(st.y, d);
    if (st.y > 0.5) a = b = 0.25;
    gl_FragColor = vec4(a * 0.5, b, c.y * 0.5, 1.0);
}
