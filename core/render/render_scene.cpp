// SPDX-License-Identifier: MIT
// Compilation of the IR node tree into world-space solids, and closest-hit queries.
#include "core/render/render_scene.h"

#include <algorithm>
#include <numeric>
#include <type_traits>
#include <unordered_map>

#include "core/csg/csg_shape.h"
#include "core/geometry/triangle_mesh.h"

namespace rt {

namespace {

/// Calls f for every primitive or mesh instance of a solid; the leaves are const where the
/// solid is (S is Shape or const Shape).
template <typename S, typename F>
void forEachLeaf(S &object, F &&f) {
    using Leaf = std::conditional_t<std::is_const_v<S>, const LeafShape, LeafShape>;
    if (const auto *csg = dynamic_cast<const CsgShape *>(&object))
        for (const auto &l : csg->leaves()) f(static_cast<Leaf &>(*l));
    else
        f(static_cast<Leaf &>(object));
}

class Compiler {
  public:
    Compiler(const ir::Scene &scene, DiagnosticSink &diag, const CompileOptions &options,
             CompileStats &stats)
        : scene_(scene), diag_(diag), options_(options), stats_(stats) {
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
                if (options_.plan) {
                    splitUnion(node, m, out);
                    return;
                }
                [[fallthrough]];
            case ir::NodeKind::Intersection:
            case ir::NodeKind::Difference: {
                auto csg = std::make_unique<CsgShape>();
                csg->setPruning(options_.plan);
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
                out.push_back(std::move(csg));
                return;
            }
        }
    }

  private:
    /// A union whose parts are disjoint needs no span merging: its surface is the surfaces of
    /// its parts, so each part becomes a solid of its own in the BVH. Otherwise (parts that
    /// overlap or touch, or differ in interior) the parts are merged into one CSG solid.
    void splitUnion(const ir::Node &node, const Mat4 &m, std::vector<std::unique_ptr<Shape>> &out) {
        std::vector<std::unique_ptr<Shape>> parts;
        for (const auto &c : node.children) flatten(*c, m, parts);
        if (parts.empty()) {
            ++stats_.emptyDropped;
            return;
        }
        if (parts.size() == 1 || separable(parts)) {
            if (parts.size() > 1) ++stats_.unionsSplit;
            for (auto &p : parts) out.push_back(std::move(p));
            return;
        }
        auto csg = std::make_unique<CsgShape>();
        std::vector<int> roots;
        for (auto &p : parts) {
            if (auto *c = dynamic_cast<CsgShape *>(p.get()))
                roots.push_back(csg->absorb(std::move(*c)));
            else
                roots.push_back(csg->addLeaf(
                    std::unique_ptr<LeafShape>(static_cast<LeafShape *>(p.release()))));
        }
        csg->addOp(CsgShape::Op::Union, std::move(roots));
        requireClosedMeshes(*csg);
        finishObject(*csg, csg->leaves());
        out.push_back(std::move(csg));
    }

    /// Parts whose bounds are apart by more than the tie tolerance (touching solids fuse, so
    /// they are not separable) and whose primitives share one interior (a CSG solid has the
    /// interior of its first primitive).
    bool separable(const std::vector<std::unique_ptr<Shape>> &parts) const {
        const ir::Interior *interior = nullptr;
        bool same = true;
        auto checkLeaf = [&](const LeafShape &l) {
            const ir::Interior &in = scene_.materials[l.material()].interior;
            if (!interior) interior = &in;
            same = same && in == *interior;
        };
        std::vector<Bounds3> boxes;
        Bounds3 centres;
        for (const auto &p : parts) {
            forEachLeaf(*p, checkLeaf);
            Bounds3 b = p->worldBounds();
            // Far above the tie tolerance, 1e-11 of the coordinates
            double pad = 1e-9 * maxComponent(max(abs(b.min), abs(b.max)));
            b.min -= Vec3(pad);
            b.max += Vec3(pad);
            boxes.push_back(b);
            centres = unionBounds(centres, b.centroid());
        }
        if (!same) return false;
        // Sweep along the axis where the parts spread most: each box is compared with those
        // starting before it ends
        int axis = maxDimension(centres.diagonal());
        std::vector<size_t> order(boxes.size());
        std::iota(order.begin(), order.end(), size_t(0));
        std::sort(order.begin(), order.end(),
                  [&](size_t a, size_t b) { return boxes[a].min[axis] < boxes[b].min[axis]; });
        for (size_t i = 0; i < order.size(); ++i) {
            const Bounds3 &a = boxes[order[i]];
            for (size_t j = i + 1; j < order.size() && boxes[order[j]].min[axis] <= a.max[axis];
                 ++j)
                if (!intersectBounds(a, boxes[order[j]]).isEmpty()) return false;
        }
        return true;
    }

