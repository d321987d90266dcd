// Solid texture animated through the fourth dimension: the object position (3 cells per unit)
// and time, 0.3 cells per second, as the noise's w.
uniform float time;
varying vec4 P;
void main(void) {
    P = vec4(gl_Vertex.xyz * 3.0, 0.3 * time);
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
