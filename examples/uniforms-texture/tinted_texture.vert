#version 130
// The scene's inputs by name: its transform and its meshes' POSITION and TEXCOORD_0.
uniform mat4 mvp;
in vec3 position;
in vec2 texcoord;
out vec2 uv;
void main(void) {
    uv = texcoord;
    gl_Position = mvp * vec4(position, 1.0);
}
