// SPDX-License-Identifier: MIT
// Node construction, material table and CSG-aware bounds of the IR.
#include "core/ir/scene_ir.h"

#include <cmath>

#include "core/ir/prism.h"
#include "core/math/float_util.h"
#include "core/math/transform.h"

namespace rt::ir {

Node::~Node() {
    if (children.empty()) return;
    std::vector<std::unique_ptr<Node>> pending = std::move(children);
    while (!pending.empty()) {
        std::unique_ptr<Node> n = std::move(pending.back());
        pending.pop_back();
        if (!n) continue;  // importers may leave null slots while they build
        for (auto &c : n->children) pending.push_back(std::move(c));
        n->children.clear();
    }  // each node is destroyed with no children left
}

std::unique_ptr<Node> Node::makeGroup(NodeKind kind, SourceLoc loc) {
    auto n = std::make_unique<Node>();
    n->kind = kind;
    n->loc = std::move(loc);
    return n;
}

std::unique_ptr<Node> Node::makeTransform(const Mat4 &m, SourceLoc loc) {
    auto n = makeGroup(NodeKind::Transform, std::move(loc));
    n->matrix = m;
    return n;
}

std::unique_ptr<Node> Node::makePrimitive(PrimShape shape, int material, SourceLoc loc) {
    auto n = makeGroup(NodeKind::Primitive, std::move(loc));
    n->shape = shape;
    n->material = material;
    return n;
}

size_t Node::primitiveCount() const {
    size_t n = kind == NodeKind::Primitive ? 1 : 0;
    for (const auto &c : children) n += c->primitiveCount();
    return n;
}

std::unique_ptr<Node> Node::clone() const {
    auto n = std::make_unique<Node>();
    n->kind = kind;
    n->loc = loc;
    n->label = label;
    n->matrix = matrix;
    n->shape = shape;
    n->material = material;
    n->fragments = fragments;
    n->highlight = highlight;
    n->shape2d = shape2d;
    n->children.reserve(children.size());
    for (const auto &c : children) n->children.push_back(c->clone());
    return n;
}

const char *nodeKindName(NodeKind k) {
    switch (k) {
        case NodeKind::Group:
            return "group";
        case NodeKind::Union:
            return "union";
        case NodeKind::Intersection:
            return "intersection";
        case NodeKind::Difference:
            return "difference";
        case NodeKind::Transform:
            return "transform";
        case NodeKind::Primitive:
            return "primitive";
    }
    return "?";
}

double Camera::horizontalFov(double aspect) const {
    if (fovAxis == FovAxis::Horizontal) return fov;
    return degrees(2 * std::atan(std::tan(radians(fov) / 2) * aspect));
}

namespace {

size_t appearanceHash(const Material &m) {
    size_t h = 0;
    // std::hash<double> maps -0 and +0 alike, as == compares them
    std::apply([&h](auto... v) { ((h = h * 1000003 ^ std::hash<decltype(v)>()(v)), ...); },
               m.appearanceKey());
    return h;
}

}  // namespace

int Scene::addMaterial(const Material &m) {
    if (materialIndex_.size() != materials.size()) {
        materialIndex_.clear();
        for (size_t i = 0; i < materials.size(); ++i)
            materialIndex_.emplace(appearanceHash(materials[i]), static_cast<int>(i));
    }
    size_t h = appearanceHash(m);
    auto [first, last] = materialIndex_.equal_range(h);
    for (auto it = first; it != last; ++it)
        if (materials[it->second].sameAppearance(m)) return it->second;
    materials.push_back(m);
    int index = static_cast<int>(materials.size()) - 1;
    materialIndex_.emplace(h, index);
    return index;
}

Bounds3 primitiveBounds(const PrimShape &shape, const Scene *scene) {
    if (const auto *m = std::get_if<MeshPrim>(&shape)) {
        if (!scene || m->mesh < 0 || m->mesh >= static_cast<int>(scene->meshes.size()))
            return Bounds3();
        return scene->meshes[m->mesh]->bounds();
    }
    if (const auto *s = std::get_if<SpherePrim>(&shape))
        return Bounds3(Vec3(-s->radius), Vec3(s->radius));
    if (const auto *b = std::get_if<BoxPrim>(&shape)) return Bounds3(b->min, b->max);
    if (const auto *p = std::get_if<PolytopePrim>(&shape)) {
        Bounds3 bounds;
        for (const Vec3 &v : p->vertices) bounds = unionBounds(bounds, v);
        return bounds;
    }
    if (const auto *p = std::get_if<PrismPrim>(&shape)) {
        Bounds3 bounds;
        for (const Vec3 &v : prismPoints(*p)) bounds = unionBounds(bounds, v);
        return bounds;
    }
    if (const auto *t = std::get_if<TorusPrim>(&shape)) {
        // The whole turn's bounds, also for a partial turn (safe, and what the POV-Ray writer
        // and CSG culling need; the render primitive bounds its wedge tightly)
        double r = t->major + t->minor;
        return Bounds3(Vec3(-r, -r, -t->minor), Vec3(r, r, t->minor));
    }
    if (const auto *l = std::get_if<LathePrim>(&shape)) {
        // The whole turn's bounds, also for a partial turn (as for the torus)
        Bounds3 bounds;
        for (const auto &o : l->outlines)
            for (const ProfilePoint &p : o) {
                bounds = unionBounds(bounds, Vec3(p.r, p.r, p.z));
                bounds = unionBounds(bounds, Vec3(-p.r, -p.r, p.z));
            }
        return bounds;
    }
    const auto &c = std::get<CylinderPrim>(shape);
    double r = std::max(c.r1, c.r2);
    return Bounds3(Vec3(-r, -r, c.z0), Vec3(r, r, c.z1));
}

Bounds3 worldBounds(const Node &node, const Mat4 &parentFromNode, const Scene *scene) {
    switch (node.kind) {
        case NodeKind::Primitive: {
            Transform t(parentFromNode, Mat4());  // inverse unused by bounds()
            return t.bounds(primitiveBounds(node.shape, scene));
        }
        case NodeKind::Transform: {
            Mat4 m = parentFromNode * node.matrix;
            Bounds3 b;
            for (const auto &c : node.children) b = unionBounds(b, worldBounds(*c, m, scene));
            return b;
        }
        case NodeKind::Intersection: {
            if (node.children.empty()) return Bounds3();
            Bounds3 b = Bounds3::infinite();
            for (const auto &c : node.children)
                b = intersectBounds(b, worldBounds(*c, parentFromNode, scene));
            return b.isEmpty() ? Bounds3() : b;
        }
        case NodeKind::Difference:
            return node.children.empty()
                       ? Bounds3()
                       : worldBounds(*node.children.front(), parentFromNode, scene);
        case NodeKind::Group:
        case NodeKind::Union: {
            Bounds3 b;
            for (const auto &c : node.children)
                b = unionBounds(b, worldBounds(*c, parentFromNode, scene));
            return b;
        }
    }
    return Bounds3();
}

}  // namespace rt::ir
