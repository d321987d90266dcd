// Lawlor, Procedural Solid Texturing: "To move dots farther than one grid cell": dots shifted by
// tex4 over the 3x3 neighbouring cells, the
// colours of overlapping dots added. Changed: `.xy` added to the shift; the notes give grid()
// only, main() is the other snippets'; tex1 and tex4 are declared.
uniform sampler2D tex1;
uniform sampler2D tex4;
varying vec2 texcoords;
vec4 grid(vec2 loc) {
    vec4 ret=vec4(0.0);
    vec2 gridcorner=floor(loc);
    for (float dy=-1.0;dy<=1.0;dy++)
    for (float dx=-1.0;dx<=1.0;dx++)
    {
        vec2 thiscorner=gridcorner+vec2(dx,dy);
        vec2 gridshift=2.4*texture2D(tex4,thiscorner*3.456).xy;
        vec2 center=thiscorner+vec2(-0.7)+gridshift;
        float radius=length(loc-center);
        if (radius<0.3)
            ret+=texture2D(tex1,center*0.1);
    }
    return ret;
}
void main(void) {
    gl_FragColor=grid(texcoords*10.0);
}
