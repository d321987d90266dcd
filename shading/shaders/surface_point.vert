// Shaders with a height (shading/height_field.h): the object position itself, unscaled, so that a
// height is a function of gl_Vertex.xyz and a bake can evaluate it at any surface point.
varying vec3 P;
void main(void) {
    P = gl_Vertex.xyz;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