    bool checkTransform(const ir::Node &node, const Mat4 &m) {
        if (Transform::fromMatrix(m)) return true;
        diag_.warning(node.loc,
                      m.isFinite()
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
        const auto *prism = std::get_if<ir::PrismPrim>(&node.shape);
        if (const auto *mp = std::get_if<ir::MeshPrim>(&node.shape))
            leaf = std::make_unique<MeshInstance>(triangleMesh(node, mp->mesh), *t, mat);
        else if (prism && prism->mesh >= 0)
            leaf = std::make_unique<MeshInstance>(triangleMesh(node, prism->mesh), *t, mat);
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
            cached = std::make_shared<const TriangleMesh>(scene_.meshes[index], options_.threads);
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
            case ir::NodeKind::Union:
                return unionOf(csg, node, m);
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

    void finishObject(Shape &object, const std::vector<std::unique_ptr<LeafShape>> &leaves) {
        // The interior (ior, fade) of a CSG solid is that of its first primitive, which is the
        // minuend's for a difference; the solid blocks shadows only if every surface is opaque.
        object.interiorMaterial = leaves.front()->material();
        object.opaque =
            std::all_of(leaves.begin(), leaves.end(), [](const auto &l) { return l->opaque; });
    }

    const ir::Scene &scene_;
    DiagnosticSink &diag_;
    const CompileOptions &options_;
    CompileStats &stats_;
    std::vector<int> ranks_;
    std::unordered_map<int, std::shared_ptr<const TriangleMesh>> meshes_;
};

}  // namespace

namespace {

/// Leaves out solids entirely behind the plane of the camera when no ray can reach them there:
/// camera rays only go forward, nothing reflects or refracts, and every shadow ray runs from a
/// visible point to a light in front of the camera (the half-space is convex, so the whole
/// segment stays in it). Returns why nothing could be dropped, or "".
std::string dropBehindCamera(const ir::Scene &scene, std::vector<std::unique_ptr<Shape>> &objects,
                             CompileStats &stats) {
    const ir::Camera &cam = *scene.camera;
    Vec3 forward = normalize(cam.lookAt - cam.location);
    auto depth = [&](const Vec3 &p) { return dot(p - cam.location, forward); };
    auto behind = [&](const Bounds3 &b) {
        double scale = length(b.max - b.min) + length(abs(b.max)) + length(abs(b.min)) +
                       length(abs(cam.location));
        for (int i = 0; i < 8; ++i)
            if (!(depth(b.corner(i)) < -1e-9 * scale)) return false;
        return true;
    };
    std::vector<size_t> candidates;
    for (size_t i = 0; i < objects.size(); ++i)
        if (behind(objects[i]->worldBounds())) candidates.push_back(i);
    if (candidates.empty()) return "";

    std::string reason;
    for (const auto &o : objects)
        forEachLeaf(*o, [&](const LeafShape &l) {
            const ir::Material &m = scene.materials[l.material()];
            if (reason.empty() && m.finish.hasReflection()) reason = "a material reflects";
            if (reason.empty() && m.isTransparent()) reason = "a material is transparent";
        });
    for (const ir::Light &l : scene.lights) {
        if (!reason.empty()) break;
        if (l.shadowless) continue;
        if (l.kind == ir::Light::Kind::Directional) {
            if (dot(-normalize(l.direction), forward) < 0)
                reason = "a parallel light shines from the front, so shadow rays run backwards";
            continue;
        }
        bool front = depth(l.position) > 0;
        if (l.area)
            for (int i = 0; i < 4; ++i)
                front = front && depth(l.position + l.areaLight.axis1 * ((i & 1) ? 0.5 : -0.5) +
                                       l.areaLight.axis2 * ((i & 2) ? 0.5 : -0.5)) > 0;
        if (!front) reason = "a light is behind the camera";
    }
    if (!reason.empty()) return reason;
    for (auto it = candidates.rbegin(); it != candidates.rend(); ++it) {
        ++stats.behindCamera;
        stats.behindCameraPrimitives += objects[*it]->primitiveCount();
        stats.primitives -= objects[*it]->primitiveCount();
        objects.erase(objects.begin() + static_cast<long>(*it));
    }
    return "";
}

}  // namespace

std::unique_ptr<RenderScene> RenderScene::compile(const ir::Scene &scene, DiagnosticSink &diag,
                                                  const CompileOptions &options) {
    if (!scene.camera) throw SceneError({}, "scene has no camera (completeScene not applied)");
    std::unique_ptr<RenderScene> rs(new RenderScene());
    rs->options_ = options;
    rs->materials_ = scene.materials;
    rs->textures_ = scene.textures;
    // Per-texel materials find their images here once, not at every hit
    rs->texelImages_.resize(rs->materials_.size());
    for (size_t i = 0; i < rs->materials_.size(); ++i) {
        const ir::Material &m = rs->materials_[i];
        if (!m.texel.pbr) continue;
        const PbrMaterial &p = *m.texel.pbr;
        TexelImages &images = rs->texelImages_[i];
        images.baseColor = rs->texture(m.baseColorTexture.texture);
        images.metallicRoughness = rs->texture(p.metallicRoughnessTexture.texture);
        images.normal = rs->texture(p.normalTexture.texture);
        images.occlusion = rs->texture(p.occlusionTexture.texture);
        images.emissive = rs->texture(p.emissiveTexture.texture);
        images.transmission = rs->texture(p.transmissionTexture.texture);
        images.clearcoat = rs->texture(p.clearcoatTexture.texture);
        images.clearcoatRoughness = rs->texture(p.clearcoatRoughnessTexture.texture);
        images.sheenColor = rs->texture(p.sheenColorTexture.texture);
        images.sheenRoughness = rs->texture(p.sheenRoughnessTexture.texture);
        images.specular = rs->texture(p.specularTexture.texture);
        images.specularColor = rs->texture(p.specularColorTexture.texture);
        images.thickness = rs->texture(p.thicknessTexture.texture);
    }
    rs->lights_ = scene.lights;
    rs->camera_ = *scene.camera;
    rs->settings_ = scene.settings;
    Compiler compiler(scene, diag, options, rs->stats_);
    compiler.flatten(*scene.root, Mat4(), rs->objects_);
    if (options.plan)
        rs->stats_.behindCameraKept = dropBehindCamera(scene, rs->objects_, rs->stats_);

    rs->materialUsed_.assign(scene.materials.size(), false);
    std::vector<Bounds3> bounds;
    bounds.reserve(rs->objects_.size());
    uint32_t leaves = 0;
    for (const auto &o : rs->objects_) {
        bounds.push_back(o->worldBounds());
        if (dynamic_cast<const CsgShape *>(o.get())) ++rs->stats_.csgObjects;
        forEachLeaf(*o, [&](LeafShape &l) {
            rs->materialUsed_[l.material()] = true;
            l.sceneIndex = ++leaves;
        });
    }
    rs->bvh_ = Bvh(bounds);
    rs->axisBoxes_.reserve(rs->objects_.size());
    for (const auto &o : rs->objects_) rs->axisBoxes_.push_back(AxisBox::of(*o));
#if SCADRAY_LANE_SLABS
    rs->lanes_ = options.laneSlabs && __builtin_cpu_supports("avx2");
#endif
    // Camera rays look up the leaves their direction can meet (POV-Ray's vista buffer)
    if (rs->camera_.projection == ir::Projection::Perspective &&
        rs->objects_.size() >= options.vistaFromObjects)
        rs->vista_ = std::make_unique<VistaLists>(rs->bvh_, rs->camera_.location);
    rs->stats_.objects = rs->objects_.size();
    rs->stats_.bvhDepth = rs->bvh_.depth();
    return rs;
}

bool RenderScene::intersect(const Ray &ray, double tMin, double tMax, SurfaceInteraction *si,
                            SpanScratch &scratch, const VistaLists *vista) const {
    Hit hit;
    bool found = closestHit(ray, tMin, tMax, &hit, scratch, vista);
    if (!found) {
        si->tie = hit.tie;
        return false;
    }
    *si = surfaceAt(ray, hit);
    return true;
}

SurfaceInteraction RenderScene::surfaceAt(const Ray &ray, const Hit &hit) const {
    const AxisBox &box = axisBoxes_[hit.objectIndex];
    SurfaceInteraction si = box.leaf() && box.leaf() == hit.crossing.leaf
                                ? box.surfaceAt(ray, hit.crossing)
                                : hit.crossing.leaf->surfaceAt(ray, hit.crossing);
    si.object = hit.object;
    si.tie = hit.tie;
    return si;
}

// Both bodies are flattened: the walk, the node test and the visitor inlined into one loop
// (GCC 12 left the visitor out of line when two walks call it, 6 % slower), and the lanes'
// AVX2 node test can only be inlined into a function compiled for AVX2.
__attribute__((flatten)) bool RenderScene::closestHitPlanes(const Ray &ray, double tMin,
                                                            double tMax, Hit *hit,
                                                            SpanScratch &scratch,
                                                            const VistaLists *vista) const {
    return closestHitWith<Bvh::RaySlabs>(ray, tMin, tMax, hit, scratch, vista);
}

#if SCADRAY_LANE_SLABS
SCADRAY_LANES_TARGET __attribute__((flatten)) bool RenderScene::closestHitLanes(
    const Ray &ray, double tMin, double tMax, Hit *hit, SpanScratch &scratch,
    const VistaLists *vista) const {
    return closestHitWith<Bvh::LaneSlabs>(ray, tMin, tMax, hit, scratch, vista);
}
#endif

template <typename Slabs>
bool RenderScene::closestHitWith(const Ray &ray, double tMin, double tMax, Hit *hit,
                                 SpanScratch &scratch, const VistaLists *vista) const {
    Crossing best;
    constexpr uint32_t kNone = UINT32_MAX;
    uint32_t bestObject = kNone;  // index of the object of `best`
    bool tie = false;
    double closest = tMax;
    double cancelled = kInfinity;  // nearest coincident faces that cancelled in any object
    // Objects whose first crossing lies just beyond the closest one are still visited, so a
    // coincident face of another object is noticed as a tie
    // Inlined into both walks below (GCC 12 would otherwise call it: 6 % slower)
    const VistaLists::Cell *cell = vista ? vista->find(ray, tMin, tMax) : nullptr;
    const Vec3 invDir(1 / ray.d.x, 1 / ray.d.y, 1 / ray.d.z);  // for the walk and the boxes
    auto visit = [&](uint32_t index, double *tFar) __attribute__((always_inline)) {
        Crossing c;
        const AxisBox &box = axisBoxes_[index];
        if (box.leaf()) {
            if (!box.firstCrossing(ray, invDir, tMin, *tFar, &c)) return false;
        } else {
            scratch.cancelledTie = kInfinity;
            bool found = objects_[index]->firstCrossing(ray, tMin, *tFar, &c, scratch);
            if (scratch.cancelledTie > tMin) cancelled = std::min(cancelled, scratch.cancelledTie);
            if (!found) return false;
        }
        double eps = tieEpsilon(ray.o, c.t);
        if (bestObject == kNone || c.t < best.t) {
            tie = bestObject != kNone && best.t - c.t <= eps;
            best = c;
            bestObject = index;
            *tFar = std::min(tMax, c.t + eps);
        } else {
            tie = tie || c.t - best.t <= eps;
        }
        return false;
    };
        // The visitor only lowers `closest`, so the lanes' walks may test two boxes side by side
#if SCADRAY_LANE_SLABS
    constexpr bool paired = std::is_same_v<Slabs, Bvh::LaneSlabs>;
#else
    constexpr bool paired = false;
#endif
    const Slabs slabs(ray, invDir);
    if constexpr (paired) {
#if SCADRAY_LANE_SLABS
        if (cell)
            bvh_.traverseLeavesPairs(cell->leaves, cell->count, slabs, tMin, &closest, visit);
        else
            bvh_.traversePairs(slabs, tMin, &closest, visit);
#endif
    } else if (cell) {
        bvh_.traverseLeavesWith(cell->leaves, cell->count, slabs, tMin, &closest, visit);
    } else {
        bvh_.traverseWith(slabs, tMin, &closest, visit);
    }
    if (bestObject == kNone || best.t >= tMax) {
        hit->tie = cancelled < tMax;  // a miss can still pass coincident faces
        return false;
    }
    hit->crossing = best;
    hit->object = objects_[bestObject].get();
    hit->objectIndex = bestObject;
    // Coincident faces that cancelled in front of the hit (a face of zero thickness that another
    // renderer may show) make it a tie as well
    tie = tie || cancelled <= best.t + tieEpsilon(ray.o, best.t);
    // A surface right at the origin of a secondary ray is a tie too (POV-Ray skips hits
    // closer than its MIN_ISECT_DEPTH)
    hit->tie = tie || best.tie || best.t <= tieEpsilon(ray.o, 0);
    return true;
}

Bounds3 RenderScene::bounds() const {
    return bvh_.empty() ? Bounds3() : bvh_.nodes().front().bounds;
}

}  // namespace rt
