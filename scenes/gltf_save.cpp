// save_scene: a Scene written as glTF 2.0 through tinygltf, for the scene generator
// (generators/) and for `quadshade bake`'s baked scenes. One buffer holds the meshes (and the
// images stored as bufferViews); each object gets a material, a mesh of its own (glTF puts the
// material on the primitive) and a node, or sits on the SavedNode that carries it; the camera is
// the first node.
#include "scenes/gltf.h"

#include <algorithm>
#include <vector>

#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

#include "scenes/base64.h"

namespace qs {

namespace {

namespace fs = std::filesystem;

// The file's one buffer, and views and accessors into it.
struct BufferWriter {
    tinygltf::Model& m;
    tinygltf::Buffer buffer;

    // A view of `bytes` appended at the next 4-byte boundary.
    int view(const void* data, std::size_t bytes) {
        while (buffer.data.size() % 4) buffer.data.push_back(0);
        const std::size_t offset = buffer.data.size();
        const auto* p = static_cast<const unsigned char*>(data);
        buffer.data.insert(buffer.data.end(), p, p + bytes);
        tinygltf::BufferView v;
        v.buffer = 0, v.byteOffset = offset, v.byteLength = bytes;
        m.bufferViews.push_back(v);
        return int(m.bufferViews.size() - 1);
    }

