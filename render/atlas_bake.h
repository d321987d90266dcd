#pragma once
// A shader baked into a mesh's texture atlas, as the ProcTexGen blog does it: every triangle
// drawn at its TEXCOORD_0 (render/atlas_program.h) while the shader's own vertex stage gives its
// varyings, so each texel gets the colour the live render computes at the surface point that
// texel maps to. It is a frame like any other (quads, helper lanes, the same rasterizer), so
// the same draw through OSMesa checks it (tests/reference).
//
// Derivatives in an atlas: dFdx/dFdy are the change per atlas texel along s and t, the texel's
// footprint on the surface (its object-space size is what fwidth anti-aliases over), not a
// screen pixel's. With the quad rules, quads straddling a chart's edge take their differences
// from helper lanes extrapolated past the chart; Derivatives::Analytic (Dual2) gives the exact
// per-texel partials of the interpolated varyings everywhere, chart edges included.

#include <cstdint>
#include <filesystem>
#include <string>

#include "images/image_io.h"
#include "render/scene_render.h"
#include "scenes/scene.h"

namespace qs {

// Atlas sides (texels): what a texture may have (scenes/limits.h) so the result loads back.
inline constexpr int kMaxAtlasSide = 1 << 14;
inline constexpr int kMaxSkirt = 64;

struct AtlasRequest {
    int size = 1024;     // the atlas is size x size texels
    int skirt = 0;       // texels of skirt around each chart (render/atlas_skirts.h), 0 for none
    FrameRequest frame;  // shader, time, uniforms, derivative rule, threads; its size and atlas flag are set here
};

// Throws SceneError, naming the scene's file and the mesh and object, unless every drawn mesh has
// TEXCOORD_0 within [0, 1], every triangle with an area in POSITION has one in TEXCOORD_0, and no
// two triangles (of one mesh or of different objects) overlap there with positive area: each
// texel must belong to one surface point, and each surface point to a texel. Takes O(n log n)
// for n triangles, each tested only against its neighbours in a sweep; returns how many pairs it
// tested (at most 3n: for tests and benches).
std::size_t check_atlas(const Scene& scene);

// Bytes render_atlas_frame holds at its peak beside the scene: the frame (colour and depth of
// size x size texels), the atlas's copy of the scene with its skirts, the draw calls' vertices, the
// vertex and triangle working memory, check_atlas's sweep.
std::uint64_t atlas_bake_bytes(const Scene& scene, const AtlasRequest& request);

// The scene an atlas is drawn from: `scene` with a transparent black clear colour (the gutter
// between charts) at size x size and, with `skirt` texels, each object's skirts drawn after all
// the charts by an object of the same material. The depth test (LESS, every triangle at depth
// 0) keeps the first fragment drawn at a texel, so a skirt fills only gutter texels: the same
// atlas as the blog's skirts drawn first and charts over them, without a depth order.
Scene atlas_scene(const Scene& scene, int size, int skirt = 0);

// The atlas as its frame: rows top-down as every frame, so its last row is the atlas's first
// (t = 0). Throws as check_atlas, std::invalid_argument for a size outside [1, kMaxAtlasSide],
// SceneError for an unknown shader or a missing texture.
Framebuffer render_atlas_frame(const Scene& scene, const AtlasRequest& request);

// The atlas as a texture image: row j holds t in [j / size, (j + 1) / size], the first row
// t = 0, which is glTF's top of the image (texcoord (0, 0) is the image's top-left).
Image bake_atlas(const Scene& scene, const AtlasRequest& request);

// `scene` drawn with its baked atlas, the image file `texture` (a PNG of bake_atlas's image): the
// same meshes, objects and camera, every object drawn by `single_texture` (one texture2D of its
// baseColorTexture, unlit as the solid textures are) with the atlas sampled trilinear (LINEAR,
// LINEAR_MIPMAP_LINEAR: the mip chain is built on load as glGenerateMipmap builds it) and clamped
// to its edge. Other textures, samplers and uniforms are dropped.
Scene baked_scene(const Scene& scene, const std::filesystem::path& texture);

// The same with the maps of a bake with a height (render/normal_bake.h): with `normal_map` (a
// PNG of bake_normal_map's object-space normals) every object is drawn by `baked_lit`, the
// colour atlas its baseColorTexture and the normal map bound as the sampler `normalmap` in the
// material's extras.textures (not glTF's normalTexture, which is tangent-space), sampled as the
// atlas is. A `height_map` is bound as extras.textures' `heightmap`, for other tools: no
// shader of the catalogue samples it. Empty paths: no such map.
Scene baked_scene(const Scene& scene, const std::filesystem::path& texture, const std::filesystem::path& normal_map,
                  const std::filesystem::path& height_map);

// A frame's rows in the opposite order: between a frame (top-down) and a texture (t = 0 first).
Image flip_rows(const Framebuffer& frame);

}  // namespace qs
