// Listing 1.5: CMYK halftone screens over an image, blended to plain RGB when minified.
uniform sampler2D teximage;
uniform vec2 dims; // Texture dimensions (width and height)
varying vec2 one; // 1.0/dims from vertex shader
varying vec2 st; // 2D texture coordinates

// Explicit bilinear lookups to circumvent imprecise interpolation.
// In GLSL 1.30 and above, 'dims' can be fetched by textureSize().
vec4 texture2D_bilinear(sampler2D tex, vec2 st, vec2 dims, vec2 one) {
    vec2 uv = st * dims;
    vec2 uv00 = floor(uv - vec2(0.5)); // Lower left of lower left texel
    vec2 uvlerp = uv - uv00 - vec2(0.5); // Texel-local blends [0,1]
    vec2 st00 = (uv00 + vec2(0.5)) * one;
    vec4 texel00 = texture2D(tex, st00);
    vec4 texel10 = texture2D(tex, st00 + vec2(one.x, 0.0));
    vec4 texel01 = texture2D(tex, st00 + vec2(0.0, one.y));
    vec4 texel11 = texture2D(tex, st00 + one);
    vec4 texel0 = mix(texel00, texel01, uvlerp.y);
    vec4 texel1 = mix(texel10, texel11, uvlerp.y);
    return mix(texel0, texel1, uvlerp.x);
}

void main(void) {
    vec3 rgb = texture2D_bilinear(teximage, st, dims, one).rgb;
    float n = 0.1*snoise(st*200.0);
    n += 0.05*snoise(st*400.0);
    n += 0.025*snoise(st*800.0); // Fractal noise, 3 octaves
    vec4 cmyk;
    cmyk.xyz = 1.0 - rgb; // Rough CMY conversion
    cmyk.w = min(cmyk.x, min(cmyk.y, cmyk.z)); // Create K
    cmyk.xyz -= cmyk.w; // Subtract K amount from CMY

    // CMYK halftone screens, in angles 15/-15/0/45 degrees
    vec2 Cuv = 50.0*mat2(0.966, -0.259, 0.259, 0.966)*st;
    Cuv = fract(Cuv) - 0.5;
    float c = aastep(0.0, sqrt(cmyk.x) - 2.0*length(Cuv) + n);
    vec2 Muv = 50.0*mat2(0.966, 0.259, -0.259, 0.966)*st;
    Muv = fract(Muv) - 0.5;
    float m = aastep(0.0, sqrt(cmyk.y) - 2.0*length(Muv) + n);
    vec2 Yuv = 50.0*st; // 0 deg
    Yuv = fract(Yuv) - 0.5;
    float y = aastep(0.0, sqrt(cmyk.z)-2.0*length(Yuv)+n);
    vec2 Kuv = 50.0*mat2(0.707, -0.707, 0.707, 0.707)*st;
    Kuv = fract(Kuv) - 0.5;
    float k = aastep(0.0, sqrt(cmyk.w) - 2.0*length(Kuv) + n);

    vec3 rgbscreen = 1.0 - vec3(c, m, y);
    rgbscreen = mix(rgbscreen, vec3(0.0), 0.7*k + 0.5*n);
    vec2 fw = fwidth(st);
    float blend = smoothstep(0.7, 1.4, 200.0*max(fw.s, fw.t));
    gl_FragColor = vec4(mix(rgbscreen, rgb, blend), 1.0);
}
