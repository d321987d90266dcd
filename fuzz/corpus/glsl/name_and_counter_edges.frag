#version 130
// What C++ reads otherwise than GLSL: names the writer's own code uses (a function `each`, a
// global `IterationLanes`, a local `lanes_alike`); a nest whose inner counter reuses the outer
// one's name, and a loop head declaring a counter's name; an inner `c` initialised from the outer
// `c`; the remainder and quotient of counters at negative values and zero; a counter's float
// arithmetic, which double precision computes in double; a counter of each lane's own (handed to
// a function) in a loop lanes leave early.
varying vec2 st;

float IterationLanes = 0.25;
float h(float x) { return fract(sin(x * 12.9898 + 1.0) * 43758.5453); }
float each(float x) { return h(x) * 0.5 + IterationLanes; }
float hj(int n, float x) { return h(x + float(n)); }

void main() {
    vec2 c = floor(st * 2.0);
    float lanes_alike = 0.5;
    float acc = 0.0;
    for (int i = 0; i < 2; i++) {
        for (int i = 0; i < 3; i++) {
            float a = each(c.x + float(i)) + h(c.y) * h(c.x + c.y) + lanes_alike;
            acc += a * 0.1;
        }
    }
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 2; j++) {
            float i = h(c.x + float(j)) + h(c.y) * h(c.x * c.y);
            acc += i * 0.05;
        }
    }
    {
        vec2 c = c + vec2(0.5);
        acc += c.x * 0.25;
    }
    float remainders = 0.0;
    for (int i = -3; i <= 3; i++) {
        remainders += float(i % 2) + float(i / 2);
        if (st.x < 0.0) remainders += float(5 % i) + float(7 / i);  // never taken; i = 0 divides
    }
    for (int i = 0; i < 3; i++) {
        acc += sin((float(i) * 0.1 + 0.37 + st.x) * 1000.0) * 0.01;
    }
    float left = 0.0;
    for (int k = 0; k < 8; k++) {
        if (hj(k, c.x) > 0.5 + st.y * 0.5) break;
        left += 1.0;
    }
    gl_FragColor = vec4(acc, remainders * 0.1, left / 8.0, 1.0);
}