    int accessor(int view, int component, int type, std::size_t count, std::vector<double> mn = {},
                 std::vector<double> mx = {}) {
        tinygltf::Accessor a;
        a.bufferView = view, a.componentType = component, a.type = type, a.count = count;
        a.minValues = std::move(mn), a.maxValues = std::move(mx);
        m.accessors.push_back(a);
        return int(m.accessors.size() - 1);
    }
};

// The scene's meshes, material-less: the templates each object's mesh copies.
void add_meshes(const Scene& scene, BufferWriter& buffer) {
    for (const Mesh& mesh : scene.meshes) {
        std::vector<float> pos, st;
        std::vector<double> mn(3, 1e30), mx(3, -1e30);
        for (const Vertex& v : mesh.vertices) {
            for (int i = 0; i < 3; ++i) {
                pos.push_back(v.position[i]);
                mn[std::size_t(i)] = std::min(mn[std::size_t(i)], double(v.position[i]));
                mx[std::size_t(i)] = std::max(mx[std::size_t(i)], double(v.position[i]));
            }
            st.push_back(v.texcoord.x), st.push_back(v.texcoord.y);
        }
        tinygltf::Primitive p;
        p.mode = TINYGLTF_MODE_TRIANGLES;
        p.attributes["POSITION"] = buffer.accessor(buffer.view(pos.data(), pos.size() * 4),
                                                   TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
                                                   mesh.vertices.size(), mn, mx);
        if (mesh.has_texcoords) {
            p.attributes["TEXCOORD_0"] = buffer.accessor(buffer.view(st.data(), st.size() * 4),
                                                         TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2,
                                                         mesh.vertices.size());
        }
        p.indices = buffer.accessor(buffer.view(mesh.indices.data(), mesh.indices.size() * 4),
                                    TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, mesh.indices.size());
        tinygltf::Mesh gm;
        gm.name = mesh.name;
        gm.primitives.push_back(p);
        buffer.m.meshes.push_back(gm);
    }
}

// Textures as glTF writes them: an image (a file beside the scene, a data: URI or a bufferView),
// a sampler, and the texture pairing them; materials bind theirs as baseColorTexture.
void add_textures(const Scene& scene, const fs::path& path, BufferWriter& buffer) {
    tinygltf::Model& m = buffer.m;
    for (const Texture& t : scene.textures) {
        tinygltf::Image image;
        // A cube map's faces are files its binding lists (samplers_value); its texture keeps the
        // indices of the others and pairs its first face with its sampler.
        const ImageSource& source = t.dims == kCubeMap ? t.faces.at(0) : t.image;
        image.mimeType = source.mime_type;
        switch (source.kind) {
            case ImageSource::Kind::File:
                image.uri = fs::relative(source.file, path.parent_path()).generic_string();
                image.mimeType.clear();
                break;
            case ImageSource::Kind::DataUri:
                image.uri = "data:" + source.mime_type + ";base64," + base64(source.bytes);
                image.mimeType.clear();
                break;
            case ImageSource::Kind::BufferView:
                image.bufferView = buffer.view(source.bytes.data(), source.bytes.size());
                break;
        }
        m.images.push_back(image);
        tinygltf::Sampler sampler;
        sampler.magFilter = int(t.sampler.mag_filter), sampler.minFilter = int(t.sampler.min_filter);
        sampler.wrapS = int(t.sampler.wrap_s), sampler.wrapT = int(t.sampler.wrap_t);
        m.samplers.push_back(sampler);
        tinygltf::Texture texture;
        texture.source = texture.sampler = int(m.images.size() - 1);
        m.textures.push_back(texture);
    }
}

// A material's extras.uniforms: each a number or an array of numbers.
tinygltf::Value uniforms_value(const std::vector<UniformSetting>& settings) {
    tinygltf::Value::Object uniforms;
    for (const UniformSetting& u : settings) {
        if (u.values.size() == 1) {
            uniforms[u.name] = tinygltf::Value(u.values[0]);
        } else {
            tinygltf::Value::Array a;
            for (double x : u.values) a.emplace_back(x);
            uniforms[u.name] = tinygltf::Value(std::move(a));
        }
    }
    return tinygltf::Value(std::move(uniforms));
}

// A material's extras.textures: a 2D texture by its index, a volume with its depth and r wrap, a
// cube map by its faces (files) and sampler, a depth comparison texture with its compare function.
tinygltf::Value samplers_value(const Scene& scene, const std::vector<SamplerBinding>& samplers, const fs::path& path) {
    tinygltf::Value::Object named;
    for (const SamplerBinding& b : samplers) {
        const Texture& t = scene.textures[std::size_t(b.texture)];
        if (t.dims == kCubeMap) {
            tinygltf::Value::Array faces;
            for (const ImageSource& f : t.faces) faces.emplace_back(fs::relative(f.file, path.parent_path()).generic_string());
            tinygltf::Value::Object cube{{"faces", tinygltf::Value(std::move(faces))}, {"sampler", tinygltf::Value(b.texture)}};
            if (t.compare) cube["compare"] = tinygltf::Value(std::string(compare_func_name(*t.compare)));
            named[b.uniform] = tinygltf::Value(std::move(cube));
        } else if (t.compare) {
            named[b.uniform] = tinygltf::Value(tinygltf::Value::Object{
                {"texture", tinygltf::Value(b.texture)},
                {"compare", tinygltf::Value(std::string(compare_func_name(*t.compare)))}});
        } else if (t.dims == 2) {
            named[b.uniform] = tinygltf::Value(b.texture);
        } else {
            named[b.uniform] = tinygltf::Value(tinygltf::Value::Object{
                {"texture", tinygltf::Value(b.texture)},
                {"depth", tinygltf::Value(t.depth)},
                {"wrapR", tinygltf::Value(int(t.sampler.wrap_r))}});
        }
    }
    return tinygltf::Value(named);
}

// The object's material: its shader (or GLSL files, beside the scene), uniforms and textures in
// extras, its texture as baseColorTexture.
tinygltf::Material material_of(const Scene& scene, const Object& o, const fs::path& path) {
    tinygltf::Material mat;
    mat.name = o.name;
    mat.doubleSided = o.double_sided;
    tinygltf::Value::Object extras;
    if (!o.shader.empty()) extras["shader"] = tinygltf::Value(o.shader);
    if (!o.glsl_fragment.empty()) {
        auto beside = [&](const fs::path& f) {
            return tinygltf::Value(fs::relative(f, path.parent_path()).generic_string());
        };
        tinygltf::Value::Object glsl{{"fragment", beside(o.glsl_fragment)}};
        if (!o.glsl_vertex.empty()) glsl["vertex"] = beside(o.glsl_vertex);
        extras["glsl"] = tinygltf::Value(glsl);
    }
    if (!o.uniforms.empty()) extras["uniforms"] = uniforms_value(o.uniforms);
    if (!o.samplers.empty()) extras["textures"] = samplers_value(scene, o.samplers, path);
    if (!extras.empty()) mat.extras = tinygltf::Value(std::move(extras));
    mat.pbrMetallicRoughness.baseColorTexture.index = o.texture;
    return mat;
}

// Each object's material, and a mesh of its own carrying it (glTF puts the material on the
// primitive), after the templates; returns the glTF index of each object's mesh.
std::vector<int> add_materials(const Scene& scene, const fs::path& path, tinygltf::Model& m) {
    std::vector<int> mesh_of_object;
    for (const Object& o : scene.objects) {
        m.materials.push_back(material_of(scene, o, path));
        tinygltf::Mesh gm = m.meshes[o.mesh];
        gm.name = o.name;
        gm.primitives[0].material = int(m.materials.size() - 1);
        m.meshes.push_back(gm);
        mesh_of_object.push_back(int(m.meshes.size() - 1));
    }
    return mesh_of_object;
}

// A root node for each object, at its world transform.
void add_object_nodes(const Scene& scene, const std::vector<int>& mesh_of_object, tinygltf::Model& m,
                      tinygltf::Scene& gs) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        tinygltf::Node n;
        n.name = o.name;
        n.mesh = mesh_of_object[i];
        n.matrix.assign(glm::value_ptr(o.world_from_object), glm::value_ptr(o.world_from_object) + 16);
        m.nodes.push_back(n);
        gs.nodes.push_back(int(m.nodes.size() - 1));
    }
}

