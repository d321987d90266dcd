#version 400 compatibility
// samplerCube's and samplerCubeShadow's lookups, which the C++ translation writer writes and the
// interpreter runs through the vocabulary's functions of their names (shading/glsl/texture_cube.h):
// implicit (per pixel on a mipmapped cube map), biased, explicit and derivative levels, the legacy
// names, the size and level queries, comparisons, gathers, and a cube map passed to a function.
in vec2 st;
out vec4 color;
uniform samplerCube env;
uniform samplerCubeShadow depth;
vec3 sky(samplerCube s, vec3 d) {
    return textureCube(s, d, -0.5).rgb;
}
void main() {
    vec2 p = st * 2.0 - 1.0;
    vec3 dir = vec3(p * 2.5, 1.0 - p.x);
    vec3 a = texture(env, dir).rgb + texture(env, dir.yzx * 9.0, p.y * 2.0).rgb;
    vec3 b = textureLod(env, -dir, st.x * 5.0).rgb + textureCubeLod(env, dir.zxy, 1.5).rgb;
    vec3 c = textureGrad(env, dir, dFdx(dir) * 4.0, vec3(0.0, 0.03, 0.0)).rgb + sky(env, dir.xzy);
    float ref = fract(st.x * 3.0 + st.y * 1.7) * 1.2 - 0.1;
    float d = texture(depth, vec4(dir, ref)) + texture(depth, vec4(-dir.zyx, ref), 1.0) +
              textureGrad(depth, vec4(dir.yxz, ref), vec3(0.1), vec3(0.2));
    vec2 size = vec2(textureSize(env, 1) + textureSize(depth, 0)) / 64.0;
    vec4 g = textureGather(env, dir, 2) * 0.5 + textureGather(depth, dir.zyx, ref) * 0.5;
    vec2 q = textureQueryLod(env, dir * 3.0) + textureQueryLod(depth, dir.yzx * 0.5);
    color = vec4(a * 0.25 + b * 0.25, 1.0) * 0.5 + vec4(c * 0.25, 1.0) * 0.25 + vec4(d / 3.0, size, 1.0) * 0.0625 +
            g * 0.125 + vec4(q * 0.0625, 0.0, 0.0);
}
