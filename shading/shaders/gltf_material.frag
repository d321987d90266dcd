// The default material's fragment stage: the base colour texture (decoded from sRGB) times the
// vertex stage's colour, lit by the flat normal where the mesh has no normals, alphaMode as glTF
// defines it (OPAQUE: alpha 1; MASK: discarded below alphaCutoff, else alpha 1; BLEND: alpha, for
// GL's blending), encoded to sRGB.
uniform sampler2D teximage;  // white where the material has no base colour texture
uniform int uLighting = 2;
uniform int uAlphaMode = 0;  // 0: OPAQUE, 1: MASK, 2: BLEND
uniform float uAlphaCutoff = 0.5;
uniform vec4 uUnproject = vec4(1.0, 1.0, 0.0, 1.0);  // 1 / P[0][0], 1 / P[1][1], P[2][3], P[3][3]
uniform vec2 uResolution;
varying vec4 color;
varying vec2 uv;
varying float viewZ;

void main(void) {
    vec4 texel = texture2D(teximage, uv);
    vec4 base = vec4(decode_srgb(texel.r), decode_srgb(texel.g), decode_srgb(texel.b), texel.a) * color;
    if (uLighting == 2) {
        // The view-space position from the window position and the interpolated depth; the
        // normal of its plane from its derivatives, which always faces the eye.
        vec2 ndc = gl_FragCoord.xy / uResolution * 2.0 - 1.0;
        float w = uUnproject.z * viewZ + uUnproject.w;
        vec3 p = vec3(ndc * w * uUnproject.xy, viewZ);
        base = vec4(base.rgb * lambert(normalize(cross(dFdx(p), dFdy(p)))), base.a);
    }
    if (uAlphaMode == 1 && base.a < uAlphaCutoff) discard;
    vec3 c = clamp(base.rgb, 0.0, 1.0);
    gl_FragColor = vec4(encode_srgb(c.r), encode_srgb(c.g), encode_srgb(c.b), uAlphaMode == 2 ? base.a : 1.0);
}
