// SPDX-License-Identifier: MIT
// glTF scene traversal: node transforms, primitives to shared IR meshes, cameras and lights.
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

#include "core/math/float_util.h"
#include "importers/gltf/gltf_internal.h"
#include "importers/gltf/gltf_tangents.h"

namespace rt::gltf::detail {

namespace {

/// glTF's +Y up to the IR's +Z up, (x, y, z) -> (x, -z, y): +90 degrees about X, so winding,
/// normals and handedness are kept (gltf-notes section 2).
Mat4 zUpFromYUp() {
    Mat4 c;
    c.m[1][1] = 0;
    c.m[1][2] = -1;
    c.m[2][1] = 1;
    c.m[2][2] = 0;
    return c;
}

/// Deepest node hierarchy followed; a deeper one is taken for a corrupt file rather than
/// risking the stack.
constexpr int kMaxNodeDepth = 1000;

/// Exposure constant: IR light colour = glTF colour x intensity (cd or lux) x k. With it a
/// 1 cd point light 1 m away lights a white diffuse surface to about 1/pi (gltf-notes 7).
constexpr double kLightExposure = 1 / kPi;

const char *modeName(int mode) {
    switch (mode) {
        case 0:
            return "POINTS";
        case 1:
            return "LINES";
        case 2:
            return "LINE_LOOP";
        case 3:
            return "LINE_STRIP";
        case 4:
            return "TRIANGLES";
        case 5:
            return "TRIANGLE_STRIP";
        case 6:
            return "TRIANGLE_FAN";
        default:
            return "unknown";
    }
}

bool allFinite(const std::vector<double> &v) {
    return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

/// The rotation of quaternion (x, y, z, w), normalised here; nothing for a zero quaternion.
std::optional<Mat4> rotationMatrix(std::array<double, 4> q) {
    double len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(len > 0) || !std::isfinite(len)) return std::nullopt;
    double x = q[0] / len, y = q[1] / len, z = q[2] / len, w = q[3] / len;
    double rows[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                         {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                         {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    Mat4 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r.m[i][j] = rows[i][j];
    return r;
}

}  // namespace

/// The node's local matrix: `matrix` (16 numbers, column-major) or T * R * S with the rotation
/// a unit quaternion stored (x, y, z, w).
Mat4 localMatrix(const ImportContext &ctx, const tinygltf::Node &node, const std::string &path) {
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16 || !allFinite(node.matrix))
            ctx.fail(path + ".matrix: needs 16 finite numbers");
        if (!node.translation.empty() || !node.rotation.empty() || !node.scale.empty())
            ctx.note(path + ": has both matrix and TRS; the matrix is used");
        Mat4 m;
        for (int row = 0; row < 4; ++row)
            for (int col = 0; col < 4; ++col)
                m.m[row][col] = node.matrix[static_cast<size_t>(col * 4 + row)];
        if (!m.isAffine())
            ctx.fail(path + ".matrix: the last row must be (0, 0, 0, 1), got " + m.toString());
        return m;
    }
    auto check = [&](const std::vector<double> &v, size_t n, const char *name) {
        if (!v.empty() && (v.size() != n || !allFinite(v)))
            ctx.fail(path + "." + name + ": needs " + std::to_string(n) + " finite numbers");
    };
    check(node.translation, 3, "translation");
    check(node.rotation, 4, "rotation");
    check(node.scale, 3, "scale");
    Mat4 t, r, s;
    if (!node.translation.empty())
        t = Mat4::translate(Vec3(node.translation[0], node.translation[1], node.translation[2]));
    if (!node.scale.empty()) s = Mat4::scale(Vec3(node.scale[0], node.scale[1], node.scale[2]));
    if (!node.rotation.empty()) {
        std::optional<Mat4> rot = rotationMatrix(
            {node.rotation[0], node.rotation[1], node.rotation[2], node.rotation[3]});
        if (!rot) ctx.fail(path + ".rotation: the quaternion is zero");
        r = *rot;
    }
    return t * r * s;
}

namespace {

/// Most instances one EXT_mesh_gpu_instancing node may place (each is an IR node).
constexpr size_t kMaxGpuInstances = size_t(1) << 18;

/// Components per element of an accessor type this file reads.
int components(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return 1;
        case TINYGLTF_TYPE_VEC2:
            return 2;
        case TINYGLTF_TYPE_VEC3:
            return 3;
        default:
            return 4;
    }
}

/// A light that waits for the scene bounds (directional lights are placed outside them).
struct PendingLight {
    int light;
    Mat4 world;
    std::string path;
};

class SceneBuilder {
  public:
    SceneBuilder(const ImportContext &ctx, ir::Scene &scene, const BuildOptions &options)
        : ctx_(ctx),
          model_(ctx.model),
          scene_(scene),
          options_(options),
          visited_(ctx.model.nodes.size(), 0),
          meshIds_(ctx.model.meshes.size()) {
        if (!options.materialOverride) materials_.emplace(ctx, scene);
    }

