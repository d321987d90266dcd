// Lawlor, Procedural Solid Texturing: the high and the low octave added together; unchanged, tex4
// declared.
uniform sampler2D tex4;
varying vec2 texcoords;
vec4 grid(vec2 loc) {
    vec4 high=texture2D(tex4,loc);
    vec4 low=texture2D(tex4,loc*0.5);
    return 0.5*(high+low);
}
void main(void) {
    gl_FragColor=grid(texcoords*10.0);
}
