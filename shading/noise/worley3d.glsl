// The ProcTexGen articles, "Cellular Noise": their 3D cellular (Worley) noise, voronoi(): the two
// nearest of the 27 jittered feature points around a position, their distances F1 and F2 and their
// positions, Euclidean or Manhattan. After perlin_permutation.glsl. Needs #version 130 (int &).

// The blog's voronoi() calls perm() and perm2d(), GPU Gems 2's lookups into point-sampled,
// wrapping permutation textures (a 256x1 texture of P[i]/255 and a 256x256 RGBA texture of
// (P[P[x]+y], P[P[x]+y+1], P[P[x+1]+y], P[P[x+1]+y+1])/255), which the articles do not give.
// Written here as the same lookups into the integer table: texel floor(u * 256) mod 256.
float perm(float x)
{
    return float(perm(int(floor(x * 256.0)))) / 255.0;
}
// The articles' `float3 cellnoise = perm(perm2d(uv) + w)` passes a float4: read per component
// (three independent values; HLSL's tex1D on an L8 texture would give (L, L, L) and put every
// feature point on its cell's diagonal, which the blog's pictures do not show).
vec4 perm(vec4 x)
{
    return vec4(perm(x.x), perm(x.y), perm(x.z), perm(x.w));
}
vec4 perm2d(vec2 p)
{
    int X = int(floor(p.x * 256.0));
    int Y = int(floor(p.y * 256.0));
    int A = perm(X) + Y;
    int B = perm(X + 1) + Y;
    return vec4(perm(A), perm(A + 1), perm(B), perm(B + 1)) / 255.0;
}

// HLSL, complete apart from perm/perm2d. Ported: float3 -> vec3; the default arguments (jitter
// = .9, manhattanDistance = false) passed by the callers; `.xyz` of the vec4 perm(); int literals
// of the float loops written as floats. pos1 and pos2 are read before they are written on the
// first point (as in the articles): undefined until the second point, which no caller sees.
void voronoi(vec3 position, out float f1, out vec3 pos1, out float f2, out vec3 pos2, float jitter, bool manhattanDistance)
{
    vec3 thiscell = floor(position)+.5;
    f1 = f2 = 1000.;
    float i, j, k;

    for(i = -1.; i <= 1.; i += 1.)
    {
        for(j = -1.; j <= 1.; j += 1.)
        {
            for(k = -1.; k <= 1.; k += 1.)
            {
                vec3 testcell = thiscell  + vec3(i,j,k);
                vec3 randomUVW = testcell * vec3(0.037, 0.119, .093);
                vec3 cellnoise = perm(perm2d(randomUVW.xy)+randomUVW.z).xyz;
                vec3 pos = testcell + jitter*(cellnoise-.5);
                vec3 offset = pos - position;
                float dist;
                if(manhattanDistance)
                    dist = abs(offset.x)+abs(offset.y) + abs(offset.z);
                else
                    dist = dot(offset, offset);
                if(dist < f1)
                {
                    f2 = f1;
                    pos2 = pos1;
                    f1 = dist;
                    pos1 = pos;
                }
                else if(dist < f2)
                {
                    f2 = dist;
                    pos2 = pos;
                }
            }
        }
    }
    if(!manhattanDistance)
    {
        f1 = sqrt(f1);
        f2 = sqrt(f2);
    }
}
