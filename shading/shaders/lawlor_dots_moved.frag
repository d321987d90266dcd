// Lawlor, Procedural Solid Texturing: "You can even move the dots", by a shift read from tex1.
// Changed: `.xy` added to the shift (a vec4 assigned to a vec2 is an error in every GLSL); tex1 is
// declared.
uniform sampler2D tex1;
varying vec2 texcoords;
vec4 grid(vec2 loc) {
    vec2 gridcorner=floor(loc);
    vec2 gridshift=0.4*texture2D(tex1,gridcorner*0.1234).xy;
    vec2 gridcenter=gridcorner+vec2(0.3)+gridshift;
    float radius=length(loc-gridcenter);
    if (radius<0.3)
        return texture2D(tex1,gridcenter*0.1); // read texture 3
    else
        return vec4(0,0,0,1); // black
}
void main(void) {
    gl_FragColor=grid(texcoords*10.0);
}
