// Table 1.1 "Single texture": one bilinear lookup, clamp to edge, no mipmaps.
uniform sampler2D teximage;
varying vec2 st;
void main(void) {
    gl_FragColor = texture2D(teximage, st);
}
