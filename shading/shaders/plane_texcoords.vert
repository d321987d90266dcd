// Lawlor's plane (NetRun): the texture coordinates straight through, under NetRun's name.
varying vec2 texcoords;
void main(void) {
    texcoords = gl_MultiTexCoord0.st;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
