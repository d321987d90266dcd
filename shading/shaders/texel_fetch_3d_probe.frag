// probe: textureSize and texelFetch of the sampler3D `volume` (GLSL 1.30), as
// texel_fetch_probe.frag: textureSize at a level from -1 to 4 per 4-pixel column group,
// texelFetch at a level per pixel from -1 to 2 and texel coordinates from 2 before that size to
// 2 past it on each axis; even columns the texel, odd columns the size.
uniform sampler3D volume;
void main(void) {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    int level = (pixel.x / 4) % 6 - 1;
    ivec3 size = textureSize(volume, level);
    ivec3 texel = (ivec3(pixel, pixel.x + pixel.y) * ivec3(3, 5, 7)) % (size + 5) - 2;
    vec4 c = texelFetch(volume, texel, (pixel.x + pixel.y) % 4 - 1);
    if (pixel.x % 2 == 0) {
        gl_FragColor = vec4(c.rgb, 0.75 + 0.25 * c.a);
    } else {
        gl_FragColor = vec4(vec3(size) / 1024.0, 1.0);
    }
}
