// Listing 1.1: anisotropic anti-aliased step.
// 'threshold' is constant, 'value' is smoothly varying
// quadshade's error study also builds it with AASTEP_FWIDTH (0.7 fwidth instead of 0.7 times the
// gradient's length) or AASTEP_STEP (no anti-aliasing).
float aastep(float threshold, float value) {
#if defined(AASTEP_STEP)
    return step(threshold, value);
#else
#if defined(AASTEP_FWIDTH)
    float afwidth = 0.7 * fwidth(value);
#else
    float afwidth = 0.7 * length(vec2(dFdx(value), dFdy(value)));
#endif
    // GLSL's fwidth(value) is abs(dFdx(value)) + abs(dFdy(value))
    return smoothstep(threshold-afwidth, threshold+afwidth, value);
#endif
}
