// SPDX-License-Identifier: MIT
// Range and finiteness checks of the IR.
#include "core/ir/ir_validate.h"

#include <cmath>
#include <utility>
#include <vector>

#include "core/math/transform.h"

namespace rt::ir {

namespace {

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

std::string vec(const Vec3 &v) {
    return "[" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + "]";
}

bool inRange(const Vec3 &p) {
    return p.isFinite() && std::abs(p.x) <= kMaxCoordinate && std::abs(p.y) <= kMaxCoordinate &&
           std::abs(p.z) <= kMaxCoordinate;
}

/// A turn of a solid of revolution: 0 < angle <= 360 degrees.
void checkTurn(const Node &node, double angle) {
    if (!(angle > 0 && angle <= 360))
        throw SceneError(node.loc, "rotate_extrude angle " + number(angle) +
                                       " is not in (0, 360] degrees (internal error)");
}

/// The parameters of tori and lathes, which the importer must have checked.
void checkRevolved(const Node &node) {
    if (const auto *t = std::get_if<TorusPrim>(&node.shape)) {
        if (!std::isfinite(t->major) || !std::isfinite(t->minor) || !(t->minor > 0) ||
            t->major < t->minor)
            throw SceneError(node.loc, "torus needs finite radii with major >= minor > 0, not " +
                                           number(t->major) + " and " + number(t->minor) +
                                           " (internal error)");
        checkTurn(node, t->angle);
        for (const ProfilePoint &p : t->facetOutline)
            if (!std::isfinite(p.r) || !std::isfinite(p.z) || p.r < 0)
                throw SceneError(node.loc,
                                 "torus outline has a point with r < 0 or not finite "
                                 "(internal error)");
    }
    if (const auto *l = std::get_if<LathePrim>(&node.shape)) {
        checkTurn(node, l->angle);
        if (l->outlines.empty())
            throw SceneError(node.loc, "rotate_extrude has no outline (internal error)");
        for (const ProfileOutline &o : l->outlines) {
            if (o.size() < 3)
                throw SceneError(node.loc, "rotate_extrude outline has " +
                                               std::to_string(o.size()) +
                                               " points, fewer than 3 (internal error)");
            for (const ProfilePoint &p : o)
                if (!std::isfinite(p.r) || !std::isfinite(p.z) || p.r < 0)
                    throw SceneError(node.loc, "rotate_extrude outline point [" + number(p.r) +
                                                   ", " + number(p.z) +
                                                   "] has r < 0 or is not finite (internal error)");
        }
    }
}

/// The parameters of a prism, which the importer must have checked: a finite outline of at
/// least 3 points, z0 < z1, scales k0, k1 >= 0 and not both 0, a mesh in the scene if any.
void checkPrism(const Scene &scene, const Node &node) {
    const auto *p = std::get_if<PrismPrim>(&node.shape);
    if (!p) return;
    if (p->outline.size() < 3)
        throw SceneError(node.loc, "prism outline has " + std::to_string(p->outline.size()) +
                                       " points, fewer than 3 (internal error)");
    for (const Point2 &q : p->outline)
        if (!std::isfinite(q.x) || !std::isfinite(q.y))
            throw SceneError(node.loc,
                             "prism outline has a point that is not finite "
                             "(internal error)");
    if (!(std::isfinite(p->z0) && std::isfinite(p->z1) && p->z0 < p->z1))
        throw SceneError(node.loc, "prism needs finite z0 < z1, not " + number(p->z0) + " and " +
                                       number(p->z1) + " (internal error)");
    if (!(std::isfinite(p->k0) && std::isfinite(p->k1) && p->k0 >= 0 && p->k1 >= 0 &&
          (p->k0 > 0 || p->k1 > 0)))
        throw SceneError(node.loc, "prism needs finite scales >= 0, not both 0, not " +
                                       number(p->k0) + " and " + number(p->k1) +
                                       " (internal error)");
    if (p->mesh >= static_cast<int>(scene.meshes.size()) ||
        (p->mesh >= 0 && !scene.meshes[p->mesh]))
        throw SceneError(node.loc, "prism mesh " + std::to_string(p->mesh) +
                                       " is not in the scene (internal error)");
}

/// Walks the tree with composed transforms and checks every primitive's world bounds.
void checkNode(const Scene &scene, const Node &node, const Mat4 &m, int *primitives) {
    // An importer must resolve its 2D placeholders (extrude them or draw them as plates)
    if (node.shape2d >= 0)
        throw SceneError(node.loc, "2D shape " + std::to_string(node.shape2d) +
                                       " was left unresolved in the scene (internal error)");
    Mat4 here = node.kind == NodeKind::Transform ? m * node.matrix : m;
    if (node.kind == NodeKind::Transform && !here.isFinite())
        throw SceneError(node.loc, "transform has non-finite entries");
    if (node.kind == NodeKind::Primitive) {
        ++*primitives;
        if (const auto *mp = std::get_if<MeshPrim>(&node.shape))
            if (mp->mesh < 0 || mp->mesh >= static_cast<int>(scene.meshes.size()) ||
                !scene.meshes[mp->mesh])
                throw SceneError(node.loc, "mesh reference " + std::to_string(mp->mesh) +
                                               " is not in the scene (internal error)");
        checkRevolved(node);
        checkPrism(scene, node);
        if (node.material < 0 || node.material >= static_cast<int>(scene.materials.size()))
            throw SceneError(node.loc, "primitive has no valid material (internal error)");
        Bounds3 b = Transform(here, Mat4()).bounds(primitiveBounds(node.shape, &scene));
        if (!inRange(b.min) || !inRange(b.max)) {
            // Report the corners themselves, not the bounds padded for rounding
            Bounds3 pb = primitiveBounds(node.shape, &scene), corners;
            for (int i = 0; i < 8; ++i)
                corners = unionBounds(corners, here.transformPoint(pb.corner(i)));
            throw SceneError(node.loc, "object extends to " + vec(corners.min) + " .. " +
                                           vec(corners.max) + ", beyond the supported range of ±" +
                                           number(kMaxCoordinate));
        }
        double extent = maxComponent(b.diagonal());
        if (!(extent >= kMinExtent))
            throw SceneError(node.loc, "object size " + number(extent) +
                                           " is below the supported minimum of " +
                                           number(kMinExtent));
    }
    for (const auto &c : node.children) checkNode(scene, *c, here, primitives);
}

}  // namespace

const Node *firstNodeDeeperThan(const Node &root, int maxDepth) {
    std::vector<std::pair<const Node *, int>> pending{{&root, 1}};
    while (!pending.empty()) {
        auto [node, depth] = pending.back();
        pending.pop_back();
        if (depth > maxDepth) return node;
        // In reverse, so the first child is visited first (the error names the first node)
        for (auto c = node->children.rbegin(); c != node->children.rend(); ++c)
            pending.push_back({c->get(), depth + 1});
    }
    return nullptr;
}

void validateScene(const Scene &scene, DiagnosticSink &diag) {
    for (const MeshPtr &mesh : scene.meshes)
        if (mesh) validateMesh(*mesh);
    if (const Node *deep = firstNodeDeeperThan(*scene.root, kMaxTreeDepth))
        throw SceneError(deep->loc, "objects are nested more than " +
                                        std::to_string(kMaxTreeDepth) +
                                        " levels deep (each module call, transform, colour and CSG "
                                        "operation is a level); scadray stops there");
    int primitives = 0;
    checkNode(scene, *scene.root, Mat4(), &primitives);
    if (primitives == 0)
        diag.warning(scene.root->loc,
                     "the scene has no geometry; the image shows only the "
                     "background");
    for (const Light &l : scene.lights) {
        if (!inRange(l.position))
            throw SceneError(l.loc, "light position " + vec(l.position) +
                                        " is not finite or beyond ±" + number(kMaxCoordinate));
        if (!l.color.isFinite()) throw SceneError(l.loc, "light colour is not finite");
        if (l.kind != Light::Kind::Point && !(l.direction.isFinite() && length(l.direction) > 0))
            throw SceneError(l.loc, "light direction must be a finite non-zero vector");
        if (l.kind == Light::Kind::Spot && !(l.spotRadius >= 0 && l.spotFalloff > 0 &&
                                             l.spotFalloff <= 90 && l.spotRadius <= l.spotFalloff))
            throw SceneError(l.loc, "spot light needs 0 <= radius <= falloff <= 90 degrees");
        if (l.area) {
            const Light::Area &a = l.areaLight;
            if (!inRange(a.axis1) || !inRange(a.axis2))
                throw SceneError(
                    l.loc, "area light axes are not finite or beyond ±" + number(kMaxCoordinate));
            if (a.n1 < 1 || a.n2 < 1 || a.n1 > kMaxAreaLightGrid || a.n2 > kMaxAreaLightGrid)
                throw SceneError(l.loc, "area light grid " + std::to_string(a.n1) + "x" +
                                            std::to_string(a.n2) + " is outside 1.." +
                                            std::to_string(kMaxAreaLightGrid) + " per axis");
            if (a.adaptive < 0) throw SceneError(l.loc, "area light adaptive must be >= 0");
            if ((a.circular || a.orient) && (a.n1 < 2 || a.n2 < 2))
                throw SceneError(l.loc,
                                 "circular and orient area lights need at least 2x2 "
                                 "samples");
            if (l.kind == Light::Kind::Directional)
                throw SceneError(l.loc, "a parallel light cannot be an area light");
        }
    }
    if (scene.camera) {
        const Camera &c = *scene.camera;
        if (!inRange(c.location) || !inRange(c.lookAt) || !c.sky.isFinite())
            throw SceneError(c.loc,
                             "camera vectors are not finite or beyond ±" + number(kMaxCoordinate));
        if (c.projection == Projection::Orthographic &&
            !(c.orthoHeight > 0 && std::isfinite(c.orthoHeight)))
            throw SceneError(c.loc, "orthographic camera needs a positive view height");
        if (c.projection == Projection::Perspective && !(c.fov > 0 && c.fov < 180))
            throw SceneError(c.loc, "camera field of view " + number(c.fov) +
                                        " is not between 0 and 180 degrees");
    }
    for (const Material &m : scene.materials) {
        if (!m.color.isFinite() || !std::isfinite(m.filter) || !std::isfinite(m.transmit) ||
            !std::isfinite(m.interior.ior) || !m.finish.emission.isFinite())
            throw SceneError(m.loc, "material has non-finite values");
        const Finish &f = m.finish;
        if (!(f.glossy >= 0 && f.glossy <= kMaxBlurDegrees) ||
            !(f.frosted >= 0 && f.frosted <= kMaxBlurDegrees))
            throw SceneError(m.loc, "glossy and frosted spreads must be between 0 and " +
                                        number(kMaxBlurDegrees) + " degrees");
        if (f.blurSamples < 1 || f.blurSamples > kMaxBlurSamples)
            throw SceneError(
                m.loc, "blur_samples must be between 1 and " + std::to_string(kMaxBlurSamples));
        if (m.baseColorTexture.texture >= static_cast<int>(scene.textures.size()))
            throw SceneError(m.loc, "material refers to a missing texture (internal error)");
    }
}

}  // namespace rt::ir
