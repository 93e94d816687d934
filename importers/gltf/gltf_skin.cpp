// SPDX-License-Identifier: MIT
// The pose a glTF file stores: morph targets weighted by mesh.weights / node.weights, and skins
// posed by their joints' transforms (glTF 2.0 sections 3.7.2.2 and 3.7.3).
#include <algorithm>
#include <cmath>

#include "importers/gltf/gltf_internal.h"

namespace rt::gltf::detail {

namespace {

Mat4 columnMajor(const float *v) {
    Mat4 m;
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) m.m[row][col] = v[col * 4 + row];
    return m;
}

/// Inverse transpose of m's 3x3 block, as a matrix for transformVector (normals).
Mat4 normalMatrix(const Mat4 &m) {
    std::optional<Mat4> inv = m.affineInverse();
    return inv ? inv->transposed() : m;
}

}  // namespace

std::vector<double> Poser::weights(size_t nodeIndex) const {
    const tinygltf::Node &node = ctx_.model.nodes[nodeIndex];
    const tinygltf::Mesh &mesh = ctx_.model.meshes[static_cast<size_t>(node.mesh)];
    size_t targets = mesh.primitives.empty() ? 0 : mesh.primitives[0].targets.size();
    bool fromNode = !node.weights.empty();
    std::vector<double> w = fromNode ? node.weights : mesh.weights;
    std::string what = fromNode ? jsonPath("nodes", nodeIndex) + ".weights"
                                : jsonPath("meshes", static_cast<size_t>(node.mesh)) + ".weights";
    for (double x : w)
        if (!std::isfinite(x)) ctx_.fail(what + ": weights must be finite numbers");
    if (w.size() != targets && !(w.empty() && targets > 0)) {
        ctx_.warning(what + ": " + std::to_string(w.size()) + " weights for " +
                     std::to_string(targets) + " morph targets; " +
                     (w.size() > targets ? "the extra ones ignored" : "the missing ones are 0"));
        w.resize(targets, 0.0);
    }
    return w;
}

void Poser::morph(const tinygltf::Primitive &prim, const std::string &path,
                  const std::vector<double> &weights, ir::Mesh &mesh) const {
    if (prim.targets.size() > kMaxMorphTargets)
        ctx_.fail(path + ".targets: " + std::to_string(prim.targets.size()) +
                  " morph targets, more than " + std::to_string(kMaxMorphTargets));
    size_t nv = mesh.positions.size();
    for (size_t t = 0; t < prim.targets.size() && t < weights.size(); ++t) {
        double w = weights[t];
        if (w == 0) continue;
        for (const auto &[name, accessor] : prim.targets[t]) {
            bool isPosition = name == "POSITION", isNormal = name == "NORMAL",
                 isTangent = name == "TANGENT";
            if (!isPosition && !isNormal && !isTangent) continue;  // TEXCOORD_n, COLOR_n: not used
            if ((isNormal && mesh.normals.empty()) || (isTangent && mesh.tangents.empty()))
                continue;  // a delta for an attribute the primitive does not have
            std::string what = path + ".targets[" + std::to_string(t) + "]." + name;
            checkAttributeType(ctx_, accessor, name, true, what);
            FloatArray d = readFloats(ctx_, accessor, TINYGLTF_TYPE_VEC3, what);
            if (d.count != nv)
                ctx_.fail(what + " (" + jsonPath("accessors", static_cast<size_t>(accessor)) +
                          "): " + std::to_string(d.count) + " deltas for " + std::to_string(nv) +
                          " vertices");
            for (size_t i = 0; i < nv; ++i) {
                Vec3 delta(d.values[3 * i], d.values[3 * i + 1], d.values[3 * i + 2]);
                delta = delta * w;
                if (isPosition) {
                    mesh.positions[i] = mesh.positions[i] + delta;
                } else if (isNormal) {
                    mesh.normals[i] = mesh.normals[i] + delta;
                } else {
                    for (int c = 0; c < 3; ++c)
                        mesh.tangents[i][static_cast<size_t>(c)] +=
                            static_cast<float>(c == 0   ? delta.x
                                               : c == 1 ? delta.y
                                                        : delta.z);
                }
            }
        }
    }
}

const Mat4 &Poser::global(size_t index) {
    const tinygltf::Model &model = ctx_.model;
    size_t n = model.nodes.size();
    if (globals_.empty()) {
        globals_.resize(n);
        globalDone_.assign(n, 0);
        parents_.assign(n, -1);
        for (size_t p = 0; p < n; ++p)
            for (int c : model.nodes[p].children) {
                if (c < 0 || static_cast<size_t>(c) >= n) continue;  // reported by the traversal
                if (parents_[static_cast<size_t>(c)] >= 0 || static_cast<size_t>(c) == p)
                    ctx_.fail(jsonPath("nodes", static_cast<size_t>(c)) +
                              ": has more than one parent, or is its own");
                parents_[static_cast<size_t>(c)] = static_cast<int>(p);
            }
    }
    // The chain up to the first node whose global is known (or a root); longer than the
    // number of nodes means a cycle
    std::vector<size_t> chain;
    for (size_t at = index;;) {
        if (globalDone_[at]) break;
        chain.push_back(at);
        if (chain.size() > n) ctx_.fail(jsonPath("nodes", index) + ": its ancestors form a cycle");
        if (parents_[at] < 0) break;
        at = static_cast<size_t>(parents_[at]);
    }
    for (size_t k = chain.size(); k-- > 0;) {
        size_t at = chain[k];
        Mat4 local = localMatrix(ctx_, model.nodes[at], jsonPath("nodes", at));
        globals_[at] =
            parents_[at] >= 0 ? globals_[static_cast<size_t>(parents_[at])] * local : local;
        globalDone_[at] = 1;
    }
    return globals_[index];
}

