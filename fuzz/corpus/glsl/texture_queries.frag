#version 430
// GLSL 4.00's gathers and 4.30's level queries, which the C++ translation writer writes and the
// interpreter runs through the vocabulary's functions of their names (shading/glsl/
// texture_queries.h): every channel, with one texel offset or four, on a sampler2D; the level
// of detail of a sampler2D and a sampler3D, and their levels.
in vec2 st;
out vec4 color;
uniform sampler2D teximage;
uniform sampler3D volume;
void main() {
    vec2 p = st * 3.0 - 1.0;
    vec4 a = textureGather(teximage, p) + textureGather(teximage, p * 0.5, 1) + textureGather(teximage, p.yx, 2);
    vec4 b = textureGatherOffset(teximage, p, ivec2(-3, 5)) + textureGatherOffset(teximage, p, ivec2(7, -8), 3);
    vec2 l = textureQueryLod(teximage, p * exp2(st.x * 6.0 - 2.0));
    vec2 m = textureQueryLod(volume, vec3(p, st.x - st.y) * exp2(st.y * 4.0));
    const ivec2 offsets[4] = ivec2[4](ivec2(0, 0), ivec2(-2, 1), ivec2(3, -4), ivec2(7, 7));
    vec4 c = textureGatherOffsets(teximage, p, offsets) + textureGatherOffsets(teximage, p.yx, offsets, 2);
    float levels = float(textureQueryLevels(teximage) + textureQueryLevels(volume)) / 32.0;
    color = vec4(a.xyz / 3.0 * 0.3 + b.yzw / 2.0 * 0.3 + c.xzw / 2.0 * 0.3 + levels * 0.1, 1.0) * 0.6 +
            vec4(l / 8.0 + 0.5, m / 8.0 + 0.5) * 0.4;
}
