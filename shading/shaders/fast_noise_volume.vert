// The ProcTexGen articles' fast noise volume: object space [-1, 1]^3 (what `quadshade bake-volume`
// renders) to [0, 8]^3, one period of the looping noise; texel i of 32 is at P = 8 (i + 0.5) / 32.
varying vec3 P;
void main(void) {
    P = (gl_Vertex.xyz * 0.5 + 0.5) * 8.0;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
