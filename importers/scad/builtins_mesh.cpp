// SPDX-License-Identifier: MIT
// Builtin mesh modules: polyhedron() and import() of STL, OFF and glTF files (OpenSCAD 2021.01
// primitives.cc and import.cc), with each imported file read once per evaluation.
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <unordered_set>

#include "importers/gltf/gltf_importer.h"
#include "core/meshing/triangulate.h"
#include "importers/mesh/mesh_reader.h"
#include "importers/scad/evaluator.h"

namespace rt::scad {

namespace {

namespace fs = std::filesystem;

/// At most this many skipped-face warnings per polyhedron; the rest are counted in a summary.
constexpr int kMaxFaceWarnings = 10;
/// meshFiles_ entry of a mesh file without triangles: nothing to place.
constexpr int kNoMesh = -1;

std::string argText(const Value &v) { return v.toEchoString(); }

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

/// True when the polygon's corners hold at least three different points.
bool hasThreeDistinctPoints(const std::vector<Vec3> &positions,
                            const std::vector<uint32_t> &polygon) {
    const Vec3 *first = nullptr, *second = nullptr;
    for (uint32_t i : polygon) {
        const Vec3 &p = positions[i];
        if (!first) {
            first = &p;
        } else if (!second) {
            if (p != *first) second = &p;
        } else if (p != *first && p != *second) {
            return true;
        }
    }
    return false;
}

/// Removes the triangles that repeat an earlier one (the same corners in the same cyclic
/// order; the reverse is another face) and returns how many. A face listed many times costs
/// the trace as many times over while adding nothing: OpenSCAD's CGAL operations take such
/// a polyhedron as its distinct faces.
size_t dropRepeatedTriangles(ir::Mesh &mesh) {
    struct Hash {
        size_t operator()(const std::array<uint32_t, 3> &t) const {
            uint64_t h = t[0];
            h = h * 0x9E3779B97F4A7C15ull ^ t[1];
            h = h * 0x9E3779B97F4A7C15ull ^ t[2];
            return static_cast<size_t>(h ^ (h >> 29));
        }
    };
    std::unordered_set<std::array<uint32_t, 3>, Hash> seen;
    seen.reserve(mesh.triangles.size());
    size_t kept = 0;
    for (const auto &t : mesh.triangles) {
        // Rotated to start at the smallest index: one key per cyclic order
        int first = t[0] <= t[1] && t[0] <= t[2] ? 0 : t[1] <= t[2] ? 1 : 2;
        std::array<uint32_t, 3> key = {t[first], t[(first + 1) % 3], t[(first + 2) % 3]};
        if (seen.insert(key).second) mesh.triangles[kept++] = t;
    }
    size_t dropped = mesh.triangles.size() - kept;
    mesh.triangles.resize(kept);
    return dropped;
}

/// The same file reached by different spellings gets one cache entry.
std::string cacheKey(const std::string &path) {
    std::error_code ec;
    fs::path canonical = fs::weakly_canonical(path, ec);
    return ec ? path : canonical.string();
}

size_t countNodes(const ir::Node &n) {
    size_t count = 1;
    for (const auto &c : n.children) count += countNodes(*c);
    return count;
}

/// Gives a reused import tree the location of the new call and, when set, its material.
void relocate(ir::Node &n, const SourceLoc &loc, std::optional<int> material) {
    n.loc = loc;
    if (n.kind == ir::NodeKind::Primitive && material) n.material = *material;
    for (auto &c : n.children) relocate(*c, loc, material);
}

}  // namespace

int Evaluator::addMesh(ir::Mesh mesh) {
    // The readers and polyhedron() only make valid meshes; this keeps it so
    ir::validateMesh(mesh);
    scene_.meshes.push_back(std::make_shared<const ir::Mesh>(std::move(mesh)));
    return static_cast<int>(scene_.meshes.size()) - 1;
}

ir::NodePtr Evaluator::modulePolyhedron(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a =
        bindBuiltin(inst, {"points", "faces", "convexity", "triangles"}, f, dollars.get(), 3);
    FrameGuard g(dyn_, dollars.get());
    warnLeafChildren(inst);
    // `convexity` only matters for OpenSCAD's preview

    // Points are 3-vectors, or 2-vectors with z = 0 (2021.01 getVec3(..., 0.0))
    const Value &points = a[0];
    if (!points.isVector())
        return emptyPrimitive(inst,
                              "points = " + argText(points) + " is not a vector of coordinates");
    ir::Mesh mesh;
    mesh.name = "polyhedron";
    mesh.loc = inst.loc;
    const auto &pv = points.toVector();
    mesh.positions.reserve(pv.size());
    for (size_t i = 0; i < pv.size(); ++i) {
        double x, y, z;
        if (!pv[i].getVec3(x, y, z, true) || !std::isfinite(x) || !std::isfinite(y) ||
            !std::isfinite(z))
            return emptyPrimitive(inst, "points[" + std::to_string(i) + "] = " + argText(pv[i]) +
                                            " is not a vector of 3 finite numbers");
        mesh.positions.emplace_back(x, y, z);
    }

    // The deprecated triangles= counts only when faces is undef
    size_t facesArg = 1;
    if (a[1].isUndef() && !a[3].isUndef()) {
        warn(a.loc(3),
             "DEPRECATED: polyhedron(triangles=[]) will be removed in future releases. Use "
             "polyhedron(faces=[]) instead.");
        facesArg = 3;
    }
    const Value &faces = a[facesArg];
    if (faces.isUndef()) return emptyPrimitive(inst, "no faces given");
    if (!faces.isVector())
        return emptyPrimitive(
            inst, "faces = " + argText(faces) + " is not a vector of vectors of point indices");
    const SourceLoc &facesLoc = a.loc(facesArg);
    if (faces.isVector())
        chargeGeometryWork(inst.loc, "polyhedron()",
                           static_cast<double>(faces.toVector().size()), "faces");
    int skipped = 0;
    auto skip = [&](const std::string &why) {
        if (++skipped <= kMaxFaceWarnings) warn(facesLoc, why + "; face skipped");
    };

    std::vector<uint32_t> polygon;
    const auto &fv = faces.toVector();
    for (size_t i = 0; i < fv.size(); ++i) {
        std::string name = "faces[" + std::to_string(i) + "]";
        if (!fv[i].isVector()) {
            skip(name + " = " + argText(fv[i]) + " is not a vector of point indices");
            continue;
        }
        const auto &indices = fv[i].toVector();
        polygon.clear();
        bool valid = true;
        for (size_t j = 0; j < indices.size() && valid; ++j) {
            auto where = [&] { return name + "[" + std::to_string(j) + "]"; };
            double d;
            if (!indices[j].getFiniteNumber(d)) {
                skip(where() + " = " + argText(indices[j]) + " is not a point index");
                valid = false;
            } else if (d < 0 || d >= static_cast<double>(mesh.positions.size())) {
                skip("Point index " + formatNumber(d) + " is out of bounds (from " + where() + ")");
                valid = false;
            } else {
                // A fractional index is truncated, as OpenSCAD converts it to size_t
                polygon.push_back(static_cast<uint32_t>(d));
            }
        }
        if (!valid) continue;
        if (!hasThreeDistinctPoints(mesh.positions, polygon)) {
            skip(name + " has fewer than 3 distinct points");
            continue;
        }
        // OpenSCAD's faces are clockwise seen from outside; the IR's are counter-clockwise
        std::reverse(polygon.begin(), polygon.end());
        if (polygon.size() == 3)
            mesh.triangles.push_back({polygon[0], polygon[1], polygon[2]});
        else if (!meshing::triangulatePolygon(mesh.positions, polygon, mesh.triangles))
            skip(name + " is degenerate (its points enclose no area)");
    }
    if (skipped > kMaxFaceWarnings)
        warn(facesLoc, std::to_string(skipped) + " faces skipped in all");

    meshio::weldMesh(mesh);
    if (size_t repeated = dropRepeatedTriangles(mesh))
        warn(facesLoc, "polyhedron(): " + std::to_string(repeated) +
                           " triangles repeat earlier faces (the same points in the same "
                           "order); each is drawn once, as OpenSCAD's CGAL operations take it");
    if (mesh.triangles.empty()) return emptyPrimitive(inst, "no valid faces");
    std::string problem = meshio::solidProblem(mesh);
    if (!problem.empty())
        warn(inst.loc, "polyhedron() " + problem +
                           "; OpenSCAD needs a closed surface whose faces are listed clockwise "
                           "seen from outside");
    // Left out with its `%` subtree: no mesh without a node placing it
    if (backgroundDepth_ > 0) return newNode(ir::NodeKind::Group, inst.loc);
    int index = addMesh(std::move(mesh));
    return primitive(ir::MeshPrim{index}, inst, f);
}

ir::NodePtr Evaluator::moduleImportDeprecated(const ModuleInstantiation &inst, const FramePtr &f) {
    deprecated(inst.loc, "The " + inst.name.str() +
                             "() module will be removed in future releases. Use import() instead.",
               false);
    return moduleImport(inst, f);
}

std::string Evaluator::resolveImportPath(const std::string &name, const SourceLoc &loc) {
    fs::path p(name);
    if (p.is_absolute()) return p.lexically_normal().string();
    fs::path dir = loc.file ? fs::path(*loc.file).parent_path() : fs::path();
    fs::path candidate = (dir / p).lexically_normal();
    std::error_code ec;
    if (!fs::exists(candidate, ec) && mainFile_.src) {
        // 2021.01 lookup_file: the main file's folder as a deprecated fallback
        fs::path fallback = (fs::path(mainFile_.src->path).parent_path() / p).lexically_normal();
        if (fallback != candidate && fs::exists(fallback, ec)) {
            warn(loc, "DEPRECATED: Imported file (" + name +
                          ") found in document root instead of relative to the importing "
                          "module. This behavior is deprecated");
            return fallback.string();
        }
    }
    return candidate.string();
}

ir::NodePtr Evaluator::moduleImport(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    // 2021.01 import.cc: five positional parameters, then named ones for 2D formats and the
    // deprecated spellings. Only `file` matters for 3D formats.
    BoundArgs a = bindBuiltin(inst,
                              {"file", "layer", "convexity", "origin", "scale", "width", "height",
                               "filename", "layername", "center", "dpi"},
                              f, dollars.get(), 5);
    FrameGuard g(dyn_, dollars.get());
    warnLeafChildren(inst);
    size_t fileArg = 0;
    if (a[0].isUndef() && !a[7].isUndef()) {
        warn(a.loc(7), "DEPRECATED: filename= is deprecated. Please use file=");
        fileArg = 7;
    }
    if (a[1].isUndef() && !a[8].isUndef())
        warn(a.loc(8), "DEPRECATED: layername= is deprecated. Please use layer=");
    // Any value names a file by its text; undef (or no file at all) names none
    const Value &file = a[fileArg];
    std::string name = file.isString()  ? file.toStr()
                       : file.isUndef() ? std::string()
                                        : file.toEchoString();
    std::string ext = lowercase(fs::path(name).extension().string());
    if (ext.empty()) {
        // OpenSCAD reports a file without a format (or none) and goes on with empty geometry;
        // a `%` part never gets that far
        if (backgroundDepth_ == 0)
            warn(a.loc(fileArg), "import(): unsupported file format while trying to import "
                                 "file '" +
                                     name + "'; empty geometry");
        return newNode(ir::NodeKind::Group, inst.loc);
    }
    if (ext == ".dxf" || ext == ".svg") return importFile2d(ext, name, a, inst);
    bool meshFile = ext == ".stl" || ext == ".off";
    bool gltfFile = ext == ".gltf" || ext == ".glb";
    if (!meshFile && !gltfFile) return skipUnsupported(inst.loc, "import of " + ext + " files");

    std::string path = resolveImportPath(name, inst.loc);
    std::error_code ec;
    // The name as written, and where it was looked for when that differs
    std::string shown = "'" + name + "'" + (path != name ? " (" + path + ")" : "");
    if (!fs::is_regular_file(path, ec))
        throw EvalError(inst.loc,
                        "import(): can't open file " + shown +
                            ": " + (fs::exists(path, ec) ? "not a regular file" : "no such file"));
    if (!std::ifstream(path, std::ios::binary))
        throw EvalError(inst.loc, "import(): can't read file " + shown);
    // Left out with its `%` subtree: the file need not be read
    if (backgroundDepth_ > 0) return newNode(ir::NodeKind::Group, inst.loc);
    return meshFile ? importMeshFile(path, inst, f) : importGltfFile(path, inst);
}

ir::NodePtr Evaluator::importMeshFile(const std::string &path, const ModuleInstantiation &inst,
                                      const FramePtr &f) {
    std::string key = cacheKey(path);
    auto it = meshFiles_.find(key);
    int index;
    if (it != meshFiles_.end()) {
        // Read once: every import of the file places the same mesh
        index = it->second;
    } else {
        ir::Mesh mesh = meshio::readMeshFile(path, diag_);
        std::string problem = meshio::solidProblem(mesh);
        if (!problem.empty())
            warn(inst.loc, "import(): the mesh of '" + path + "' " + problem +
                               "; it may not render as a solid");
        index = mesh.triangles.empty() ? kNoMesh : addMesh(std::move(mesh));
        meshFiles_.emplace(key, index);
    }
    // A file without triangles is empty geometry, silently, as in OpenSCAD
    if (index == kNoMesh) return newNode(ir::NodeKind::Group, inst.loc);
    return primitive(ir::MeshPrim{index}, inst, f);
}

ir::NodePtr Evaluator::importGltfFile(const std::string &path, const ModuleInstantiation &inst) {
    // A color() or material() around the call replaces the file's materials
    std::optional<int> override;
    if (color_ || !materials_.empty()) override = resolveMaterial(inst.loc);
    std::string key = cacheKey(path);
    auto it = gltfFiles_.find(key);
    ir::NodePtr tree;
    if (it != gltfFiles_.end() && (override || it->second.fileMaterials)) {
        // Read once: later imports place the same meshes (and materials, unless overridden)
        tree = it->second.tree->clone();
        relocate(*tree, inst.loc, override);
    } else {
        tree = gltf::importGltfInto(scene_, path, inst.loc, diag_, override);
        if (it == gltfFiles_.end())
            gltfFiles_.emplace(key, GltfImport{tree->clone(), !override});
        else if (!override)
            it->second = GltfImport{tree->clone(), true};
    }
    nodes_ += static_cast<int64_t>(countNodes(*tree));
    if (nodes_ > limits_.maxNodes)
        throw EvalError(inst.loc,
                        "too many geometry nodes: more than " + std::to_string(limits_.maxNodes));
    return tree;
}

}  // namespace rt::scad
