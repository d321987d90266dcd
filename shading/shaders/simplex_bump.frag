// Gustavson, Procedural Textures in GLSL, section 1.1: "A procedural pattern allows for analytic
// derivatives, which makes it less complicated to generate corresponding bump or normal maps." A
// bump map of 3D simplex noise (noise/simplex3d.glsl, demo constants) from its analytic gradient
// (noise/simplex3d_grad.glsl), lit by one directional light. The height is 0.04 snoise(P) object
// units with P = 4 x (the object position): its gradient in object space is 0.16 G. The bump moves
// the normal against the gradient's part along the surface. quadshade's vertex stages have no
// gl_Normal: the normal is that of a unit sphere centred on the origin, normalize(P) (right on the
// sphere scene, a stand-in on other meshes). Lighting in object space.
varying vec3 P;
void main(void) {
    vec3 N = normalize(P);
    vec3 G;
    snoise_grad(P, G);
    vec3 dh = 0.16 * G;
    vec3 bumped = normalize(N - (dh - dot(dh, N) * N));
    vec3 L = normalize(vec3(0.3, -0.8, 0.6));
    float diffuse = max(dot(bumped, L), 0.0);
    gl_FragColor = vec4(vec3(0.9, 0.8, 0.6) * (0.15 + 0.85 * diffuse), 1.0);
}