    ir::NodePtr build(int sceneIndex) {
        const tinygltf::Scene &gs = model_.scenes[static_cast<size_t>(sceneIndex)];
        std::string path = jsonPath("scenes", static_cast<size_t>(sceneIndex));
        Mat4 rootMatrix = zUpFromYUp() * Mat4::scale(Vec3(ctx_.opts.unitScale));
        auto root = ir::Node::makeTransform(rootMatrix, options_.nodeLoc);
        root->label = "glTF Y-up to Z-up";
        for (size_t i = 0; i < gs.nodes.size(); ++i) {
            ir::NodePtr child =
                buildNode(gs.nodes[i], rootMatrix, 1, path + ".nodes[" + std::to_string(i) + "]");
            if (child) root->children.push_back(std::move(child));
        }
        if (root->children.empty()) ctx_.warning(path + ": has no triangles to show");
        if (!model_.animations.empty())
            ctx_.note(std::to_string(model_.animations.size()) +
                      " animation(s) ignored; the nodes are shown as stored");
        if (droppedTriangles_ > 0)
            ctx_.note("dropped " + std::to_string(droppedTriangles_) +
                      " zero-area triangle(s) in " + std::to_string(primitivesWithDropped_) +
                      " primitive(s)");
        if (extraCameras_ > 0)
            ctx_.note(std::to_string(extraCameras_) +
                      " more camera node(s) ignored; the first in traversal order is used");
        if (options_.camerasAndLights)
            addLights(*root);
        else if (ignoredCameras_ > 0 || !pendingLights_.empty())
            ctx_.note("the file's " + std::to_string(ignoredCameras_) + " camera(s) and " +
                      std::to_string(pendingLights_.size()) + " light(s) are ignored in import()");
        return root;
    }

  private:
    ir::NodePtr buildNode(int index, const Mat4 &parentWorld, int depth, const std::string &ref) {
        if (index < 0 || static_cast<size_t>(index) >= model_.nodes.size())
            ctx_.fail(ref + ": node " + std::to_string(index) + " does not exist (the file has " +
                      std::to_string(model_.nodes.size()) + ")");
        std::string path = jsonPath("nodes", static_cast<size_t>(index));
        if (visited_[static_cast<size_t>(index)])
            ctx_.fail(path + ": reached twice from " + ref +
                      " (a node has at most one parent and the hierarchy has no cycles)");
        visited_[static_cast<size_t>(index)] = 1;
        if (depth > kMaxNodeDepth)
            ctx_.fail(path + ": the node hierarchy is deeper than " +
                      std::to_string(kMaxNodeDepth));

        const tinygltf::Node &node = model_.nodes[static_cast<size_t>(index)];
        Mat4 local = localMatrix(ctx_, node, path);
        if (!local.affineInverse()) {
            // A zero scale (animation files use it to hide parts) leaves nothing to see
            ctx_.note(path +
                      ": its transform is singular (zero scale); it and its children "
                      "are not shown");
            return nullptr;
        }
        Mat4 world = parentWorld * local;
        auto t = ir::Node::makeTransform(local, options_.nodeLoc);
        t->label = node.name.empty() ? path : "node '" + node.name + "'";

        if (node.mesh >= 0) addMesh(*t, static_cast<size_t>(index), path);
        if (node.camera >= 0) addCamera(node.camera, world, path);
        auto ext = node.extensions.find("KHR_lights_punctual");
        if (ext != node.extensions.end()) {
            std::string lightPath = path + ".extensions.KHR_lights_punctual.light";
            double li = ext->second.Has("light") && ext->second.Get("light").IsNumber()
                            ? ext->second.Get("light").GetNumberAsDouble()
                            : -1;
            if (!(li >= 0 && li < static_cast<double>(model_.lights.size())) ||
                li != std::floor(li))
                ctx_.fail(lightPath + ": no such light (the file has " +
                          std::to_string(model_.lights.size()) + ")");
            pendingLights_.push_back({static_cast<int>(li), world, path});
        }

        for (size_t i = 0; i < node.children.size(); ++i) {
            ir::NodePtr child = buildNode(node.children[i], world, depth + 1,
                                          path + ".children[" + std::to_string(i) + "]");
            if (child) t->children.push_back(std::move(child));
        }
        if (t->children.empty()) return nullptr;
        return t;
    }

    /// How a node poses its mesh: morph weights (empty when all zero) and skin (-1: none).
    struct Pose {
        std::vector<double> weights;
        int skin = -1;
        bool posed() const { return !weights.empty() || skin >= 0; }
    };

