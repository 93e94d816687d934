// SPDX-License-Identifier: MIT
// The immutable, compiled form of an ir::Scene: world-space solids in a BVH, materials, lights,
// camera and settings. Built only by RenderScene::compile; any thread may read it.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/bvh/bvh.h"
#include "core/bvh/vista_lists.h"
#include "core/geometry/axis_box.h"
#include "core/geometry/shape.h"
#include "core/ir/diagnostics.h"
#include "core/ir/scene_ir.h"
#include "core/materials/pbr_material.h"

namespace rt {

/// What the compiler may leave out (the render plan). Every saving keeps the picture: tests
/// render with the plan on and off and compare.
struct CompileOptions {
    /// Off: unions are always span-merged, objects behind the camera are kept and CSG subtrees
    /// are never pruned, as a naive renderer would; for measuring and testing the plan.
    bool plan = true;
    /// Threads that build the BVHs of triangle meshes (0: every core); `render -t` sets it, so
    /// a render asked to use one core does not build on all of them. The trees do not depend on it.
    int threads = 0;
    /// In scenes of at least this many objects, camera rays look up the leaves their direction
    /// can meet instead of walking the scene's tree from the root (VistaLists); the same
    /// picture either way. A tree of a few objects is walked in a few steps, which the lookup
    /// does not beat (5 objects: 1 to 3 % slower; 49 to 227: 1 to 3 % faster; 2,000: 5 %).
    /// SIZE_MAX: never (tests and measurements).
    size_t vistaFromObjects = 16;
    /// Where the machine has AVX2, the scene tree's node tests take the three axes side by side
    /// in one register (Bvh::LaneSlabs); the same visits, so the same picture, either way.
    /// Off: one plane at a time (tests and measurements).
    bool laneSlabs = true;
};

struct CompileStats {
    size_t objects = 0;       ///< top-level solids
    size_t primitives = 0;    ///< primitives and mesh instances in them
    size_t triangles = 0;     ///< triangles of the distinct meshes
    size_t csgObjects = 0;    ///< solids that need span merging
    size_t emptyDropped = 0;  ///< subtrees with no volume (empty operands, singular transforms)
    size_t unionsSplit = 0;   ///< unions of disjoint parts rendered as separate solids
    size_t behindCamera = 0;  ///< objects no ray can reach: behind the camera, nothing reflects
    size_t behindCameraPrimitives = 0;
    /// Why objects behind the camera had to be kept (empty when none were, or none are behind)
    std::string behindCameraKept;
    int bvhDepth = 0;
};

class RenderScene {
  public:
    /// Builds render objects from a complete scene (ir::completeScene already applied: it must
    /// have a camera). Singular transforms and empty operands are dropped with a located warning.
    static std::unique_ptr<RenderScene> compile(const ir::Scene &scene, DiagnosticSink &diag,
                                                const CompileOptions &options = {});

    /// Closest surface crossing with tMin < t < tMax. On a miss only si->tie is set: whether the
    /// ray passed coincident faces that cancelled (a zero-thickness face).
    /// `vista`: the camera's leaf lists (vista()) for a camera ray, which give the same answer
    /// as the whole tree with fewer box tests; null for other rays.
    bool intersect(const Ray &ray, double tMin, double tMax, SurfaceInteraction *si,
                   SpanScratch &scratch, const VistaLists *vista = nullptr) const;

    /// The closest crossing of intersect() without its surface (point, normals, texture
    /// coordinates): all a shadow ray needs when the blocker is opaque. `tie` is set as
    /// intersect() sets si->tie, on a hit and on a miss.
    struct Hit {
        Crossing crossing;
        const Shape *object = nullptr;
        uint32_t objectIndex = 0;  ///< object's position in objects()
        bool tie = false;
    };
    bool closestHit(const Ray &ray, double tMin, double tMax, Hit *hit, SpanScratch &scratch,
                    const VistaLists *vista = nullptr) const {
#if SCADRAY_LANE_SLABS
        if (lanes_) return closestHitLanes(ray, tMin, tMax, hit, scratch, vista);
#endif
        return closestHitPlanes(ray, tMin, tMax, hit, scratch, vista);
    }
    /// Leaf lists for the rays that leave a perspective camera (null for an orthographic one
    /// and for scenes of fewer than CompileOptions::vistaFromObjects objects).
    const VistaLists *vista() const { return vista_.get(); }
    /// Whether closestHit() tests nodes in AVX lanes (CompileOptions::laneSlabs on a machine
    /// with AVX2).
    bool laneSlabs() const { return lanes_; }
    /// The surface at a hit closestHit() found along the same ray.
    SurfaceInteraction surfaceAt(const Ray &ray, const Hit &hit) const;

    const ir::Material &material(int index) const { return materials_[index]; }
    const std::vector<ir::Material> &materials() const { return materials_; }
    const ir::Texture *texture(int index) const {
        return index >= 0 && index < static_cast<int>(textures_.size()) ? textures_[index].get()
                                                                        : nullptr;
    }
    /// The images material `index` reads per texel, resolved once at compile time (all null
    /// for a material without a per-texel description).
    const TexelImages &texelImages(int index) const { return texelImages_[index]; }
    const std::vector<ir::Light> &lights() const { return lights_; }
    const ir::Camera &camera() const { return camera_; }
    const ir::Settings &settings() const { return settings_; }
    const std::vector<std::unique_ptr<Shape>> &objects() const { return objects_; }
    const Bvh &bvh() const { return bvh_; }
    const CompileStats &stats() const { return stats_; }
    const CompileOptions &options() const { return options_; }
    /// Whether some rendered primitive uses the material.
    bool materialUsed(int index) const { return materialUsed_[index]; }
    /// World bounds of everything renderable.
    Bounds3 bounds() const;

  private:
    RenderScene() = default;
    /// closestHit() with the node test of `Slabs` (Bvh::RaySlabs or Bvh::LaneSlabs).
    template <typename Slabs>
    bool closestHitWith(const Ray &ray, double tMin, double tMax, Hit *hit, SpanScratch &scratch,
                        const VistaLists *vista) const;
    /// closestHitWith<Bvh::RaySlabs>, and closestHitWith<Bvh::LaneSlabs> compiled for AVX2.
    bool closestHitPlanes(const Ray &ray, double tMin, double tMax, Hit *hit, SpanScratch &scratch,
                          const VistaLists *vista) const;
    bool closestHitLanes(const Ray &ray, double tMin, double tMax, Hit *hit, SpanScratch &scratch,
                         const VistaLists *vista) const;
    bool lanes_ = false;

    /// By object: the objects that are boxes placed by the identity or a translation (the
    /// floor tiles and `translate()`d cubes of most scenes), whose crossings and surfaces
    /// closestHit() and surfaceAt() find inline (AxisBox); the others are empty.
    std::vector<AxisBox> axisBoxes_;

    std::vector<std::unique_ptr<Shape>> objects_;
    Bvh bvh_;
    std::unique_ptr<VistaLists> vista_;  ///< after bvh_: it refers to it
    std::vector<ir::Material> materials_;
    std::vector<ir::TexturePtr> textures_;
    std::vector<TexelImages> texelImages_;  ///< by material
    std::vector<ir::Light> lights_;
    ir::Camera camera_;
    ir::Settings settings_;
    CompileStats stats_;
    CompileOptions options_;
    std::vector<bool> materialUsed_;
};

}  // namespace rt
