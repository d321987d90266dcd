// Solid textures: the object-space position, 8 lattice cells per unit.
varying vec3 P;
void main(void) {
    P = gl_Vertex.xyz * 8.0;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
