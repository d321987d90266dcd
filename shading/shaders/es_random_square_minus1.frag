// OpenGL ES Pixel Shaders Tutorial, "Procedural Textures: Square Grid": es_random_square with the
// noise's input moved by -1 ("float n = randomNoise(position-1.);").
void main(void) {
    vec2 position = gl_FragCoord.xy/uResolution.xx;
    if ((position.x>1.) || (position.y>1.)) {
        discard;
    }
    float n = randomNoise(position-1.);
    gl_FragColor = vec4(vec3(n), 1.);
}
