#version 130
// Every texture lookup the C++ translation writer writes and the interpreter runs, each through
// the vocabulary's function of its name: implicit, biased, explicit and derivative levels of
// detail, projective, with and without texel offsets, fetches and sizes, on a sampler2D and a
// sampler3D.
in vec2 st;
out vec4 color;
uniform sampler2D teximage;
uniform sampler3D volume;
void main() {
    vec2 p = st * 3.0 - 1.0;
    vec2 dx = dFdx(p) * (1.0 + 4.0 * st.x), dy = vec2(0.0, 0.01 * st.y);
    vec4 a = textureGrad(teximage, p, dx, dy) + texture(teximage, p) + texture2D(teximage, p, 0.5);
    vec4 b = textureOffset(teximage, p, ivec2(-3, 2)) + textureOffset(teximage, p, ivec2(1, 1), 0.5);
    vec4 c = textureLodOffset(teximage, p, st.y * 4.0, ivec2(5, -1)) +
             textureGradOffset(teximage, p, dx, dy, ivec2(-2, 0));
    vec4 d = textureProj(teximage, vec3(p, 1.5)) + textureProjOffset(teximage, vec4(p, 0.0, 2.0), ivec2(2, 3)) +
             textureProjLod(teximage, vec3(p, 2.0), 1.0) + textureProjGrad(teximage, vec3(p, 0.5), dy, dx);
    vec4 e = texelFetch(teximage, ivec2(st * 20.0), 1) +
             texelFetchOffset(teximage, ivec2(st * 20.0) - 2, 0, ivec2(1, -1));
    vec4 g = textureProj(teximage, vec3(p, 1.25), 0.5) + textureProjOffset(teximage, vec3(p, 1.5), ivec2(-1, 4), 0.25) +
             textureProjLodOffset(teximage, vec4(p, 0.0, 1.5), 0.5, ivec2(3, -3)) +
             textureProjGradOffset(teximage, vec3(p, 2.0), dx, dy, ivec2(-4, -2)) + textureLod(teximage, p, 2.5 * st.x);
    vec3 q = vec3(p, st.x - st.y);
    vec4 f = textureGrad(volume, q, dFdx(q) * 2.0, dFdy(q)) + textureOffset(volume, q, ivec3(1, -2, 3)) +
             textureLodOffset(volume, q, 1.5, ivec3(0, 4, -4)) +
             texelFetchOffset(volume, ivec3(q * 8.0), 0, ivec3(2, 0, 1));
    vec4 r = vec4(q, 1.25);
    vec4 h = textureOffset(volume, q, ivec3(-1, 0, 2), -0.5) +
             textureGradOffset(volume, q, dFdy(q), dFdx(q), ivec3(3, 1, -2)) + textureProj(volume, r) +
             textureProjOffset(volume, r, ivec3(0, -1, 1), 0.5) + textureProjLod(volume, r, 0.75) +
             textureProjGrad(volume, r, dFdx(q), dFdy(q)) + textureProjLodOffset(volume, r, 2.0, ivec3(1, 1, -1)) +
             textureProjGradOffset(volume, r, dFdx(q), dFdy(q) * 3.0, ivec3(-2, 2, 0)) +
             texelFetch(volume, ivec3(q * 4.0), 1) + texture(volume, q, 1.0);
    vec2 size = vec2(textureSize(teximage, 0));
    ivec3 volume_size = textureSize(volume, 1);
    color = vec4((a.rgb + b.rgb + c.rgb) / 7.0, 1.0) * 0.3 + vec4((d.rgb + e.rgb) / 6.0, size.x / 256.0) * 0.15 +
            vec4(g.rgb / 5.0, 1.0) * 0.15 + vec4(f.rgb / 4.0, 1.0) * 0.2 +
            vec4(h.rgb / 10.0, float(volume_size.z) / 16.0) * 0.2;
}
