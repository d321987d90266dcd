// Lawlor, Procedural Solid Texturing: a single repeating texture, "a high note"; unchanged, tex4
// declared.
uniform sampler2D tex4;
varying vec2 texcoords;
vec4 grid(vec2 loc) {
    return texture2D(tex4,loc);
}
void main(void) {
    gl_FragColor=grid(texcoords*10.0);
}
