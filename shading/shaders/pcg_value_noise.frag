// Value noise from the PCG integer hash (GLSL 1.30): "Noise is Beautiful", Integer Hash
// (pcg_hash, cellnoise_pcg2), blended over each cell with smoothstep's cubic, four octaves.
// The integer-hash benchmark shader.
varying vec2 st;

uint pcg_hash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

float cellnoise_pcg2(vec2 p) {
    // Convert to integer input, and apply a bit mask to remove the sign bit
    uvec2 pu = uvec2(ivec2(floor(p)) & ivec2(0x7FFFFFFF));
    // Chain hash calls and then squish the noise output to [0,1]
    return float(pcg_hash(pu.x + pcg_hash(pu.y)) & 0xFFFFu) / 65536.0;
}

float value_noise(vec2 p) {
    vec2 i = floor(p);
    vec2 f = p - i;
    vec2 u = f * f * (3.0 - 2.0 * f);
    float a = cellnoise_pcg2(i), b = cellnoise_pcg2(i + vec2(1.0, 0.0));
    float c = cellnoise_pcg2(i + vec2(0.0, 1.0)), d = cellnoise_pcg2(i + vec2(1.0, 1.0));
    return mix(mix(a, b, u.x), mix(c, d, u.x), u.y);
}

void main(void) {
    vec2 p = st * 16.0;
    float n = 0.5 * value_noise(p) + 0.25 * value_noise(p * 2.0 + 17.0) + 0.125 * value_noise(p * 4.0 + 31.0) +
              0.0625 * value_noise(p * 8.0 + 47.0);
    gl_FragColor = vec4(vec3(n), 1.0);
}
