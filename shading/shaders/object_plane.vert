// Figure 1.1 ground plane: flow-noise coordinates from the object-space position.
varying vec2 p;
void main(void) {
    p = gl_Vertex.xy * 8.0;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
