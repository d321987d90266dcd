#include "study/study_views.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/gltf.h"
#include "study/study_csv.h"

namespace qs::study {

const std::vector<View>& generated_views() {
    auto view = [](std::string name, std::string description, float zoom, float texcoord_scale, bool grazing) {
        View v;
        v.name = std::move(name), v.description = std::move(description);
        v.zoom = zoom, v.texcoord_scale = texcoord_scale, v.grazing = grazing;
        return v;
    };
    static const std::vector<View> views = {
        view("camera", "the scene's camera", 1.0f, 1.0f, false),
        view("magnified", "the camera's extent 0.3 times as wide: pattern edges span many pixels", 0.3f, 1.0f, false),
        view("minified", "TEXCOORD_0 scaled by 4: a texture-coordinate pattern repeats 4 times as often", 1.0f, 4.0f,
             false),
        view("grazing",
             "perspective over the scene stretched 4 times along its widest axes, TEXCOORD_0 scaled by 8, eye just "
             "beyond its edge: minification grows to the horizon",
             1.0f, 8.0f, true),
    };
    return views;
}

View view_named(const std::string& name) {
    const std::filesystem::path file = name;
    std::string ext = file.extension().string();
    for (char& c : ext) c = char(std::tolower((unsigned char)c));
    if (ext == ".gltf" || ext == ".glb") {
        View v;
        v.name = file.stem().string(), v.description = "the camera of " + file.filename().string();
        v.camera_file = file;
        return v;
    }
    std::string names;
    for (const View& v : generated_views()) {
        if (v.name == name) return v;
        names += (names.empty() ? "" : ", ") + v.name;
    }
    throw std::invalid_argument("no view '" + name + "' (the views are " + names +
                                ", or a .gltf or .glb file's camera)");
}

std::vector<View> at_frames(const std::vector<View>& views, const std::vector<int>& frames, double fps) {
    if (frames.empty()) return views;
    const bool camera_alone = views.size() == 1 && views[0].name == "camera" && !views[0].changes_scene();
    std::vector<View> out;
    for (const View& v : views) {
        for (const int f : frames) {
            View at = v;
            at.name = (camera_alone ? "" : v.name + "-") + "frame-" + std::to_string(f);
            const std::string time = number(double(f) / fps);
            at.description = v.description + " at frame " + std::to_string(f) + " (time " + time + " s)";
            at.time = double(f) / fps;
            out.push_back(std::move(at));
        }
    }
    return out;
}

void size_for(Scene& scene, int size) {
    const double aspect = double(scene.width) / double(scene.height);
    if (aspect >= 1.0) {
        scene.width = size, scene.height = std::max(1, int(std::lround(size / aspect)));
    } else {
        scene.height = size, scene.width = std::max(1, int(std::lround(size * aspect)));
    }
}

namespace {

struct Box {
    glm::vec3 lo{std::numeric_limits<float>::max()}, hi{std::numeric_limits<float>::lowest()};
};

Box world_box(const Scene& scene) {
    Box b;
    for (const Object& o : scene.objects) {
        for (const Vertex& v : scene.meshes.at(o.mesh).vertices) {
            const glm::vec3 p = glm::vec3(o.world_from_object * glm::dvec4(glm::dvec3(v.position), 1.0));
            b.lo = glm::min(b.lo, p), b.hi = glm::max(b.hi, p);
        }
    }
    return b;
}

void zoom_camera(Camera& c, float zoom) {
    if (c.kind == Camera::Kind::Orthographic) {
        c.xmag *= zoom, c.ymag *= zoom;
    } else {
        c.yfov = 2.0f * std::atan(std::tan(c.yfov / 2.0f) * zoom);
    }
}

// Stretches the scene along its two widest axes and puts a perspective camera low over it.
void graze(Scene& scene) {
    const Box b = world_box(scene);
    if (scene.objects.empty() || !(b.hi.x >= b.lo.x))
        throw std::invalid_argument("grazing view: the scene draws nothing");
    const glm::vec3 centre = (b.lo + b.hi) * 0.5f, half = (b.hi - b.lo) * 0.5f;
    // The thinnest axis is up (ties: the later axis, z before y before x); the eye looks along the
    // wider of the other two (ties: the later).
    int up = 2;
    for (int i = 1; i >= 0; --i) {
        if (half[i] < half[up]) up = i;
    }
    int along = -1;
    for (int i = 0; i < 3; ++i) {
        if (i != up && (along < 0 || half[i] >= half[along])) along = i;
    }
    const float reach = half[along];
    if (!(reach > 0.0f)) throw std::invalid_argument("grazing view: the scene has no extent");
    glm::vec3 stretch(4.0f);
    stretch[up] = 1.0f;
    const glm::mat4 about_centre = glm::translate(glm::mat4(1.0f), centre) * glm::scale(glm::mat4(1.0f), stretch) *
                                   glm::translate(glm::mat4(1.0f), -centre);
    for (Object& o : scene.objects) o.world_from_object = glm::dmat4(about_centre) * o.world_from_object;
    glm::vec3 eye = centre, axis_up(0.0f);
    eye[along] -= 4.2f * reach;
    eye[up] += half[up] + 0.5f * reach;
    axis_up[up] = 1.0f;
    Camera& c = scene.camera;
    c.kind = Camera::Kind::Perspective;
    c.yfov = glm::radians(40.0f);
    c.znear = 0.05f * reach, c.zfar = 50.0f * reach;
    c.view = glm::lookAt(eye, centre, axis_up);
}

}  // namespace

void apply_view(const View& view, Scene& scene) {
    if (!view.camera_file.empty()) scene.camera = load_scene(view.camera_file).camera;
    if (view.texcoord_scale != 1.0f) {
        for (Mesh& m : scene.meshes) {
            for (Vertex& v : m.vertices) v.texcoord *= view.texcoord_scale;
        }
    }
    if (view.zoom != 1.0f) zoom_camera(scene.camera, view.zoom);
    if (view.grazing) graze(scene);
}

}  // namespace qs::study
