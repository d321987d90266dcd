// Texture coordinates straight through.
varying vec2 st;
void main(void) {
    st = gl_MultiTexCoord0.st;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
