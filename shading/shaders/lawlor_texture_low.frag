// Lawlor, Procedural Solid Texturing: the repeating texture stretched to a lower frequency;
// unchanged, tex4 declared.
uniform sampler2D tex4;
varying vec2 texcoords;
vec4 grid(vec2 loc) {
    return texture2D(tex4,loc*0.5);
}
void main(void) {
    gl_FragColor=grid(texcoords*10.0);
}
