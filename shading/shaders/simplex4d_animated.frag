// Gustavson, Procedural Textures in GLSL, section 1.6 (Animation): "3D spatial coordinates and time
// together provide the texture coordinates for an animated solid texture". 4D simplex noise
// (noise/simplex4d.glsl) of (object position, time), as grey.
varying vec4 P;
void main(void) {
    float n = snoise4(P);
    gl_FragColor = vec4(vec3(0.5 + 0.5 * n), 1.0);
}
