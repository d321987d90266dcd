// Noise is Beautiful (notes), "Integer Hash": the PCG hash and cellnoise_pcg2 (GLSL 1.30: uint).
// Changed: two typos, `flag cellnoise_pcg2` is `float`, and the parameter `input` (a reserved
// word) is `v`. Shown as 32 cells across the plane: the notes say how to hash, not what they drew.
varying vec2 st;
uint pcg_hash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}
// Chain hash calls: hash(x, y) = hash(hash(x) + y)
float cellnoise_pcg2(vec2 p) {
    // Convert to integer input, and apply a bit mask to remove the sign bit
    uvec2 pu = uvec2(ivec2(floor(p)) & ivec2(0x7FFFFFFF));
    // Chain hash calls and then squish the noise output to [0,1]
    return float(pcg_hash(pu.x + pcg_hash(pu.y)) & 0xFFFFu) / 65536.0;
}
void main(void) {
    gl_FragColor = vec4(vec3(cellnoise_pcg2(st * 32.0)), 1.0);
}
