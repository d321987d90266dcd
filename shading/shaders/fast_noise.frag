// The ProcTexGen articles, "Noise + Real Numbers + Imaginary Numbers == ???": noiseFast, two
// trilinear lookups of an 8x8x8-cell looping noise stored in a 32^3 volume, at p/8 and p/72; the
// low frequency rotates the high frequency's (real, imaginary) pair. Ported from HLSL: tex3D ->
// texture3D, half -> float, PI defined (the articles use it undeclared), noise3dSampler declared
// (the scene binds the volume: GL_REPEAT on s, t, r, GL_LINEAR, no mipmaps).
uniform sampler3D noise3dSampler;
varying vec3 P;
const float PI = 3.14159265358979;
float noiseFast(vec3 p)
{
    p /= 8.0; // the volume holds 8x8x8 noise cells: keep in parity with the true Perlin noise
    vec2 hi = texture3D(noise3dSampler, p).rg * 2.0 - 1.0; // high frequency noise
    float lo = texture3D(noise3dSampler, p / 9.0).r * 2.0 - 1.0; // low frequency noise
    float angle = lo * 2.0 * PI;
    return hi.r * cos(angle) + hi.g * sin(angle); // the low frequency rotates the high one
}
void main(void) {
    gl_FragColor = vec4(vec3(0.5 + 0.5 * noiseFast(P)), 1.0);
}
