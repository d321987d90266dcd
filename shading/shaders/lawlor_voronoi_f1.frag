// Lawlor, Procedural Solid Texturing: "just the distance to the nearest grid cell", Voronoi F1: the
// distance to the nearest of the 3x3 neighbouring cells' points (shifted by tex4), written to all
// four channels. Changed: `.xy` added to the shift; main() added (the notes give grid() only); tex4
// is declared.
uniform sampler2D tex4;
varying vec2 texcoords;
vec4 grid(vec2 loc) {
    float dist=10.0; // distance to closest grid cell
    vec2 gridcorner=floor(loc);
    for (float dy=-1.0;dy<=1.0;dy++)
    for (float dx=-1.0;dx<=1.0;dx++)
    {
        vec2 thiscorner=gridcorner+vec2(dx,dy);
        vec2 gridshift=texture2D(tex4,thiscorner*3.456).xy;
        vec2 center=thiscorner+gridshift;
        float radius=length(loc-center);
        dist=min(radius,dist);
    }
    return vec4(dist);
}
void main(void) {
    gl_FragColor=grid(texcoords*10.0);
}