    /// The node's mesh, skinned and morphed as it says, under `parent`: once, or once per
    /// EXT_mesh_gpu_instancing instance.
    void addMesh(ir::Node &parent, size_t nodeIndex, const std::string &path) {
        const tinygltf::Node &node = model_.nodes[nodeIndex];
        if (static_cast<size_t>(node.mesh) >= model_.meshes.size())
            ctx_.fail(path + ": mesh " + std::to_string(node.mesh) +
                      " does not exist (the file has " + std::to_string(model_.meshes.size()) +
                      ")");
        Pose pose;
        pose.weights = poser_.weights(nodeIndex);
        if (std::all_of(pose.weights.begin(), pose.weights.end(), [](double w) { return w == 0; }))
            pose.weights.clear();
        ir::Node *target = &parent;
        if (node.skin >= 0) {
            if (static_cast<size_t>(node.skin) >= model_.skins.size())
                ctx_.fail(path + ".skin: skin " + std::to_string(node.skin) +
                          " does not exist (the file has " + std::to_string(model_.skins.size()) +
                          ")");
            // glTF 3.7.3.3: only the joints' transforms place a skinned mesh, not its node's
            std::optional<Mat4> inverse = poser_.global(nodeIndex).affineInverse();
            if (!inverse) ctx_.fail(path + ": its global transform is singular");
            pose.skin = node.skin;
            auto skinned = ir::Node::makeTransform(*inverse, options_.nodeLoc);
            skinned->label = path + " skinned (node transform ignored)";
            target = skinned.get();
            parent.children.push_back(std::move(skinned));
        }
        std::optional<std::vector<Mat4>> instances = gpuInstances(node, path);
        if (!instances) {
            addPrimitives(*target, node.mesh, pose, path);
        } else {
            for (size_t i = 0; i < instances->size(); ++i) {
                auto inst = ir::Node::makeTransform((*instances)[i], options_.nodeLoc);
                inst->label = path + " instance " + std::to_string(i);
                addPrimitives(*inst, node.mesh, pose, path);
                if (!inst->children.empty()) target->children.push_back(std::move(inst));
            }
        }
        if (target != &parent && target->children.empty()) parent.children.pop_back();
    }

    /// The instance transforms of EXT_mesh_gpu_instancing (none without the extension).
    std::optional<std::vector<Mat4>> gpuInstances(const tinygltf::Node &node,
                                                  const std::string &path) {
        auto ext = node.extensions.find("EXT_mesh_gpu_instancing");
        if (ext == node.extensions.end()) return std::nullopt;
        std::string extPath = path + ".extensions.EXT_mesh_gpu_instancing";
        const tinygltf::Value &attrs = ext->second.Get("attributes");
        if (!attrs.IsObject()) ctx_.fail(extPath + ": needs an attributes object");
        std::optional<FloatArray> values[3];
        const char *names[3] = {"TRANSLATION", "ROTATION", "SCALE"};
        const int types[3] = {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4, TINYGLTF_TYPE_VEC3};
        std::optional<size_t> count;
        for (int k = 0; k < 3; ++k) {
            if (!attrs.Has(names[k])) continue;
            const tinygltf::Value &v = attrs.Get(names[k]);
            std::string what = extPath + ".attributes." + names[k];
            if (!v.IsNumber()) ctx_.fail(what + ": needs an accessor index");
            double index = v.GetNumberAsDouble();
            if (index != std::floor(index) || index < 0 || index > 1e9)
                ctx_.fail(what + ": " + std::to_string(index) + " is not an accessor index");
            values[k] = readFloats(ctx_, static_cast<int>(index), types[k], what);
            if (count && *count != values[k]->count)
                ctx_.fail(what + ": " + std::to_string(values[k]->count) +
                          " instances, but the other attributes have " + std::to_string(*count));
            count = values[k]->count;
        }
        if (!count) ctx_.fail(extPath + ": has none of TRANSLATION, ROTATION and SCALE");
        if (*count > kMaxGpuInstances)
            ctx_.fail(extPath + ": " + std::to_string(*count) + " instances, more than " +
                      std::to_string(kMaxGpuInstances));
        std::vector<Mat4> out;
        size_t singular = 0;
        for (size_t i = 0; i < *count; ++i) {
            auto vec = [&](int k, size_t n, Vec3 fallback) {
                if (!values[k]) return fallback;
                const float *p = values[k]->values.data() + i * n;
                return Vec3(p[0], p[1], p[2]);
            };
            Vec3 tr = vec(0, 3, Vec3(0, 0, 0)), sc = vec(2, 3, Vec3(1, 1, 1));
            std::array<double, 4> q = {0, 0, 0, 1};
            if (values[1])
                for (int c = 0; c < 4; ++c) q[c] = values[1]->values[i * 4 + c];
            std::optional<Mat4> rot = rotationMatrix(q);
            if (!tr.isFinite() || !sc.isFinite() || !rot)
                ctx_.fail(extPath + ": instance " + std::to_string(i) +
                          " has a non-finite translation or scale or a zero rotation");
            Mat4 m = Mat4::translate(tr) * *rot * Mat4::scale(sc);
            if (!m.affineInverse()) {
                ++singular;  // zero scale: hidden, as for nodes
                continue;
            }
            out.push_back(m);
        }
        if (singular > 0)
            ctx_.note(extPath + ": " + std::to_string(singular) +
                      " instance(s) with a zero scale not shown");
        return out;
    }

