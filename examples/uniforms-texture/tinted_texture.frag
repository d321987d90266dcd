#version 130
// The scene's texture (the material's baseColorTexture), tinted, in bands whose count is a
// uniform: set them with the material's extras.uniforms or --uniform NAME=VALUE.
uniform sampler2D teximage;
uniform vec3 uTint = vec3(1.0, 0.6, 0.2);
uniform float uBands = 6.0;
in vec2 uv;
void main(void) {
    vec3 texel = texture2D(teximage, uv).rgb;
    float band = step(0.5, fract(uBands * uv.y));
    gl_FragColor = vec4(mix(texel, texel * uTint, band), 1.0);
}
