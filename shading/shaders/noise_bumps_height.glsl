// noise_bumps' height (shading/height_field.h): three octaves of 3D simplex noise (noise/
// simplex3d.glsl, which must come first, with a kernel radius^2 of 0.5 so that the height and
// its gradient are continuous: shaders/heights.h) on the object position, about [0.06, 0.94]. The surface it describes is P + 0.05 height(P) N: 0.05 object units of relief for
// heights 0 to 1 (the amplitude its C++ translation declares; render/normal_bake.h).
float height(vec3 P) {
    float n = snoise(3.0 * P) + 0.5 * snoise(6.0 * P) + 0.25 * snoise(12.0 * P);
    return 0.5 + 0.25 * n;
}
