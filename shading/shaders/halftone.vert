// Listing 1.5's vertex stage: texture coordinates and the texel size.
uniform vec2 dims;
varying vec2 st;
varying vec2 one;
void main(void) {
    st = gl_MultiTexCoord0.st;
    one = 1.0 / dims;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
