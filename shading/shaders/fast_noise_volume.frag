// The ProcTexGen articles ("Too Many Instructions", "Noise + Real Numbers"): the volume noiseFast
// reads, "a 32x32x32 volume texture to simulate an 8x8x8 looping sample of perlin noise", with "a
// different 8x8x8 noise into the G channel" (the articles name no base; 8 is a different cube of
// the permutation). Stored as 0.5 + 0.5 n, which the reader's `*2-1` undoes. `quadshade bake-volume
// --shader fast_noise_volume --size 32` bakes it.
varying vec3 P;
void main(void) {
    gl_FragColor = vec4(0.5 + 0.5 * texShaderNoise(P, 8, 0), 0.5 + 0.5 * texShaderNoise(P, 8, 8), 0.0, 1.0);
}
