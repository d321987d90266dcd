// Probe of sin and cos (GLSL 3.30): each pixel writes its argument a, sin(a), cos(a) and the
// sine hash fract(sin(a) * 43758.5453), which multiplies sin's last bit by 2^15. Rows 0-95: a
// is any float (a hash of the pixel's index as its bits: huge, tiny, denormal, inf and NaN);
// rows 96-191: |a| from 2^-31 to 2^32, either sign; rows 192 and up: dot(p, vec2(12.9898,
// 78.233)) as the sine hashes evaluate it, p up to 128 with fractions.
void main(void) {
    vec2 p = floor(gl_FragCoord.xy);
    uint i = uint(p.x) + 256u * uint(p.y);
    uint h = i * 2654435761u;
    float a;
    if (p.y < 96.0) {
        a = uintBitsToFloat(h);
    } else if (p.y < 192.0) {
        a = uintBitsToFloat((h & 0x807FFFFFu) | ((96u + i % 64u) << 23));
    } else {
        vec2 q = vec2(p.x * 0.5, (p.y - 192.0) * 2.0) + fract(vec2(h & 1023u, h >> 22) / 1024.0);
        a = dot(q, vec2(12.9898, 78.233));
    }
    float s = sin(a);
    gl_FragColor = vec4(a, s, cos(a), fract(s * 43758.5453));
}
