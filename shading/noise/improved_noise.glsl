// Ken Perlin's improved noise (2002) over the ProcTexGen articles' tables ("Improved Perlin noise
// from GPU Gems 2"), and the articles' looping variant texShaderNoise. After
// perlin_permutation.glsl.

// The 16 gradients ("Crazy 8s"): the 12 cube edge midpoints and 4 of them again, the
// vectors the reference implementation's `grad(hash & 15, ...)` bit tests select.
const vec3 g[16] = vec3[16](
    vec3( 1, 1, 0), vec3(-1, 1, 0), vec3( 1,-1, 0), vec3(-1,-1, 0),
    vec3( 1, 0, 1), vec3(-1, 0, 1), vec3( 1, 0,-1), vec3(-1, 0,-1),
    vec3( 0, 1, 1), vec3( 0,-1, 1), vec3( 0, 1,-1), vec3( 0,-1,-1),
    vec3( 1, 1, 0), vec3( 0,-1, 1), vec3(-1, 1, 0), vec3( 0,-1,-1));

// The articles print these three bodies without their headers (their text was cut): restored as the
// blog's published sample has them.
vec3 texfade(vec3 t)
{
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); // new curve
//  return t * t * (3 - 2 * t); // old curve
}

float texgrad(int hash, vec3 p)
{
    return dot(g[hash & 15], p); // the articles: g[hash%16] (% of a negative int is undefined in GLSL)
}

float texgradperm(int x, vec3 p)
{
    return texgrad(perm(x), p);
}

// The reference algorithm the articles quote ("Crazy 8s": A = p[X]+Y; AA = p[A]+Z; AB = p[A+1]+Z;
// B = p[X+1]+Y; ...), on the same tables; HLSL's lerp is GLSL's mix.
float inoise(vec3 p)
{
    ivec3 P = ivec3(floor(p)) & 255;
    p -= floor(p);
    vec3 f = texfade(p);
    int A = perm(P.x) + P.y, AA = perm(A) + P.z, AB = perm(A + 1) + P.z;
    int B = perm(P.x + 1) + P.y, BA = perm(B) + P.z, BB = perm(B + 1) + P.z;
    return mix(mix(mix(texgradperm(AA,     p + vec3( 0,  0,  0)),
                       texgradperm(BA,     p + vec3(-1,  0,  0)), f.x),
                   mix(texgradperm(AB,     p + vec3( 0, -1,  0)),
                       texgradperm(BB,     p + vec3(-1, -1,  0)), f.x), f.y),
               mix(mix(texgradperm(AA + 1, p + vec3( 0,  0, -1)),
                       texgradperm(BA + 1, p + vec3(-1,  0, -1)), f.x),
                   mix(texgradperm(AB + 1, p + vec3( 0, -1, -1)),
                       texgradperm(BB + 1, p + vec3(-1, -1, -1)), f.x), f.y), f.z);
}

// "Crazy 8s": noise that loops every `repeat` cells, offset into the table by `base`.
// Ported from HLSL: float3/int3 -> vec3/ivec3; fmod (truncating: negative for p < 0, which would
// index outside the table) -> mod (floored); `(I+1) % repeat.xxx` (a scalar's swizzle: GLSL 4.20)
// -> `(I + 1) % repeat`; the default argument `base = 0` passed by the callers; lerp -> mix; the
// line `float3 f = texfade(p);`, lost from the articles' text (the next line reads an undeclared f),
// restored.
float texShaderNoise(vec3 p, int repeat, int base)
{
    ivec3 I = ivec3(mod(floor(p), float(repeat)));
    ivec3 J = (I + 1) % repeat;
    I += base;
    J += base;

    p -= floor(p);

    vec3 f = texfade(p);

    int A  = perm(I.x);
    int AA = perm(A+I.y);
    int AB = perm(A+J.y);

    int B  = perm(J.x);
    int BA = perm(B+I.y);
    int BB = perm(B+J.y);

    return mix( mix( mix( texgradperm(AA+I.z, p + vec3( 0,  0,  0) ),
                          texgradperm(BA+I.z, p + vec3(-1,  0,  0) ), f.x),
                     mix( texgradperm(AB+I.z, p + vec3( 0, -1,  0) ),
                          texgradperm(BB+I.z, p + vec3(-1, -1,  0) ), f.x), f.y),
                mix( mix( texgradperm(AA+J.z, p + vec3( 0,  0, -1) ),
                          texgradperm(BA+J.z, p + vec3(-1,  0, -1) ), f.x),
                     mix( texgradperm(AB+J.z, p + vec3( 0, -1, -1) ),
                          texgradperm(BB+J.z, p + vec3(-1, -1, -1) ), f.x), f.y), f.z);
}
