// Lawlor, Procedural Solid Texturing: "Or you can draw a grid of dots", unchanged.
varying vec2 texcoords;
vec4 grid(vec2 loc) {
    vec2 gridcorner=floor(loc);
    vec2 gridcenter=gridcorner+vec2(0.5);
    float radius=length(loc-gridcenter);
    if (radius<0.3)
        return vec4(1,0,0,1); // red
    else
        return vec4(0,0,0,1); // black
}
void main(void) {
    gl_FragColor=grid(texcoords*10.0);
}
