// The Mandelbrot set, as in Lawlor's "Procedural Solid Texturing" (CS 481/681): up to 100
// iterations, the loop left as soon as the point escapes. The point is the window position, 3/1024
// unit per pixel from (-2, -1.5), so that the set fills a 1024x1024 window. (The notes iterate on
// the texture coordinates: an ulp of an interpolated coordinate changes escape times near the
// set's boundary, and every renderer interpolates its own way, while all know the window
// position exactly.) x * x - y * y + cx is written in the order Mesa's optimizer puts it in,
// which GLSL allows any compiler to do without `precise`: so quadshade and Mesa round alike.
void main(void) {
    float cx = gl_FragCoord.x * (3.0 / 1024.0) - 2.0, cy = gl_FragCoord.y * (3.0 / 1024.0) - 1.5;
    float x = cx, y = cy;  // point to iterate
    float r = 0.0;         // radius of point (squared)
    for (int i = 0; i < 100; i++) {
        float newx = x * x + cx - y * y;
        y = 2.0 * x * y + cy;  // complex multiplication, biased by the location
        x = newx;
        r = x * x + y * y;  // check radius
        if (r > 4.0) break;
    }
    gl_FragColor = vec4(x, r * 0.1, y, 1.0);
}
