#pragma once
// The catalogue as contact sheets: one image per collection (shading/catalogue.h), every shader
// of it rendered on a scene that can feed it and labelled with its name. The README shows the
// source texts' sheets; `quadshade gallery` writes them.

#include <filesystem>
#include <string>
#include <vector>

#include "images/image_io.h"
#include "render/scene_render.h"
#include "shading/shader_info.h"

namespace qs {

struct GalleryRequest {
    // Scenes to draw on, in order of preference; a shader is drawn on the first that binds the
    // textures it samples, solid textures (Coordinates::Object3D) on the first that holds the
    // word "solids" in its file name if any binds them.
    std::vector<std::filesystem::path> scenes;
    int tile = 160;    // each shader's square, in pixels
    int columns = 6;   // squares per row, at most
    FrameRequest frame;  // time, derivative rule, threads; its size and shader are set per tile
    std::vector<std::string> collections;  // the catalogue's collections to draw (empty: all)
};

struct GallerySheet {
    std::string collection;
    Image image;
    // Per shader of the collection: its name and the scene it was drawn on ("" when no scene
    // binds its textures: its square is left grey, the label says so).
    std::vector<std::pair<std::string, std::filesystem::path>> drawn;
};

// The sheets, in collection order (catalogue_by_collection). Throws SceneError for an unreadable
// scene, ImageError when labels cannot be drawn (no font), std::invalid_argument for a tile size
// outside [16, 1024] or no scene.
std::vector<GallerySheet> render_gallery(const GalleryRequest& request);

// The file name of a collection's sheet: its name up to a colon, lower case, spaces as dashes
// ("Noise is Beautiful: ..." -> "noise-is-beautiful"; separators . _ / as dashes), other characters dropped.
std::string gallery_file_stem(const std::string& collection);

}  // namespace qs
