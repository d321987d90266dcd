// Figure 1.1 sphere 3: cellular coordinates, moving down with time.
uniform float time;
varying vec3 P;
void main(void) {
    P = gl_Vertex.xyz * 4.0 - vec3(0.0, 0.0, time);
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
