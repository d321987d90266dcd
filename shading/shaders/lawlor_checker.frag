// Lawlor, Procedural Solid Texturing: "you can draw a checkerboard grid".
// Changed: `^` between the two comparisons is `^^`, GLSL's logical xor (GLSL 1.20 reserves `^`
// and 1.30 defines it for integers only); `<` binds tighter than `^^`, as the notes intend.
varying vec2 texcoords;
vec4 grid(vec2 loc) {
    vec2 gridcorner=floor(loc);
    vec2 gridfrac=loc-gridcorner;
    if (gridfrac.x<0.5 ^^ gridfrac.y<0.5)
        return vec4(1,0,0,1); // red
    else
        return vec4(0,0,0,1); // black
}
void main(void) {
    gl_FragColor=grid(texcoords*10.0);
}
