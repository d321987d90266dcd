// probe: the quad's level of detail plus a bias per pixel (texture2D's third argument).
uniform sampler2D teximage;
varying vec2 st;
void main(void) {
    gl_FragColor = texture2D(teximage, st, fract(st.y * 2.0) * 3.0 - 1.0);
}
