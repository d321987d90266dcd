// Seed 003 (the OpenGL ES pixel shaders tutorial, page 4) calls randomNoise, which the tutorial
// defines on its page 3, not part of the seed: this is the classic one-liner issue #19 prescribes
// in its place, not necessarily the tutorial's own. Ported from GLSL ES: no precision statement.
uniform vec2 uResolution;
float randomNoise(vec2 p) {
    return fract(sin(dot(p, vec2(12.9898, 78.233))) * 43758.5453);
}