void Poser::skin(int skinIndex, const AttributeReader &read, const std::string &path,
                 ir::Mesh &mesh) {
    const tinygltf::Model &model = ctx_.model;
    const tinygltf::Skin &skin = model.skins[static_cast<size_t>(skinIndex)];
    std::string skinPath = jsonPath("skins", static_cast<size_t>(skinIndex));

    // Joint matrices: global transform of the joint x its inverse bind matrix
    auto cached = jointMatrices_.find(skinIndex);
    if (cached == jointMatrices_.end()) {
        size_t nj = skin.joints.size();
        std::vector<Mat4> joints(nj);
        FloatArray ibm;
        if (skin.inverseBindMatrices >= 0) {
            std::string what = skinPath + ".inverseBindMatrices";
            ibm = readFloats(ctx_, skin.inverseBindMatrices, TINYGLTF_TYPE_MAT4, what);
            if (ibm.count < nj)
                ctx_.fail(what + ": " + std::to_string(ibm.count) + " matrices for " +
                          std::to_string(nj) + " joints");
        }
        for (size_t j = 0; j < nj; ++j) {
            int node = skin.joints[j];
            std::string what = skinPath + ".joints[" + std::to_string(j) + "]";
            if (node < 0 || static_cast<size_t>(node) >= model.nodes.size())
                ctx_.fail(what + ": node " + std::to_string(node) +
                          " does not exist (the file has " + std::to_string(model.nodes.size()) +
                          ")");
            Mat4 inverseBind = ibm.count ? columnMajor(ibm.values.data() + 16 * j) : Mat4();
            if (!inverseBind.isFinite())
                ctx_.fail(skinPath + ".inverseBindMatrices: matrix " + std::to_string(j) +
                          " is not finite");
            joints[j] = global(static_cast<size_t>(node)) * inverseBind;
        }
        cached = jointMatrices_.emplace(skinIndex, std::move(joints)).first;
    }
    const std::vector<Mat4> &joints = cached->second;

    // Influences: JOINTS_n and WEIGHTS_n, four per set
    size_t nv = mesh.positions.size();
    std::vector<FloatArray> jointSets, weightSets;
    for (int s = 0; s < kMaxSkinSets; ++s) {
        std::string jn = "JOINTS_" + std::to_string(s), wn = "WEIGHTS_" + std::to_string(s);
        std::optional<FloatArray> j = read(jn, TINYGLTF_TYPE_VEC4);
        std::optional<FloatArray> w = read(wn, TINYGLTF_TYPE_VEC4);
        if (!j && !w) break;
        if (!j || !w)
            ctx_.fail(path + ".attributes: has " + (j ? jn : wn) + " without " + (j ? wn : jn));
        for (const auto &[a, name] : {std::pair(&*j, jn), std::pair(&*w, wn)})
            if (a->count != nv)
                ctx_.fail(path + ".attributes." + name + ": " + std::to_string(a->count) +
                          " elements for " + std::to_string(nv) + " vertices");
        jointSets.push_back(std::move(*j));
        weightSets.push_back(std::move(*w));
    }
    if (jointSets.empty()) {
        ctx_.warning(path + ": used with " + skinPath +
                     " but has no JOINTS_0/WEIGHTS_0; shown unskinned");
        return;
    }

    size_t unweighted = 0;
    for (size_t i = 0; i < nv; ++i) {
        Mat4 m;
        for (auto &row : m.m)
            for (double &x : row) x = 0;
        double total = 0;
        for (size_t s = 0; s < jointSets.size(); ++s)
            for (size_t k = 0; k < 4; ++k) {
                double w = weightSets[s].values[4 * i + k];
                if (w == 0) continue;
                double j = jointSets[s].values[4 * i + k];
                if (!(j >= 0 && j < static_cast<double>(joints.size())))
                    ctx_.fail(path + ".attributes.JOINTS_" + std::to_string(s) + ": vertex " +
                              std::to_string(i) + " names joint " + std::to_string(long(j)) +
                              ", but " + skinPath + " has " + std::to_string(joints.size()));
                const Mat4 &jm = joints[static_cast<size_t>(j)];
                for (int r = 0; r < 4; ++r)
                    for (int c = 0; c < 4; ++c) m.m[r][c] += w * jm.m[r][c];
                total += w;
            }
        if (!(total != 0)) {
            ++unweighted;  // no influence: the vertex stays where it is
            continue;
        }
        mesh.positions[i] = m.transformPoint(mesh.positions[i]);
        if (!mesh.normals.empty())
            mesh.normals[i] = normalMatrix(m).transformVector(mesh.normals[i]);
        if (!mesh.tangents.empty()) {
            std::array<float, 4> &t = mesh.tangents[i];
            Vec3 v = m.transformVector(Vec3(t[0], t[1], t[2]));
            t = {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z), t[3]};
        }
    }
    if (unweighted > 0)
        ctx_.warning(path + ": " + std::to_string(unweighted) +
                     " vertices have all skin weights 0; they keep their bind position");
}

}  // namespace rt::gltf::detail
