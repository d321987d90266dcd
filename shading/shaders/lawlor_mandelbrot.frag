// Lawlor, Procedural Solid Texturing: "a very famous procedural texture: the Mandelbrot set",
// iterated at the plane's texture coordinates. `2*x*y` multiplies a float by an int, which GLSL
// 1.20 converts implicitly (hence #version 120). Changed: alpha is 1 where the notes write 0
// (NetRun shows colour only), so that the picture is opaque and the tests can read coverage from
// alpha as for every other shader.
varying vec2 texcoords;
void main(void) {
    float cx=texcoords.x, cy=texcoords.y; // location onscreen
    float x=cx, y=cy; // point to iterate
    float r=0.0; // radius of point (squared)

    for (int i=0;i<100;i++) //<- repeat!
    {
        float newx=x*x - y*y;
        y=2*x*y; // <- complex multiplication

        x=newx+cx; y=y+cy; // bias by onscreen location

        r=x*x+y*y; // check radius
        if (r>4.0) break;
    }
    gl_FragColor=vec4(x,r*0.1,y,1);
}
