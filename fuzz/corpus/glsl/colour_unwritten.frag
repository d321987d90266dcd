#version 120
// The colour where main() leaves it unwritten: lanes whose branch does not write it read black,
// as GLSL's output zeroed in the interpreter does.
varying vec2 st;

void main() {
    float edge = st.x + 0.25 * st.y;
    if (st.y > 0.6) {
        gl_FragColor = vec4(st, edge, 1.0);
    } else if (st.y < 0.3) {
        gl_FragColor = vec4(edge);
    }
}
