#pragma once
// Meshes with a real UV atlas, for `quadshade bake`: a cube whose six faces are six charts with
// gutters between them, and a UV sphere, one chart cut open along a seam (u = 0 and u = 1 meet
// there) with its poles fanned. Each chart's texcoords lie inside [0, 1] and no two triangles
// overlap there, as an atlas bake needs; the materials name solid (object-space) textures.

#include <filesystem>

namespace qs {

// Writes DIR/bake/atlas-cube.gltf and DIR/bake/atlas-sphere.gltf (+ .bin).
void write_atlas_scenes(const std::filesystem::path& dir);

}  // namespace qs
