// OpenGL ES Pixel Shaders Tutorial, "Procedural Textures: Square Grid": the square viewport cut
// into 128x128 tiles ("the square grid for
// tiles = 128."), es_tiles2's lines with 128.
void main(void) {
    vec2 position = gl_FragCoord.xy/uResolution.xx;
    if ((position.x>1.) || (position.y>1.)) {
        discard;
    }
    float tiles = 128.;
    position = floor(position*tiles);
    float n = randomNoise(position);
    gl_FragColor = vec4(vec3(n), 1.);
}