// The caller's node hierarchy; every object must sit on exactly one of its nodes.
void add_saved_nodes(const Scene& scene, const fs::path& path, std::span<const SavedNode> nodes,
                     const std::vector<int>& mesh_of_object, tinygltf::Model& m, tinygltf::Scene& gs) {
    std::vector<int> carried(scene.objects.size(), 0);
    const std::size_t first_node = m.nodes.size();  // glTF index of nodes[0]
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const SavedNode& sn = nodes[i];
        const std::string field = path.string() + ": saving node " + std::to_string(i) + " '" + sn.name + "': ";
        if (sn.parent >= int(i) || sn.parent < -1) throw SceneError(field + "its parent must be an earlier node");
        if (sn.object >= int(scene.objects.size()) || sn.object < -1) throw SceneError(field + "no such object");
        tinygltf::Node n;
        n.name = sn.name;
        if (sn.object >= 0) n.mesh = mesh_of_object[std::size_t(sn.object)], ++carried[std::size_t(sn.object)];
        if (sn.matrix) {
            n.matrix.assign(glm::value_ptr(*sn.matrix), glm::value_ptr(*sn.matrix) + 16);
        } else {
            n.translation = {sn.translation.x, sn.translation.y, sn.translation.z};
            n.rotation = {sn.rotation.x, sn.rotation.y, sn.rotation.z, sn.rotation.w};
            n.scale = {sn.scale.x, sn.scale.y, sn.scale.z};
        }
        m.nodes.push_back(n);
        const int index = int(first_node + i);
        if (sn.parent < 0) gs.nodes.push_back(index);
        else m.nodes[first_node + std::size_t(sn.parent)].children.push_back(index);
    }
    if (std::count(carried.begin(), carried.end(), 1) != std::ptrdiff_t(carried.size())) {
        throw SceneError(path.string() + ": saving nodes: every object must sit on exactly one node");
    }
}

