// Lawlor, Procedural Solid Texturing: "consistent colors across the dots", tex1 at each dot's
// centre, unchanged; tex1 is
// declared (NetRun declared it).
uniform sampler2D tex1;
varying vec2 texcoords;
vec4 grid(vec2 loc) {
    vec2 gridcorner=floor(loc);
    vec2 gridcenter=gridcorner+vec2(0.5);
    float radius=length(loc-gridcenter);
    if (radius<0.3)
        return texture2D(tex1,gridcenter*0.1); // read texture 3
    else
        return vec4(0,0,0,1); // black
}
void main(void) {
    gl_FragColor=grid(texcoords*10.0);
}
