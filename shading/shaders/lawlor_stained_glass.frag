// Lawlor, Procedural Solid Texturing: "stained glass", F2 - F1 over the 5x5 neighbouring cells.
// Changed: `.xy` added to the shift; tex4 is declared.
uniform sampler2D tex4;
varying vec2 texcoords;
vec4 grid(vec2 loc) {
    float dist=10.0; // distance to closest grid cell
    float second=10.0; // distance to the next-nearest grid cell
    vec2 gridcorner=floor(loc);
    for (float dy=-2.0;dy<=2.0;dy++)
    for (float dx=-2.0;dx<=2.0;dx++)
    {
        vec2 thiscorner=gridcorner+vec2(dx,dy);
        vec2 gridshift=texture2D(tex4,thiscorner*3.456).xy;
        vec2 center=thiscorner+gridshift;
        float radius=length(loc-center);
        if (radius<dist) { // new best
            second=dist;
            dist=radius;
        } else if (radius<second) {
            second=radius; // new second-best
        }
    }
    return 2.0*vec4(second-dist);
}
void main(void) {
    gl_FragColor=grid(texcoords*10.0);
}
