// SPDX-License-Identifier: MIT
// ir::Scene: the one scene description every importer produces and every consumer reads.
//
// The IR is plain data with no render logic. Importers (.scad evaluator, glTF) build it;
// ir::completeScene fills in the automatic camera and default lights; render::compile turns it
// into an immutable RenderScene; the POV-Ray writer prints it as SDL; ir::dump prints it as
// canonical text for golden tests. World space is right-handed with +Z up (OpenSCAD's).
// Every node, material, light and camera carries the SourceLoc it came from.
#pragma once

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/ir/camera.h"
#include "core/ir/environment.h"
#include "core/ir/facet_mode.h"
#include "core/ir/light.h"
#include "core/ir/material.h"
#include "core/ir/mesh.h"
#include "core/ir/node.h"
#include "core/math/bounds3.h"

namespace rt::ir {

/// Global render settings (POV-Ray global_settings and background).
struct Settings {
    Rgb background{0};
    /// What rays leaving the scene see; None: the background colour.
    Environment environment;
    Rgb ambientLight{1};
    int maxTraceLevel = 5;
    double adcBailout = 1.0 / 255.0;
};

/// What the importer read but left out of the scene, reported by the render plan.
struct ImportStats {
    int backgroundParts = 0;  ///< `%` subtrees (OpenSCAD excludes them from renders)
    int disabledParts = 0;    ///< `*` subtrees
    int skippedModules = 0;   ///< unsupported modules skipped with a warning
    /// How round primitives were drawn (`--facets`); unset when the pass did not run.
    std::optional<FacetStats> facets;
};

struct Scene {
    NodePtr root = Node::makeGroup(NodeKind::Group, {});
    std::vector<Material> materials;
    std::vector<MeshPtr> meshes;       ///< referenced by MeshPrim::mesh
    std::vector<TexturePtr> textures;  ///< referenced by Material texture slots (TextureRef)
    std::vector<Light> lights;
    std::optional<Camera> camera;
    Settings settings;
    ImportStats stats;
    /// Font files a .scad registered with use<x.ttf> (for text()), in order of registration.
    std::vector<std::string> fontFiles;

    /// Returns the index of a material with the same appearance, adding it if new.
    /// Constant time on average: materials are indexed by a hash of their appearance.
    int addMaterial(const Material &m);

  private:
    /// Hash of appearance -> index into materials; rebuilt if materials was edited directly.
    std::unordered_multimap<size_t, int> materialIndex_;
};

/// World-space bounds of a subtree placed by `parentFromNode` (CSG-aware: an intersection is
/// bounded by the overlap of its children, a difference by its first child).
Bounds3 worldBounds(const Node &node, const Mat4 &parentFromNode = Mat4(),
                    const Scene *scene = nullptr);

/// Object-space bounds of a primitive (meshes are looked up in `scene`).
Bounds3 primitiveBounds(const PrimShape &shape, const Scene *scene = nullptr);

}  // namespace rt::ir
