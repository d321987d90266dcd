// Lawlor, Procedural Solid Texturing: many octaves added together, frequency 8 down to 0.25 (six
// exact halvings); unchanged, tex4 declared.
uniform sampler2D tex4;
varying vec2 texcoords;
vec4 grid(vec2 loc) {
    vec4 ret=vec4(0.0);
    for (float freq=8.0;freq>=0.25;freq*=0.5)
        ret+=texture2D(tex4,loc*freq);
    return (1.0/6.0)*ret;
}
void main(void) {
    gl_FragColor=grid(texcoords);
}
