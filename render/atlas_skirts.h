#pragma once
// Skirts against seams (the ProcTexGen articles, "Short Skirt, Long Jacket"): a baked texture is sampled with
// bilinear filtering and mipmaps, which blend texels across a chart's edge with the gutter beyond
// it; drawn at a chart's border the mesh then shows a dark seam. A skirt is a strip of triangles
// along each chart boundary, pushed out into the gutter in texcoord space while keeping the
// boundary's object positions, so the shader fills the gutter near a chart with the colours at
// its edge.
//
// Chart boundaries are found the blog's way: vertices with equal texcoords are one vertex (not
// vertices with equal indices: a mesh duplicates vertices wherever any attribute differs), and a
// boundary edge is an edge that one triangle uses. Each boundary vertex gets a "UV normal" from
// the outward normals of its boundary edges, and the skirt's outer vertices are the boundary's
// moved along it by the skirt's width.

#include "scenes/scene.h"

namespace qs {

// The skirt strips of `mesh`'s charts, `width` texcoord units wide (the skirt's texels divided by
// the atlas's size): two triangles per boundary edge, their inner edge the boundary, their outer
// edge moved out along the UV normals, every vertex at its boundary vertex's position. Empty for a
// mesh whose charts have no boundary (a closed chart).
Mesh skirt_mesh(const Mesh& mesh, float width);

}  // namespace qs
