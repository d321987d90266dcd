#version 130
// The varyings of scene_inputs.vert as colours, smooth and within [0, 1] on every scene.
in vec3 world;
in vec3 turned;
in vec2 ndc;
void main(void) {
    vec3 w = 0.5 + 0.5 * sin(world);
    float r = (w.x + w.y + w.z) / 3.0;
    float g = clamp(0.5 + 0.2 * (turned.x + turned.y) + 0.25 * ndc.x, 0.0, 1.0);
    float b = clamp(0.5 + 0.2 * turned.z + 0.25 * ndc.y, 0.0, 1.0);
    gl_FragColor = vec4(r, g, b, 1.0);
}
