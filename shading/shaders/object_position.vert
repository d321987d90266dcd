// Solid textures: the object-space position, 4 lattice cells per unit (as improved noise).
varying vec3 P;
void main(void) {
    P = gl_Vertex.xyz * 4.0;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