    /// One Primitive child per glTF primitive that has triangles to show. Primitives that
    /// draw the same IR mesh in the same glTF material (built from the same accessors, indices
    /// and mode) are one surface drawn again in the same place: it is placed once, since each
    /// copy would cost every ray that reaches it (500,000 copies of a triangle: minutes).
    void addPrimitives(ir::Node &parent, int meshIndex, const Pose &pose, const std::string &path) {
        const tinygltf::Mesh &mesh = model_.meshes[static_cast<size_t>(meshIndex)];
        std::set<std::pair<int, int>> placed;
        size_t repeated = 0;
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            int id = meshFor(static_cast<size_t>(meshIndex), p, pose);
            if (id < 0) continue;
            if (!placed.emplace(id, mesh.primitives[p].material).second) {
                ++repeated;
                continue;
            }
            std::string primPath =
                jsonPath("meshes", static_cast<size_t>(meshIndex)) + jsonPath(".primitives", p);
            int material;
            if (options_.materialOverride) {
                material = *options_.materialOverride;
            } else {
                std::optional<int> m = materials_->irMaterial(
                    mesh.primitives[p].material, *scene_.meshes[static_cast<size_t>(id)], primPath);
                if (!m) continue;
                material = *m;
            }
            auto prim = ir::Node::makePrimitive(ir::MeshPrim{id}, material, options_.nodeLoc);
            prim->label = "mesh '" + scene_.meshes[static_cast<size_t>(id)]->name + "'";
            parent.children.push_back(std::move(prim));
        }
        if (repeated > 0 && repeatedReported_.insert(meshIndex).second)
            ctx_.warning(path + ": " + jsonPath("meshes", static_cast<size_t>(meshIndex)) +
                         " has " + std::to_string(repeated) +
                         " primitive(s) repeating an earlier one (the same accessors, indices, "
                         "mode and material); each surface is drawn once");
    }

    /// The IR mesh of a glTF (mesh, primitive) in a pose, loaded on first use and shared by
    /// every node that uses it so; -1 when it has nothing to show.
    int meshFor(size_t meshIndex, size_t primIndex, const Pose &pose) {
        if (pose.posed()) {
            auto [it, isNew] = posedMeshes_.try_emplace(
                std::tuple(meshIndex, primIndex, pose.weights, pose.skin), -1);
            if (isNew)
                it->second = addMesh(
                    loadPrimitive(meshIndex, primIndex, pose, tangentSet(meshIndex, primIndex)));
            return it->second;
        }
        std::vector<int> &ids = meshIds_[meshIndex];
        if (ids.empty()) ids.assign(model_.meshes[meshIndex].primitives.size(), kNotLoaded);
        int &id = ids[primIndex];
        if (id != kNotLoaded) return id;

        // Primitives of different meshes built from the same accessors (CAD exporters make one
        // mesh per material) share one IR mesh too; compressed ones are decoded each
        const tinygltf::Primitive &prim = model_.meshes[meshIndex].primitives[primIndex];
        int tangents = tangentSet(meshIndex, primIndex);
        if (prim.extensions.count("KHR_draco_mesh_compression") || !prim.targets.empty())
            return id = addMesh(loadPrimitive(meshIndex, primIndex, pose, tangents));
        auto attribute = [&](const char *name) {
            auto it = prim.attributes.find(name);
            return it == prim.attributes.end() ? -1 : it->second;
        };
        PrimitiveKey key{attribute("POSITION"),
                         attribute("NORMAL"),
                         attribute("TEXCOORD_0"),
                         attribute("TEXCOORD_1"),
                         attribute("TANGENT"),
                         attribute("COLOR_0"),
                         prim.indices,
                         prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode,
                         tangents};
        auto [shared, isNew] = sharedMeshes_.try_emplace(key, -1);
        if (isNew) shared->second = addMesh(loadPrimitive(meshIndex, primIndex, pose, tangents));
        return id = shared->second;
    }

