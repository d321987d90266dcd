#extension GL_ARB_shader_texture_lod : require
// probe: a 3D texture lookup at an explicit level of detail per pixel (texture3DLod).
uniform sampler3D volume;
varying vec2 st;
void main(void) {
    gl_FragColor = texture3DLod(volume, vec3(st, st.x * 0.75 - st.y * 0.5), floor(fract(st.x + st.y) * 48.0) * 0.125 - 1.0);
}