// Drops the material-less template meshes: the objects' meshes follow them.
void drop_template_meshes(const Scene& scene, tinygltf::Model& m) {
    const int templates = int(scene.meshes.size());
    m.meshes.erase(m.meshes.begin(), m.meshes.begin() + templates);
    for (tinygltf::Node& n : m.nodes) {
        if (n.mesh >= 0) n.mesh -= templates;
    }
}

// The scene's camera, on the scene's first root node.
void add_camera(const Scene& scene, tinygltf::Model& m, tinygltf::Scene& gs) {
    tinygltf::Camera cam;
    if (scene.camera.kind == Camera::Kind::Perspective) {
        cam.type = "perspective";
        cam.perspective.yfov = scene.camera.yfov;
        cam.perspective.znear = scene.camera.znear;
        cam.perspective.zfar = scene.camera.zfar;
    } else {
        cam.type = "orthographic";
        cam.orthographic.xmag = scene.camera.xmag, cam.orthographic.ymag = scene.camera.ymag;
        cam.orthographic.znear = scene.camera.znear, cam.orthographic.zfar = scene.camera.zfar;
    }
    m.cameras.push_back(cam);
    tinygltf::Node cn;
    cn.name = "camera";
    cn.camera = 0;
    // Inverted in float, as the scenes written so far were: the shipped files stay as they are.
    const glm::mat4 world_from_view = glm::inverse(glm::mat4(scene.camera.view));
    cn.matrix.assign(glm::value_ptr(world_from_view), glm::value_ptr(world_from_view) + 16);
    m.nodes.push_back(cn);
    gs.nodes.insert(gs.nodes.begin(), int(m.nodes.size() - 1));
}

// scenes[0].extras: the clear colour, time, size and stretch (gltf.h).
tinygltf::Value scene_extras(const Scene& scene) {
    tinygltf::Value::Array clear;
    for (int i = 0; i < 4; ++i) clear.push_back(tinygltf::Value(double(scene.clear_color[i])));
    tinygltf::Value::Object extras{
        {"clear_color", tinygltf::Value(clear)},
        {"time", tinygltf::Value(double(scene.time))},
        {"size", tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(scene.width), tinygltf::Value(scene.height)})}};
    if (scene.camera.stretch) extras["stretch"] = tinygltf::Value(true);
    return tinygltf::Value(std::move(extras));
}

// tinygltf's image writer: write no file, keep each image's URI (or bufferView) as it is.
bool keep_image_uri(const std::string*, const std::string*, const tinygltf::Image*, bool, std::string*, void*) {
    return false;
}

}  // namespace

void save_scene(const Scene& scene, const fs::path& path, std::span<const SavedNode> nodes) {
    tinygltf::Model m;
    m.asset.version = "2.0";
    m.asset.generator = "quadshade scene generator";
    BufferWriter buffer{m, {}};
    add_meshes(scene, buffer);
    const bool binary = path.extension() == ".glb";
    if (!binary) buffer.buffer.uri = path.stem().string() + ".bin";
    add_textures(scene, path, buffer);
    const std::vector<int> mesh_of_object = add_materials(scene, path, m);
    tinygltf::Scene gs;
    if (nodes.empty()) {
        add_object_nodes(scene, mesh_of_object, m, gs);
    } else {
        add_saved_nodes(scene, path, nodes, mesh_of_object, m, gs);
    }
    drop_template_meshes(scene, m);
    add_camera(scene, m, gs);
    gs.extras = scene_extras(scene);
    m.scenes.push_back(gs);
    m.defaultScene = 0;

    m.buffers.push_back(buffer.buffer);  // last: textures above may append to it
    tinygltf::TinyGLTF writer;
    writer.SetImageWriter(keep_image_uri, nullptr);
    if (!writer.WriteGltfSceneToFile(&m, path.string(), false, binary, !binary, binary)) {
        throw SceneError(path.string() + ": cannot write glTF");
    }
}

}  // namespace qs