    /// The texture coordinate set a primitive's normal map reads, from which its mesh gets
    /// tangents when the file gives none; -1 when its material has no normal map (or the
    /// primitive is skipped for its mode or lack of POSITION, or materials are overridden).
    int tangentSet(size_t meshIndex, size_t primIndex) {
        if (options_.materialOverride) return -1;
        const tinygltf::Primitive &prim = model_.meshes[meshIndex].primitives[primIndex];
        int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        if (mode < 4 || mode > 6 || !prim.attributes.count("POSITION")) return -1;
        return materials_->tangentTexCoord(
            prim.material, jsonPath("meshes", meshIndex) + jsonPath(".primitives", primIndex));
    }

    int addMesh(std::optional<ir::Mesh> mesh) {
        if (!mesh) return -1;
        scene_.meshes.push_back(std::make_shared<const ir::Mesh>(std::move(*mesh)));
        return static_cast<int>(scene_.meshes.size()) - 1;
    }

    /// `tangentSet` >= 0: tangents generated from that texture coordinate set where the file
    /// gives none (a normal-mapped material).
    std::optional<ir::Mesh> loadPrimitive(size_t meshIndex, size_t primIndex, const Pose &pose,
                                          int tangentSet) {
        const tinygltf::Mesh &gm = model_.meshes[meshIndex];
        const tinygltf::Primitive &prim = gm.primitives[primIndex];
        std::string path = jsonPath("meshes", meshIndex) + jsonPath(".primitives", primIndex);

        // Topology: triangles, strips and fans are surfaces; points and lines are not
        int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        if (mode >= 0 && mode <= 3) {
            ctx_.warning(path + ": mode " + std::to_string(mode) + " (" + modeName(mode) +
                         ") has no surface to render; skipped");
            return std::nullopt;
        }
        if (mode > 6) ctx_.fail(path + ": invalid mode " + std::to_string(mode));
        if (!prim.attributes.count("POSITION")) {
            ctx_.warning(path + ": has no POSITION attribute; skipped");
            return std::nullopt;
        }

        // Attributes come from their accessors, or from the Draco data that replaces them
        std::unique_ptr<DracoPrimitive> draco = DracoPrimitive::decode(ctx_, prim, path);
        if (draco) mode = TINYGLTF_MODE_TRIANGLES;  // Draco data holds triangles
        AttributeReader read = [&](const std::string &name, int type) -> std::optional<FloatArray> {
            auto it = prim.attributes.find(name);
            if (it == prim.attributes.end()) return std::nullopt;
            std::string what = path + ".attributes." + name;
            checkAttributeType(ctx_, it->second, name, false, what);
            if (!draco || !draco->has(name)) return readFloats(ctx_, it->second, type, what);
            const tinygltf::Accessor &acc = model_.accessors[static_cast<size_t>(it->second)];
            if (acc.type != type)
                ctx_.fail(what + " (" + jsonPath("accessors", static_cast<size_t>(it->second)) +
                          "): the accessor's type does not fit " + name);
            return draco->floats(name, components(type));
        };
        auto attributePath = [&](const char *attribute) {
            return path + ".attributes." + attribute + " (" +
                   jsonPath("accessors", static_cast<size_t>(prim.attributes.at(attribute))) + ")";
        };

        ir::Mesh mesh;
        mesh.name = gm.name.empty() ? "mesh" + std::to_string(meshIndex) : gm.name;
        if (gm.primitives.size() > 1) mesh.name += "/" + std::to_string(primIndex);
        mesh.loc = ctx_.loc;

        // Positions, normals and tangents as stored, then morphed and skinned
        FloatArray pos = *read("POSITION", TINYGLTF_TYPE_VEC3);
        size_t nv = pos.count;
        mesh.positions.resize(nv);
        for (size_t i = 0; i < nv; ++i)
            mesh.positions[i] =
                Vec3(pos.values[3 * i], pos.values[3 * i + 1], pos.values[3 * i + 2]);
        auto countCheck = [&](const FloatArray &a, const char *attribute) {
            if (a.count != nv)
                ctx_.fail(attributePath(attribute) + ": " + std::to_string(a.count) +
                          " elements for " + std::to_string(nv) + " vertices");
        };
        if (std::optional<FloatArray> nrm = read("NORMAL", TINYGLTF_TYPE_VEC3)) {
            countCheck(*nrm, "NORMAL");
            mesh.normals.resize(nv);
            for (size_t i = 0; i < nv; ++i)
                mesh.normals[i] =
                    Vec3(nrm->values[3 * i], nrm->values[3 * i + 1], nrm->values[3 * i + 2]);
        }
        if (std::optional<FloatArray> tan = read("TANGENT", TINYGLTF_TYPE_VEC4)) {
            countCheck(*tan, "TANGENT");
            mesh.tangents.resize(nv);
            for (size_t i = 0; i < nv; ++i)
                for (int c = 0; c < 4; ++c) mesh.tangents[i][c] = tan->values[4 * i + c];
        }
        if (!pose.weights.empty()) poser_.morph(prim, path, pose.weights, mesh);
        if (pose.skin >= 0) poser_.skin(pose.skin, read, path, mesh);
        const char *posed = pose.skin >= 0          ? " (after skinning)"
                            : !pose.weights.empty() ? " (after morphing)"
                                                    : "";
        for (size_t i = 0; i < nv; ++i)
            if (!mesh.positions[i].isFinite())
                ctx_.fail(attributePath("POSITION") + ": vertex " + std::to_string(i) +
                          " is not finite " + mesh.positions[i].toString() + posed);

        // Vertex order: the index accessor (or the Draco faces), or the vertices as they come
        std::vector<uint32_t> indices;
        if (draco) {
            indices = draco->indices();
        } else if (prim.indices >= 0) {
            indices = readIndices(ctx_, prim.indices, path + ".indices");
        } else {
            indices.resize(nv);
            std::iota(indices.begin(), indices.end(), 0u);
        }
        for (size_t k = 0; k < indices.size(); ++k)
            if (indices[k] >= nv)
                ctx_.fail(path + ": index " + std::to_string(indices[k]) + " (indices[" +
                          std::to_string(k) + "]) out of range for " + std::to_string(nv) +
                          " vertices");

        // Triangles; strips alternate their winding so every triangle stays counter-clockwise
        size_t n = indices.size();
        size_t dropped = 0;
        auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
            const Vec3 &p0 = mesh.positions[a], &p1 = mesh.positions[b], &p2 = mesh.positions[c];
            if (a == b || b == c || a == c || lengthSquared(cross(p1 - p0, p2 - p0)) == 0) {
                ++dropped;
                return;
            }
            mesh.triangles.push_back({a, b, c});
        };
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            if (n % 3 != 0)
                ctx_.warning(path + ": " + std::to_string(n) +
                             " vertices is not a multiple of 3; the last " + std::to_string(n % 3) +
                             " ignored");
            mesh.triangles.reserve(n / 3);
            for (size_t i = 0; i + 2 < n; i += 3) add(indices[i], indices[i + 1], indices[i + 2]);
        } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            for (size_t i = 0; i + 2 < n; ++i) {
                if (i % 2 == 0)
                    add(indices[i], indices[i + 1], indices[i + 2]);
                else
                    add(indices[i], indices[i + 2], indices[i + 1]);
            }
        } else {  // TRIANGLE_FAN
            for (size_t i = 0; i + 2 < n; ++i) add(indices[i + 1], indices[i + 2], indices[0]);
        }
        if (dropped > 0) {
            droppedTriangles_ += dropped;
            ++primitivesWithDropped_;
        }
        if (mesh.triangles.empty()) {
            ctx_.note(path + ": has no triangles with area; skipped");
            return std::nullopt;
        }

        // Normals: renormalised; without them the renderer shades flat (glTF 3.7.2.1)
        if (!mesh.normals.empty()) {
            bool zero = false;
            for (size_t i = 0; i < nv && !zero; ++i) {
                Vec3 v = mesh.normals[i];
                if (!v.isFinite())
                    ctx_.fail(attributePath("NORMAL") + ": normal " + std::to_string(i) +
                              " is not finite " + v.toString() + posed);
                double len = length(v);
                zero = !(len > 0) || !std::isfinite(1 / len);
                mesh.normals[i] = v / len;
            }
            if (zero) {
                ctx_.warning(attributePath("NORMAL") +
                             ": contains a zero-length normal; flat shading used");
                mesh.normals.clear();
            }
        }

        // Tangents: a unit xyz and the sign of w; ignored without normals (glTF 3.7.2.1)
        if (!mesh.tangents.empty() && mesh.normals.empty()) {
            ctx_.note(attributePath("TANGENT") + ": ignored without normals");
            mesh.tangents.clear();
        }
        for (size_t i = 0; i < mesh.tangents.size(); ++i) {
            std::array<float, 4> &t = mesh.tangents[i];
            Vec3 v(t[0], t[1], t[2]);
            double len = length(v);
            if (!v.isFinite() || !std::isfinite(t[3]))
                ctx_.fail(attributePath("TANGENT") + ": tangent " + std::to_string(i) +
                          " is not finite" + posed);
            if (!(len > 0) || !std::isfinite(1 / len)) {
                ctx_.warning(attributePath("TANGENT") + ": tangent " + std::to_string(i) +
                             " has zero length; the tangents are ignored");
                mesh.tangents.clear();
                break;
            }
            t = {static_cast<float>(v.x / len), static_cast<float>(v.y / len),
                 static_cast<float>(v.z / len), t[3] < 0 ? -1.0f : 1.0f};
        }

        // Texture coordinate sets 0 and 1 (TEXCOORD_2 and up are not used)
        auto readUvs = [&](const char *name, std::vector<std::array<float, 2>> &out) {
            std::optional<FloatArray> uv = read(name, TINYGLTF_TYPE_VEC2);
            if (!uv) return;
            countCheck(*uv, name);
            out.resize(nv);
            for (size_t i = 0; i < nv; ++i) {
                float u = uv->values[2 * i], v = uv->values[2 * i + 1];
                if (!std::isfinite(u) || !std::isfinite(v))
                    ctx_.fail(attributePath(name) + ": coordinate " + std::to_string(i) +
                              " is not finite");
                out[i] = {u, v};
            }
        };
        readUvs("TEXCOORD_0", mesh.uvs);
        readUvs("TEXCOORD_1", mesh.uvs1);

        // COLOR_0: linear RGB or RGBA (alpha 1 for RGB), multiplying the base colour
        auto colorIt = prim.attributes.find("COLOR_0");
        if (colorIt != prim.attributes.end()) {
            int index = colorIt->second;
            bool rgb = index >= 0 && static_cast<size_t>(index) < model_.accessors.size() &&
                       model_.accessors[static_cast<size_t>(index)].type == TINYGLTF_TYPE_VEC3;
            FloatArray c = *read("COLOR_0", rgb ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4);
            countCheck(c, "COLOR_0");
            size_t channels = rgb ? 3 : 4;
            mesh.colors.resize(nv);
            for (size_t i = 0; i < nv; ++i) {
                std::array<float, 4> rgba = {0, 0, 0, 1};
                for (size_t k = 0; k < channels; ++k) {
                    float v = c.values[i * channels + k];
                    if (!std::isfinite(v))
                        ctx_.fail(attributePath("COLOR_0") + ": colour " + std::to_string(i) +
                                  " is not finite");
                    rgba[k] = v;
                }
                mesh.colors[i] = rgba;
            }
        }

        // A normal map without TANGENT: tangents generated (MikkTSpace's way) from its set
        if (tangentSet >= 0 && mesh.tangents.empty()) generateTangents(mesh, tangentSet);
        return mesh;
    }

    /// The first camera in traversal order becomes the scene camera (gltf-notes section 8).
    void addCamera(int cameraIndex, const Mat4 &world, const std::string &nodePath) {
        if (static_cast<size_t>(cameraIndex) >= model_.cameras.size())
            ctx_.fail(nodePath + ": camera " + std::to_string(cameraIndex) +
                      " does not exist (the file has " + std::to_string(model_.cameras.size()) +
                      ")");
        if (!options_.camerasAndLights) {
            ++ignoredCameras_;
            return;
        }
        if (scene_.camera) {
            ++extraCameras_;
            return;
        }
        const tinygltf::Camera &gc = model_.cameras[static_cast<size_t>(cameraIndex)];
        std::string path = jsonPath("cameras", static_cast<size_t>(cameraIndex));

        // The view frame without scale: the lens looks down -Z with +Y up
        Vec3 eye = world.transformPoint(Vec3(0, 0, 0));
        Vec3 forward = world.transformVector(Vec3(0, 0, -1));
        Vec3 up = world.transformVector(Vec3(0, 1, 0));
        double fl = length(forward);
        if (!(fl > 0) || !eye.isFinite()) {
            ctx_.warning(nodePath + ": camera transform is degenerate; camera ignored");
            return;
        }
        forward = forward / fl;
        up = up - forward * dot(up, forward);
        double ul = length(up);
        if (!(ul > 0)) {
            ctx_.warning(nodePath + ": camera transform is degenerate; camera ignored");
            return;
        }

        ir::Camera cam;
        cam.location = eye;
        cam.lookAt = eye + forward;
        cam.sky = up / ul;
        cam.source = ir::CameraSource::Explicit;
        cam.loc = ctx_.loc;
        if (gc.type == "perspective") {
            double yfov = gc.perspective.yfov;
            if (!(yfov > 0 && yfov < kPi)) {
                ctx_.warning(path + ": yfov " + std::to_string(yfov) +
                             " is not in (0, pi); camera ignored");
                return;
            }
            cam.projection = ir::Projection::Perspective;
            cam.fov = degrees(yfov);
            cam.fovAxis = ir::FovAxis::Vertical;
            if (gc.perspective.aspectRatio > 0)
                ctx_.note(path + ": aspectRatio " + std::to_string(gc.perspective.aspectRatio) +
                          " ignored; the image's aspect ratio is used with the vertical field of "
                          "view");
        } else if (gc.type == "orthographic") {
            double ymag = std::abs(gc.orthographic.ymag);
            if (!(ymag > 0) || !std::isfinite(ymag)) {
                ctx_.warning(path + ": ymag must not be zero; camera ignored");
                return;
            }
            cam.projection = ir::Projection::Orthographic;
            cam.orthoHeight = 2 * ymag * ctx_.opts.unitScale;
        } else {
            ctx_.warning(path + ": unknown camera type '" + gc.type + "'; camera ignored");
            return;
        }
        scene_.camera = cam;
    }

    /// KHR_lights_punctual lights, once the geometry (and so the scene bounds) is known.
    void addLights(const ir::Node &root) {
        if (pendingLights_.empty()) return;
        Bounds3 bounds = ir::worldBounds(root, Mat4(), &scene_);
        Vec3 centre(0, 0, 0);
        double diagonal = 0;
        if (!bounds.isEmpty() && bounds.isFinite()) {
            centre = bounds.centroid();
            diagonal = length(bounds.diagonal());
        }
        for (const PendingLight &pl : pendingLights_) {
            const tinygltf::Light &gl = model_.lights[static_cast<size_t>(pl.light)];
            std::string path = jsonPath("lights", static_cast<size_t>(pl.light));
            if (!gl.name.empty()) path += " ('" + gl.name + "')";

            Rgb color(1);  // absent colour: white (tinygltf leaves the vector empty)
            if (gl.color.size() == 3)
                color = Rgb(gl.color[0], gl.color[1], gl.color[2]);
            else if (!gl.color.empty())
                ctx_.warning(path + ": color needs 3 numbers; white used");
            double intensity = gl.intensity;
            if (!(intensity >= 0)) {
                ctx_.warning(path + ": negative intensity; 0 used");
                intensity = 0;
            }
            if (gl.range > 0)
                ctx_.note(path + ": range " + std::to_string(gl.range) +
                          " ignored (the light falls off as 1/d^2 everywhere)");

            ir::Light light;
            light.loc = ctx_.loc;
            Vec3 dir = pl.world.transformVector(Vec3(0, 0, -1));
            double dl = length(dir);
            dir = dl > 0 ? dir / dl : Vec3(0, 0, -1);
            if (gl.type == "point" || gl.type == "spot") {
                // POV-Ray's fade 2 / (1 + (d/D)^2) with D = one metre approximates I / d^2 at
                // distance; the factor 2 at the source is divided out of the colour
                light.kind = gl.type == "point" ? ir::Light::Kind::Point : ir::Light::Kind::Spot;
                light.position = pl.world.transformPoint(Vec3(0, 0, 0));
                light.color = color * (intensity * kLightExposure / 2);
                light.fadeDistance = ctx_.opts.unitScale;
                light.fadePower = 2;
                if (light.kind == ir::Light::Kind::Spot) {
                    light.direction = dir;
                    light.spotRadius = degrees(gl.spot.innerConeAngle);
                    light.spotFalloff = degrees(gl.spot.outerConeAngle);
                    light.spotTightness = 0;
                }
            } else if (gl.type == "directional") {
                light.kind = ir::Light::Kind::Directional;
                light.color = color * (intensity * kLightExposure);
                light.direction = dir;
                light.position = centre - dir * (10 * diagonal + 1);
            } else {
                ctx_.warning(path + ": unknown light type '" + gl.type + "'; light ignored");
                continue;
            }
            scene_.lights.push_back(light);
        }
    }

    static constexpr int kNotLoaded = -2;
    /// POSITION, NORMAL, TEXCOORD_0, TEXCOORD_1, TANGENT, COLOR_0 and index accessors and the
    /// mode of a primitive.
    using PrimitiveKey = std::array<int, 9>;  ///< attributes, indices, mode, tangent set

    const ImportContext &ctx_;
    const tinygltf::Model &model_;
    ir::Scene &scene_;
    const BuildOptions &options_;
    std::optional<MaterialMapper> materials_;
    std::vector<char> visited_;
    std::vector<std::vector<int>> meshIds_;  ///< IR mesh per (mesh, primitive); -1 = none
    std::map<PrimitiveKey, int> sharedMeshes_;
    std::set<int> repeatedReported_;  ///< glTF meshes whose repeated primitives were reported
    /// IR mesh per (mesh, primitive, morph weights, skin) for posed meshes
    std::map<std::tuple<size_t, size_t, std::vector<double>, int>, int> posedMeshes_;
    Poser poser_{ctx_};
    std::vector<PendingLight> pendingLights_;
    size_t droppedTriangles_ = 0, primitivesWithDropped_ = 0;
    int extraCameras_ = 0, ignoredCameras_ = 0;
};

}  // namespace

ir::NodePtr buildScene(const ImportContext &ctx, ir::Scene &scene, int sceneIndex,
                       const BuildOptions &options) {
    SceneBuilder builder(ctx, scene, options);
    return builder.build(sceneIndex);
}

}  // namespace rt::gltf::detail
