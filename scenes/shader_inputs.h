#pragma once
// The GLSL names by which a scene feeds a vertex shader that declares its inputs itself (GLSL
// 1.30 and later: `in` attributes and matrix uniforms) instead of reading the compatibility
// profile's gl_Vertex, gl_MultiTexCoord0 and gl_ModelViewProjectionMatrix. Every renderer binds
// these names the same way (the OSMesa reference, quadshade's Uniforms and VertexIn, the GLSL front
// end), and refuses any other attribute, and any other matrix uniform nothing sets, by name:
// a shader never renders black because a transform it reads was left 0.
//
//   uniform mat4 mvp;                  the object's clip_from_object (also: modelViewProjection)
//   uniform mat4 model;                world_from_object, the glTF node's world transform
//   uniform mat4 view;                 view_from_world, the camera node's inverse
//   uniform mat4 projection;           clip_from_view, for the frame's aspect ratio
//   uniform mat3 normalMatrix;         transpose(inverse(mat3(view * model))): eye-space normals
//   in vec3 position;                  glTF POSITION
//   in vec3 normal;                    glTF NORMAL
//   in vec2 texcoord;                  glTF TEXCOORD_0 (also: texcoord0)
//   in vec2 texcoord1;                 glTF TEXCOORD_1
//   in vec4 color;                     glTF COLOR_0
//
// An attribute may be declared with fewer or more components than the data has; GL's rule
// applies to both renderers (missing y, z are 0 and w is 1). Nothing here depends on a renderer.

#include <cstddef>
#include <string_view>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

namespace qs {

struct Scene;
struct Pose;

enum class SceneMatrix { ModelViewProjection, Model, View, Projection, Normal };

struct SceneMatrixName {
    std::string_view name;
    SceneMatrix matrix;
    int columns;  // 4: a mat4 uniform; 3: a mat3
};
inline constexpr SceneMatrixName kSceneMatrices[] = {
    {"mvp", SceneMatrix::ModelViewProjection, 4},
    {"modelViewProjection", SceneMatrix::ModelViewProjection, 4},
    {"model", SceneMatrix::Model, 4},
    {"view", SceneMatrix::View, 4},
    {"projection", SceneMatrix::Projection, 4},
    {"normalMatrix", SceneMatrix::Normal, 3},
};

enum class VertexAttribute { Position, Normal, Texcoord0, Texcoord1, Color };

struct VertexAttributeName {
    std::string_view name;
    VertexAttribute attribute;
    int components;           // of the data: vec3 positions and normals, vec2 texcoords, vec4 colours
    std::string_view gltf;    // the glTF attribute semantic it is read from
};
inline constexpr VertexAttributeName kVertexAttributes[] = {
    {"position", VertexAttribute::Position, 3, "POSITION"},
    {"normal", VertexAttribute::Normal, 3, "NORMAL"},
    {"texcoord", VertexAttribute::Texcoord0, 2, "TEXCOORD_0"},
    {"texcoord0", VertexAttribute::Texcoord0, 2, "TEXCOORD_0"},
    {"texcoord1", VertexAttribute::Texcoord1, 2, "TEXCOORD_1"},
    {"color", VertexAttribute::Color, 4, "COLOR_0"},
};

// The entry of that GLSL name; nullptr for none.
constexpr const SceneMatrixName* find_scene_matrix(std::string_view name) {
    for (const SceneMatrixName& m : kSceneMatrices) {
        if (m.name == name) return &m;
    }
    return nullptr;
}
constexpr const VertexAttributeName* find_vertex_attribute(std::string_view name) {
    for (const VertexAttributeName& a : kVertexAttributes) {
        if (a.name == name) return &a;
    }
    return nullptr;
}

// The names, for messages: "mvp, modelViewProjection, model, view, projection, normalMatrix".
std::string_view scene_matrix_names();
std::string_view vertex_attribute_names();

// Object `i`'s transforms under `pose`, for a frame of the given aspect ratio, composed in double
// and rounded to float once. model_view_projection is Scene::clip_from_object's, bit for bit, so
// that a shader reading `mvp` and one reading gl_ModelViewProjectionMatrix place vertices alike.
struct ObjectTransforms {
    glm::mat4 model_view_projection{1.0f};
    glm::mat4 model{1.0f}, view{1.0f}, projection{1.0f};
    glm::mat3 normal{1.0f};
};
ObjectTransforms object_transforms(const Scene& scene, const Pose& pose, std::size_t i, double aspect);

}  // namespace qs
