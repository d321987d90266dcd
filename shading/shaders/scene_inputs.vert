#version 130
// The scene's inputs by name (scenes/shader_inputs.h): every transform and the vertex inputs a
// mesh of these scenes has, each folded into a varying so that a wrong one shows.
uniform mat4 mvp;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform mat3 normalMatrix;
in vec3 position;
in vec2 texcoord;
out vec3 world;
out vec3 turned;
out vec2 ndc;
void main(void) {
    vec4 w = model * vec4(position, 1.0);
    world = w.xyz + vec3(texcoord, 0.0);
    turned = normalMatrix * vec3(0.6, 0.0, 0.8);
    vec4 clip = projection * (view * w);
    ndc = clip.xy / clip.w;
    gl_Position = mvp * vec4(position, 1.0);
}
