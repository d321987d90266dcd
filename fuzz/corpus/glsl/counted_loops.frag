#version 130
// Loops every fragment runs equally often (C++ loops in the translation) beside and inside loops a
// fragment leaves on its own (Loop objects), and inside a condition that varies per fragment; a
// built-in's out argument written in a loop lanes leave.
varying vec2 st;

float octaves(vec2 p) {
    float sum = 0.0, scale = 1.0;
    for (int i = 0; i < 4; i++) {
        sum += scale * fract(sin(dot(p, vec2(12.9898, 78.233))) * 43758.5453);
        p *= 2.0;
        scale *= 0.5;
    }
    return sum;
}

void main() {
    vec2 p = st * 3.0;
    float escape = 0.0, inner = 0.0;
    for (int i = 0; i < 8; i++) {
        for (int j = 0; j < 3; j++) inner += 0.01 * float(j) * p.x;
        p = vec2(p.x * p.x - p.y * p.y, 2.0 * p.x * p.y) + st;
        if (dot(p, p) > 4.0) break;
        escape += 1.0;
    }
    float t = st.x, steps = 0.0;
    for (int k = 0; k < 2; k++) {
        while (t < 1.0) {
            t += 0.3 + 0.1 * float(k);
            steps += 1.0;
        }
        t -= 0.9;
    }
    float o = 0.0;
    if (st.y > 0.4) {
        for (float f = 8.0; f >= 0.25; f *= 0.5) o += octaves(st * f) / f;
        for (int j = 0; j < 3; j++) o += 0.125 * fract(st.x * float(j + 2));
    }
    float whole = 0.0, parts = 0.0;
    for (int i = 0; i < 6; i++) {
        if (st.x < 0.15 * float(i)) break;
        parts += modf(st.y * float(i) * 1.7, whole);
    }
    gl_FragColor = vec4(escape / 8.0, fract(inner + whole * 0.1), steps / 8.0 + fract(parts), o * 0.25);
}
