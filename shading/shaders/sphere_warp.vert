// Figure 1.1 sphere 4: the cellular domain is warped by 3D noise, computed per vertex.
uniform float time;
varying vec3 P;
void main(void) {
    vec3 o = gl_Vertex.xyz;
    P = o * 4.0 + 0.2 * vec3(snoise(o + vec3(0.0, 0.0, time)),
                             snoise(o + vec3(43.0, 17.0, time)),
                             snoise(o + vec3(0.0, -43.0, time - 17.0)));
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
