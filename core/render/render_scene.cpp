// SPDX-License-Identifier: MIT
// Compilation of the IR node tree into world-space solids, and closest-hit queries.
#include "core/render/render_scene.h"

#include <algorithm>
#include <numeric>
#include <unordered_map>

#include "core/csg/csg_shape.h"
#include "core/geometry/triangle_mesh.h"

namespace rt {

namespace {

class Compiler {
  public:
    Compiler(const ir::Scene &scene, DiagnosticSink &diag, CompileStats &stats)
        : scene_(scene), diag_(diag), stats_(stats) {
        // Rank materials by value for the CSG tie-break
        std::vector<int> order(scene.materials.size());
        std::iota(order.begin(), order.end(), 0);
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
            // By value, so coincident faces pick a material by what it is, not by the order
            // in which the file mentions it
            return scene.materials[a].appearanceKey() < scene.materials[b].appearanceKey();
        });
        ranks_.resize(order.size());
        for (size_t i = 0; i < order.size(); ++i) ranks_[order[i]] = static_cast<int>(i);
    }

    /// Top level: each solid below the root's groups and transforms becomes its own object.
    void flatten(const ir::Node &node, const Mat4 &m, std::vector<std::unique_ptr<Shape>> &out) {
        switch (node.kind) {
            case ir::NodeKind::Group:
                for (const auto &c : node.children) flatten(*c, m, out);
                return;
            case ir::NodeKind::Transform: {
                Mat4 composed = m * node.matrix;
                if (!checkTransform(node, composed)) return;
                for (const auto &c : node.children) flatten(*c, composed, out);
                return;
            }
            case ir::NodeKind::Primitive: {
                if (auto leaf = makeLeaf(node, m)) out.push_back(std::move(leaf));
                return;
            }
            case ir::NodeKind::Union:
            case ir::NodeKind::Intersection:
            case ir::NodeKind::Difference: {
                auto csg = std::make_unique<CsgShape>();
                int root = build(*csg, node, m);
                if (root < 0) {
                    ++stats_.emptyDropped;
                    return;
                }
                if (csg->primitiveCount() == 1) {
                    // A CSG node that reduced to one primitive needs no span merging
                    out.push_back(csg->releaseOnlyLeaf());
                    return;
                }
                requireClosedMeshes(*csg);
                finishObject(*csg, csg->leaves());
                ++stats_.csgObjects;
                out.push_back(std::move(csg));
                return;
            }
        }
    }

  private:
    bool checkTransform(const ir::Node &node, const Mat4 &m) {
        if (Transform::fromMatrix(m)) return true;
        diag_.warning(node.loc, m.isFinite()
                                    ? "transform is singular (a zero scale?); the object has no "
                                      "volume and is not rendered"
                                    : "transform has non-finite entries; the object is not rendered");
        ++stats_.emptyDropped;
        return false;
    }

    std::unique_ptr<LeafShape> makeLeaf(const ir::Node &node, const Mat4 &m) {
        auto t = Transform::fromMatrix(m);
        if (!t) {
            checkTransform(node, m);
            return nullptr;
        }
        int mat = node.material;
        if (mat < 0 || mat >= static_cast<int>(scene_.materials.size()))
            throw SceneError(node.loc, "primitive has no valid material (internal error)");
        std::unique_ptr<LeafShape> leaf;
        if (const auto *mp = std::get_if<ir::MeshPrim>(&node.shape))
            leaf = std::make_unique<MeshInstance>(triangleMesh(node, mp->mesh), *t, mat);
        else
            leaf = std::make_unique<PrimitiveInstance>(Primitive::create(node.shape), *t, mat);
        leaf->tieRank = ranks_[mat];
        leaf->interiorMaterial = mat;
        leaf->opaque = !scene_.materials[mat].isTransparent();
        leaf->loc = node.loc;
        ++stats_.primitives;
        return leaf;
    }

    /// The render geometry of an IR mesh, built once and shared by every instance.
    std::shared_ptr<const TriangleMesh> triangleMesh(const ir::Node &node, int index) {
        if (index < 0 || index >= static_cast<int>(scene_.meshes.size()) || !scene_.meshes[index])
            throw SceneError(node.loc, "mesh reference is not in the scene (internal error)");
        auto &cached = meshes_[index];
        if (!cached) {
            cached = std::make_shared<const TriangleMesh>(scene_.meshes[index]);
            stats_.triangles += cached->triangleCount();
        }
        return cached;
    }

    /// Meshes combined with other solids must bound a volume.
    static void requireClosedMeshes(const CsgShape &csg) {
        for (const auto &leaf : csg.leaves()) {
            const auto *mesh = dynamic_cast<const MeshInstance *>(leaf.get());
            if (!mesh || mesh->geometry().closed()) continue;
            const auto &top = mesh->geometry().topology();
            throw SceneError(leaf->loc,
                             "mesh '" + mesh->geometry().mesh().name + "' is open (" +
                                 std::to_string(top.boundaryEdges) + " boundary edges, " +
                                 std::to_string(top.nonManifoldEdges) +
                                 " non-manifold edges): only closed meshes bound a solid that "
                                 "CSG can combine");
        }
    }

