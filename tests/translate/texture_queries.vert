#version 130
// texture_queries.frag's vertex stage, in GLSL 1.30: the writer refuses a vertex stage of GLSL
// 1.50 or later, the front end's own for a 4.00 fragment shader included ("an array of unknown
// size": from 1.50 on, the built-in gl_PerVertex block holds gl_ClipDistance[]).
in vec4 position;
in vec2 texcoord;
uniform mat4 mvp;
out vec2 st;
void main() {
    st = texcoord;
    gl_Position = mvp * position;
}
