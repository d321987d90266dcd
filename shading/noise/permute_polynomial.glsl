// Noise is Beautiful (notes), "Permutation Polynomials": the polynomial (34h + b)h mod 289 with
// its parameter b, and the 3D gradient the notes build from it in "Scatterings" ("Example: Sample
// Code"),
// unchanged. The 2D gradients differ per listing (B2 = 23 for Perlin noise, 6 for simplex noise)
// and stay with their noise.
// Generate gradient vecors using a permutation polynomial
// We can vary B to get different permutation outputs.
float permute(float x, float b) {
    float h = mod(x, 289.0f);
    return mod((34.0 * h + b) * h, 289.0);
}
vec3 gradient(vec3 p) {
    float B1 = 11.f;
    float B2 = 134.f;
    float B3 = 53.f;
    float x = permute(permute(permute(p.x, B1) + p.y, B1) + p.z, B1) / 288.f;
    float y = permute(permute(permute(p.x, B2) + p.y, B2) + p.z, B2) / 288.f;
    float z = permute(permute(permute(p.x, B3) + p.y, B3) + p.z, B3) / 288.f;
    // Our permutation function gives us a value in [0,1].
    // Convert this to a gradient vector that can go in any direction.
    return normalize(vec3(x,y,z) - vec3(0.5, 0.5, 0.5));
}
