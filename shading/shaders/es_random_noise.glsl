// Rendon Cepeda's OpenGL ES Pixel Shaders Tutorial calls randomNoise in "Procedural Textures:
// Square Grid" and defines it on the page before ("Procedural Textures: \"Random\" Noise"): this is
// the classic one-liner in its place, not necessarily the tutorial's own. Ported from GLSL ES: no
// precision statement.
uniform vec2 uResolution;
float randomNoise(vec2 p) {
    return fract(sin(dot(p, vec2(12.9898, 78.233))) * 43758.5453);
}
