#pragma once
// Normal maps from a shader's height (shading/height_field.h), baked into the mesh's UV atlas as
// the ProcTexGen blog does: "Generating three heights in close proximity (using (pos), (pos+tangent*scaler),
// (pos+bitangent*scaler)) gives me two edges which I can take the cross-product of to get a
// pixel normal map ... in object space".
//
// Per atlas texel whose centre lies in a triangle's texcoords: the surface point p there (object
// space, interpolated in double), the triangle's face normal N (its winding's: counter-clockwise
// is outward, as glTF's front faces), and an orthonormal tangent frame from the UV mapping:
// T = dp/ds made orthogonal to N and normalised, B = N x T, turned to point along dp/dt (a
// mirrored chart gives a left-handed frame). The surface with relief is q(p) = p + A h(p) N (A: the
// height's amplitude), and its normal is made two ways:
//  - finite differences (the blog's): q0 = p + A h(p) N, q1 = p + e T + A h(p + e T) N,
//    q2 = p + e B + A h(p + e B) N and n = normalize((q1 - q0) x (q2 - q0)), turned to N's side.
//    Expanded with T x B = N: (q1 - q0) x (q2 - q0) = e^2 (N - A (h1 - h0)/e T - A (h2 - h0)/e B),
//    a forward difference of h along T and B, with an error O(e) and rounding O(eps/e);
//  - analytically: h_t = grad h . T and h_b = grad h . B from Dual2 (HeightField::gradients,
//    the chain rule through the whole height) and n = normalize(N - A (h_t T + h_b B)), the
//    finite differences' limit for e -> 0: N - A grad_tangential h. Over a flat triangle (N
//    constant) it is exactly the displaced surface's normal: dq/dT x dq/dB =
//    (T + A h_t N) x (B + A h_b N) = N - A h_t T - A h_b B.
// The step e is in object units (T and B are unit vectors).
//
// Encoding: object-space normals, each component as 0.5 + 0.5 n (RGB), alpha 1 on texels the
// charts cover and 0 in the gutter, an image in the colour atlas's layout (row 0 is t = 0).
// glTF's normalTexture is tangent-space, so the baked scene binds this map under the name
// `normalmap` in the material's extras.textures (shading: baked_lit), never as normalTexture.
// Skirts: gutter texels within `skirt` texels of a chart take the mean normal of their covered
// neighbours, one ring per pass (a dilation: a normal map has no surface point outside its
// charts to evaluate, and the colour's skirts repeat the boundary's points anyway).

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "images/image_io.h"
#include "scenes/scene.h"
#include "shading/height_field.h"

namespace qs {

enum class NormalMethod { FiniteDifferences, Analytic };

struct NormalBakeRequest {
    int size = 1024;   // atlas texels per side
    int skirt = 0;     // dilation rings into the gutter
    NormalMethod method = NormalMethod::Analytic;
    double step = 1e-4;  // finite differences' e, object units (the float optimum: docs/results.md)
    Precision precision = Precision::Float;
    int threads = 0;  // 0: all cores
};

// The surface behind each covered texel of a size x size atlas: its index (row-major, row 0 is
// t = 0), object position, face normal and tangent frame. Texels whose centre lies on an edge
// shared by two triangles belong to the first in scene order. Throws as check_atlas.
struct AtlasTexels {
    int size = 0;
    std::vector<std::uint32_t> texel;
    std::vector<glm::dvec3> position, normal, tangent, bitangent;
};
AtlasTexels atlas_texels(const Scene& scene, int size);

// The unit normal at each of `texels`, by `request`'s method, step and precision.
std::vector<glm::dvec3> surface_normals(const HeightField& field, const AtlasTexels& texels, const NormalBakeRequest& request);

// At most how many texel centres of a size x size atlas the scene's triangles cover (area +
// perimeter / 2 + 1 per triangle, in texels; no more than the atlas has).
std::uint64_t covered_texels_bound(const Scene& scene, int size);

// Bytes bake_normal_map holds at its peak: per texel the charts may cover (covered_texels_bound:
// its surface point, frame and normal) and per texel of the map (the image, a skirt pass's copy).
std::uint64_t normal_bake_bytes(const Scene& scene, const NormalBakeRequest& request);

// The object-space normal map, encoded as above. Throws std::invalid_argument for a size outside
// [1, kMaxAtlasSide], a skirt outside [0, kMaxSkirt] or, for finite differences, a step that is
// not finite and positive.
Image bake_normal_map(const Scene& scene, const HeightField& field, const NormalBakeRequest& request);

}  // namespace qs
