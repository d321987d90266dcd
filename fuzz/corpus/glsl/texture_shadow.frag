#version 430 compatibility
// sampler2DShadow's lookups, which the C++ translation writer writes and the interpreter runs
// through the vocabulary's functions of their names (shading/glsl/texture_shadow.h): implicit,
// explicit and derivative levels, projective, with and without texel offsets, the legacy
// shadow2D forms, gathers, the level query, and a depth texture passed to a function.
in vec2 st;
out vec4 color;
uniform sampler2DShadow depth;
float lit(sampler2DShadow s, vec3 p) {
    return textureProjOffset(s, vec4(p, 1.0) * (1.5 - st.x), ivec2(2, -3));
}
void main() {
    vec2 p = st * 2.5 - 0.7;
    float ref = fract(st.x * 3.0 + st.y * 1.7) * 1.2 - 0.1;
    float a = texture(depth, vec3(p, ref)) + textureOffset(depth, vec3(p, ref), ivec2(-3, 2), 0.5);
    float b = textureProj(depth, vec4(vec3(p, ref) * (1.0 + st.y), 1.0 + st.y)) + textureLod(depth, vec3(p.yx, ref), 1.0);
    float c = textureGrad(depth, vec3(p, ref), vec2(0.1), vec2(0.2)) + textureGradOffset(depth, vec3(p, ref), vec2(0.1),
                                                                                         vec2(0.2), ivec2(5, 5));
    float d = textureLodOffset(depth, vec3(p * 0.5, ref), 0.0, ivec2(-1, 1)) + lit(depth, vec3(p, ref));
    vec4 e = shadow2D(depth, vec3(p * 0.8, ref)) * 0.5 + shadow2DProj(depth, vec4(p, ref, 1.0) * 2.0) * 0.25 +
             shadow2DLod(depth, vec3(p, ref), st.y * 3.0) * 0.25;
    float f = textureProjLod(depth, vec4(p, ref, 1.0) * (1.0 + st.x), 1.5) +
              textureProjGrad(depth, vec4(p, ref, 2.0) * 0.5, vec2(0.3 * st.y), vec2(0.05)) +
              textureProjLodOffset(depth, vec4(p, ref, 1.0), 0.7, ivec2(3, -1)) +
              textureProjGradOffset(depth, vec4(p, ref, 1.0), vec2(0.0, 0.2), vec2(0.1, 0.0), ivec2(-4, 2)) +
              textureProjOffset(depth, vec4(p, ref, 1.0), ivec2(1, 2), st.x * 2.0 - 1.0) + texture(depth, vec3(p, ref), -1.5);
    vec4 g = textureGather(depth, p, ref) * 0.25 + textureGatherOffset(depth, p.yx, ref, ivec2(-2, 3)) * 0.25 +
             textureGatherOffsets(depth, p, ref, ivec2[4](ivec2(1), ivec2(-1, 0), ivec2(0, 4), ivec2(3, -3))) * 0.5;
    float levels = float(textureQueryLevels(depth));
    vec2 q = textureQueryLod(depth, p * 4.0);
    color = vec4(a * 0.5, b * 0.5, c * 0.25 + d * 0.25, 1.0) * 0.375 + e * 0.375 + g * 0.125 +
            vec4(q * 0.125, levels * 0.1 + f * 0.02, 0.0);
}