    /// Adds the subtree to the CSG shape; returns its node index, or -1 when it has no volume.
    int build(CsgShape &csg, const ir::Node &node, const Mat4 &m) {
        switch (node.kind) {
            case ir::NodeKind::Primitive: {
                auto leaf = makeLeaf(node, m);
                return leaf ? csg.addLeaf(std::move(leaf)) : -1;
            }
            case ir::NodeKind::Transform: {
                Mat4 composed = m * node.matrix;
                if (!checkTransform(node, composed)) return -1;
                return unionOf(csg, node, composed);
            }
            case ir::NodeKind::Group:
            case ir::NodeKind::Union: return unionOf(csg, node, m);
            case ir::NodeKind::Intersection: {
                std::vector<int> kids;
                for (const auto &c : node.children) {
                    int k = build(csg, *c, m);
                    if (k < 0) {
                        // Pruning rule: an empty operand empties the intersection
                        ++stats_.emptyDropped;
                        return -1;
                    }
                    kids.push_back(k);
                }
                if (kids.empty()) return -1;
                return kids.size() == 1 ? kids[0]
                                        : csg.addOp(CsgShape::Op::Intersection, std::move(kids));
            }
            case ir::NodeKind::Difference: {
                if (node.children.empty()) return -1;
                int minuend = build(csg, *node.children.front(), m);
                if (minuend < 0) return -1;  // pruning rule: nothing to subtract from
                std::vector<int> kids{minuend};
                for (size_t i = 1; i < node.children.size(); ++i) {
                    int k = build(csg, *node.children[i], m);
                    if (k >= 0) kids.push_back(k);
                }
                return kids.size() == 1 ? minuend
                                        : csg.addOp(CsgShape::Op::Difference, std::move(kids));
            }
        }
        return -1;
    }

    int unionOf(CsgShape &csg, const ir::Node &node, const Mat4 &m) {
        std::vector<int> kids;
        for (const auto &c : node.children) {
            int k = build(csg, *c, m);
            if (k >= 0) kids.push_back(k);
        }
        if (kids.empty()) return -1;
        return kids.size() == 1 ? kids[0] : csg.addOp(CsgShape::Op::Union, std::move(kids));
    }

    void finishObject(Shape &object,
                      const std::vector<std::unique_ptr<LeafShape>> &leaves) {
        // The interior (ior, fade) of a CSG solid is that of its first primitive, which is the
        // minuend's for a difference; the solid blocks shadows only if every surface is opaque.
        object.interiorMaterial = leaves.front()->material();
        object.opaque = std::all_of(leaves.begin(), leaves.end(),
                                    [](const auto &l) { return l->opaque; });
    }

    const ir::Scene &scene_;
    DiagnosticSink &diag_;
    CompileStats &stats_;
    std::vector<int> ranks_;
    std::unordered_map<int, std::shared_ptr<const TriangleMesh>> meshes_;
};

}  // namespace

std::unique_ptr<RenderScene> RenderScene::compile(const ir::Scene &scene, DiagnosticSink &diag) {
    if (!scene.camera) throw SceneError({}, "scene has no camera (completeScene not applied)");
    std::unique_ptr<RenderScene> rs(new RenderScene());
    rs->materials_ = scene.materials;
    rs->textures_ = scene.textures;
    rs->lights_ = scene.lights;
    rs->camera_ = *scene.camera;
    rs->settings_ = scene.settings;
    Compiler compiler(scene, diag, rs->stats_);
    compiler.flatten(*scene.root, Mat4(), rs->objects_);

    std::vector<Bounds3> bounds;
    bounds.reserve(rs->objects_.size());
    for (const auto &o : rs->objects_) bounds.push_back(o->worldBounds());
    rs->bvh_ = Bvh(bounds);
    rs->stats_.objects = rs->objects_.size();
    rs->stats_.bvhDepth = rs->bvh_.depth();
    return rs;
}

bool RenderScene::intersect(const Ray &ray, double tMin, double tMax, SurfaceInteraction *si,
                            SpanScratch &scratch) const {
    Crossing best;
    const Shape *bestObject = nullptr;
    bool tie = false;
    double closest = tMax;
    double cancelled = kInfinity;  // nearest coincident faces that cancelled in any object
    // Objects whose first crossing lies just beyond the closest one are still visited, so a
    // coincident face of another object is noticed as a tie
    bvh_.traverse(ray, tMin, &closest, [&](uint32_t index, double *tFar) {
        Crossing c;
        const Shape *obj = objects_[index].get();
        scratch.cancelledTie = kInfinity;
        bool found = obj->firstCrossing(ray, tMin, *tFar, &c, scratch);
        if (scratch.cancelledTie > tMin) cancelled = std::min(cancelled, scratch.cancelledTie);
        if (!found) return false;
        double eps = tieEpsilon(ray.o, c.t);
        if (!bestObject || c.t < best.t) {
            tie = bestObject && best.t - c.t <= eps;
            best = c;
            bestObject = obj;
            *tFar = std::min(tMax, c.t + eps);
        } else {
            tie = tie || c.t - best.t <= eps;
        }
        return false;
    });
    if (!bestObject || best.t >= tMax) {
        si->tie = cancelled < tMax;  // a miss can still pass coincident faces
        return false;
    }
    *si = best.leaf->surfaceAt(ray, best);
    si->object = bestObject;
    // Coincident faces that cancelled in front of the hit (a face of zero thickness that another
    // renderer may show) make it a tie as well
    tie = tie || cancelled <= best.t + tieEpsilon(ray.o, best.t);
    // A surface right at the origin of a secondary ray is a tie too (POV-Ray skips hits
    // closer than its MIN_ISECT_DEPTH)
    si->tie = tie || best.tie || best.t <= tieEpsilon(ray.o, 0);
    return true;
}

Bounds3 RenderScene::bounds() const {
    return bvh_.empty() ? Bounds3() : bvh_.nodes().front().bounds;
}

}  // namespace rt
