#pragma once
// The views a study renders a shader from: the scene's own camera, and views generated from it
// that stress a shader's derivatives and filtering in three ways.
//   camera     the scene's camera as it is
//   magnified  the camera's extent 0.3 times as wide about the image's centre: pattern edges span
//              many pixels
//   minified   TEXCOORD_0 scaled by 4: a shader driven by texture coordinates repeats 4 times as
//              often (one driven by positions sees the camera's view)
//   grazing    the scene stretched 4 times along its two widest axes, TEXCOORD_0 scaled by 8,
//              seen in perspective (40 degrees) from just beyond its edge, half its half-width
//              above its top: minification grows towards the horizon
// On the Table 1.1 plane (z = 0, x and y in [-1, 1]) the grazing eye is (0, -4.2, 0.5).
// A user's camera is a view too: a .gltf or .glb file whose camera replaces the scene's. And the
// frames of an animated scene are views: each view at time frame / fps, where the scene's
// animations put its objects and camera and the shaders read `time`.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace qs::study {

struct View {
    std::string name, description;
    float zoom = 1.0f;            // the camera's extent times this
    float texcoord_scale = 1.0f;  // TEXCOORD_0 times this
    bool grazing = false;
    std::filesystem::path camera_file;  // a user's camera: this scene file's
    std::optional<double> time;         // a frame's: the scene's time and the `time` uniform
    bool changes_scene() const { return zoom != 1.0f || texcoord_scale != 1.0f || grazing || !camera_file.empty(); }
};

// camera, magnified, minified, grazing.
const std::vector<View>& generated_views();
// The generated view `name`, or the camera of the scene file `name` (ending in .gltf or .glb,
// named by its stem); throws std::invalid_argument listing the names for another.
View view_named(const std::string& name);

// Each of `views` at each of `frames` (time = frame / fps), named VIEW-frame-N, or frame-N when
// `views` is the scene's camera alone; `views` as they are when `frames` is empty.
std::vector<View> at_frames(const std::vector<View>& views, const std::vector<int>& frames, double fps);

// `scene` drawn at `size` pixels along its longer side, its aspect kept.
void size_for(Scene& scene, int size);

// `scene` seen from `view`. Throws std::invalid_argument for a grazing view of a scene with no
// object, or one whose objects have no extent.
void apply_view(const View& view, Scene& scene);

}  // namespace qs::study
