#pragma once
// The geometry conformance scenes: what a renderer gets wrong when it is only ever shown one
// plane facing the camera. Self-occluding and overlapping meshes in several draw orders, a node
// hierarchy with matrices and non-uniform TRS, rolled cameras, a large plane crossing the near
// plane at a grazing angle, a fan of slivers, odd and even image sizes. Every catalogue shader
// is compared on them against OSMesa (tests/reference/test_conformance.cpp).

#include <filesystem>

#include "scenes/scene.h"

namespace qs {

// A torus around the y axis: major radius R in the xz plane, minor radius r; st = (s_repeats u,
// t_repeats v) over the seams (duplicated vertices), u around the major circle, v the minor.
Mesh torus_mesh(float R, float r, int steps_u, int steps_v, float s_repeats, float t_repeats);

// Writes DIR/conformance/<name>.gltf and .bin for each scene.
void write_geometry_scenes(const std::filesystem::path& dir);

}  // namespace qs
