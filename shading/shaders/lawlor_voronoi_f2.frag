// Lawlor, Procedural Solid Texturing: "the distance to the *second* nearest grid point", Voronoi
// F2: the distance to the second-nearest point over the 5x5 neighbouring cells. Changed: `.xy`
// added to the shift; main() added (the notes give grid() only); tex4 is declared.
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
    return vec4(second*0.7);
}
void main(void) {
    gl_FragColor=grid(texcoords*10.0);
}
