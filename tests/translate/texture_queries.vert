#version 130
// texture_queries.frag's vertex stage: the writer does not write the vertex shader the front end
// makes for a GLSL 4.00 fragment shader (its built-in gl_ClipDistance is an array of unknown size).
in vec4 position;
in vec2 texcoord;
uniform mat4 mvp;
out vec2 st;
void main() {
    st = texcoord;
    gl_Position = mvp * position;
}
