#extension GL_ARB_shader_texture_lod : require
// probe: an explicit level of detail per pixel (texture2DLod, llvmpipe's textureLod), from below
// the base level to past the last, in steps of 1/8 with exact halves among them.
uniform sampler2D teximage;
varying vec2 st;
void main(void) {
    gl_FragColor = texture2DLod(teximage, st, floor(fract(st.x + st.y) * 80.0) * 0.125 - 1.5);
}
