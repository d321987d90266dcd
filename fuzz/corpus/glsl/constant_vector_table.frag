#version 130
// Constant arrays of vectors read at an index that varies per fragment: a table per component.
varying vec2 st;

const vec3 colours[4] = vec3[4](vec3(1.0, 0.2, 0.1), vec3(0.1, 0.8, 0.3), vec3(0.2, 0.3, 0.9), vec3(0.9, 0.9, 0.2));
const ivec2 steps[3] = ivec2[3](ivec2(1, 2), ivec2(3, 1), ivec2(2, 2));

void main() {
    int i = int(floor(st.x * 4.0)) & 3;
    ivec2 k = steps[clamp(int(floor(st.y * 3.0)), 0, 2)];
    gl_FragColor = vec4(colours[i] * float(k.x) / 3.0, float(k.y) * 0.5);
}
