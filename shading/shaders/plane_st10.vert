// Listing 1.3/1.4 demos: ten pattern cells across the plane.
varying vec2 st;
void main(void) {
    st = gl_MultiTexCoord0.st * 10.0;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
