// A baked atlas drawn lit (quadshade bake --maps color,normal): the colour from teximage (the
// material's baseColorTexture), the object-space normal from `normalmap` (encoded as
// 0.5 + 0.5 n, render/normal_bake.h), normalised again after filtering, and Lambert's law for one
// directional light fixed in object space (towards (0.3, 0.8, 0.6), 0.2 ambient). The texcoords
// come from plane_st.vert.
uniform sampler2D teximage;
uniform sampler2D normalmap;
varying vec2 st;
void main(void) {
    vec4 color = texture2D(teximage, st);
    vec3 N = normalize(texture2D(normalmap, st).xyz * 2.0 - 1.0);
    vec3 L = vec3(0.2873479, 0.7662610, 0.5746958);
    float diffuse = max(dot(N, L), 0.0);
    gl_FragColor = vec4(color.rgb * (0.2 + 0.8 * diffuse), color.a);
}
