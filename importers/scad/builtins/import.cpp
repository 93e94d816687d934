// SPDX-License-Identifier: MIT
// Builtin file readers: import() and its deprecated spellings, surface(), dxf_dim(), dxf_cross().
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <unordered_set>

#include "core/meshing/triangulate.h"
#include "core/system/input_file.h"
#include "importers/gltf/gltf_importer.h"
#include "importers/mesh/mesh_reader.h"
#include "importers/scad/builtins/families.h"
#include "importers/scad/builtins/file_support.h"
#include "importers/scad/builtins/module_support.h"
#include "importers/scad/builtins/placeholders2d.h"
#include "importers/scad/formats/dxf.h"
#include "importers/scad/formats/surface.h"
#include "importers/scad/formats/svg.h"

namespace rt::scad {

namespace {

namespace fs = std::filesystem;

/// ev.state().meshFiles entry of a mesh file without triangles: nothing to place.
constexpr int kNoMesh = -1;

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
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

ir::NodePtr importMeshFile(Evaluator &ev, const std::string &path, const ModuleInstantiation &inst,
                           const FramePtr &f) {
    std::string key = cacheKey(path);
    auto it = ev.state().meshFiles.find(key);
    int index;
    if (it != ev.state().meshFiles.end()) {
        // Read once: every import of the file places the same mesh
        index = it->second;
    } else {
        ir::Mesh mesh = meshio::readMeshFile(path, ev.diag());
        std::string problem = meshio::solidProblem(mesh);
        if (!problem.empty())
            ev.warn(inst.loc, "import(): the mesh of '" + path + "' " + problem +
                                  "; it may not render as a solid");
        index = mesh.triangles.empty() ? kNoMesh : addMesh(ev, std::move(mesh));
        ev.state().meshFiles.emplace(key, index);
    }
    // A file without triangles is empty geometry, silently, as in OpenSCAD
    if (index == kNoMesh) return ev.newNode(ir::NodeKind::Group, inst.loc);
    return primitive(ev, ir::MeshPrim{index}, inst, f);
}

ir::NodePtr importGltfFile(Evaluator &ev, const std::string &path,
                           const ModuleInstantiation &inst) {
    // A color() or material() around the call replaces the file's materials
    std::optional<int> override;
    if (ev.state().color || !ev.state().materials.empty()) override = resolveMaterial(ev, inst.loc);
    std::string key = cacheKey(path);
    auto it = ev.state().gltfFiles.find(key);
    ir::NodePtr tree;
    if (it != ev.state().gltfFiles.end() && (override || it->second.fileMaterials)) {
        // Read once: later imports place the same meshes (and materials, unless overridden)
        tree = it->second.tree->clone();
        relocate(*tree, inst.loc, override);
    } else {
        tree = gltf::importGltfInto(ev.scene(), path, inst.loc, ev.diag(), override);
        if (it == ev.state().gltfFiles.end())
            ev.state().gltfFiles.emplace(key, GltfImport{tree->clone(), !override});
        else if (!override)
            it->second = GltfImport{tree->clone(), true};
    }
    ev.countNodes(static_cast<int64_t>(countNodes(*tree)), inst.loc);
    return tree;
}

ir::NodePtr moduleImport(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    // 2021.01 import.cc: five positional parameters, then named ones for 2D formats and the
    // deprecated spellings. Only `file` matters for 3D formats.
    BoundArgs a = ev.bindBuiltin(inst,
                                 {"file", "layer", "convexity", "origin", "scale", "width",
                                  "height", "filename", "layername", "center", "dpi"},
                                 f, dollars.get(), 5);
    FrameGuard g(ev.dynamicScope(), dollars.get());
    warnLeafChildren(ev, inst);
    size_t fileArg = 0;
    if (a[0].isUndef() && !a[7].isUndef()) {
        ev.warn(a.loc(7), "DEPRECATED: filename= is deprecated. Please use file=");
        fileArg = 7;
    }
    if (a[1].isUndef() && !a[8].isUndef())
        ev.warn(a.loc(8), "DEPRECATED: layername= is deprecated. Please use layer=");
    // Any value names a file by its text; undef (or no file at all) names none
    const Value &file = a[fileArg];
    std::string name = file.isString()  ? file.toStr()
                       : file.isUndef() ? std::string()
                                        : file.toEchoString();
    std::string ext = lowercase(fs::path(name).extension().string());
    if (ext.empty()) {
        // OpenSCAD reports a file without a format (or none) and goes on with empty geometry;
        // a `%` part never gets that far
        if (ev.state().backgroundDepth == 0)
            ev.warn(a.loc(fileArg),
                    "import(): unsupported file format while trying to import "
                    "file '" +
                        name + "'; empty geometry");
        return ev.newNode(ir::NodeKind::Group, inst.loc);
    }
    if (ext == ".dxf" || ext == ".svg") return importFile2d(ev, ext, name, a, inst);
    bool meshFile = ext == ".stl" || ext == ".off";
    bool gltfFile = ext == ".gltf" || ext == ".glb";
    if (!meshFile && !gltfFile) return skipUnsupported(ev, inst.loc, "import of " + ext + " files");

    std::string path = resolveImportPath(ev, name, inst.loc);
    std::error_code ec;
    // The name as written, and where it was looked for when that differs
    std::string shown = "'" + name + "'" + (path != name ? " (" + path + ")" : "");
    if (!fs::is_regular_file(path, ec))
        throw EvalError(inst.loc,
                        "import(): can't open file " + shown + ": " +
                            (fs::exists(path, ec) ? "not a regular file" : "no such file"));
    if (!std::ifstream(path, std::ios::binary))
        throw EvalError(inst.loc, "import(): can't read file " + shown);
    // Left out with its `%` subtree: the file need not be read
    if (ev.state().backgroundDepth > 0) return ev.newNode(ir::NodeKind::Group, inst.loc);
    return meshFile ? importMeshFile(ev, path, inst, f) : importGltfFile(ev, path, inst);
}

ir::NodePtr moduleImportDeprecated(Evaluator &ev, const ModuleInstantiation &inst,
                                   const FramePtr &f) {
    ev.deprecated(inst.loc,
                  "The " + inst.name.str() +
                      "() module will be removed in future releases. Use import() instead.",
                  false);
    return moduleImport(ev, inst, f);
}

ir::NodePtr moduleSurface(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a =
        ev.bindBuiltin(inst, {"file", "center", "convexity", "invert"}, f, dollars.get(), 3);
    FrameGuard g(ev.dynamicScope(), dollars.get());
    warnLeafChildren(ev, inst);
    // `convexity` only matters for OpenSCAD's preview
    bool center = a[1].isBool() && a[1].boolValue();
    bool invert = a[3].isBool() && a[3].boolValue();
    std::string path = resolveImportPath(ev, textOf(a[0]), inst.loc);
    if (ev.state().backgroundDepth > 0) return ev.newNode(ir::NodeKind::Group, inst.loc);
    surface::HeightMap map;
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
        ev.warn(inst.loc, "The file '" + path + "' couldn't be opened.");
        return ev.newNode(ir::NodeKind::Group, inst.loc);
    }
    surface::ReadResult r;
    try {
        r = surface::readHeightMap(path, invert, map,
                                   [&](const std::string &m) { ev.warn(inst.loc, m); });
    } catch (const InputFileError &e) {
        throw EvalError(inst.loc, std::string("surface(): ") + e.what());
    }
    if (r == surface::ReadResult::TooLarge)
        throw EvalError(inst.loc, "surface(): '" + path + "' holds more than " +
                                      std::to_string(surface::kMaxCells) + " heights");
    for (double v : map.values)
        if (!std::isfinite(v)) {
            ev.warn(inst.loc, "surface(): '" + path +
                                  "' holds a height that is not a finite "
                                  "number; the surface is left out");
            return ev.newNode(ir::NodeKind::Group, inst.loc);
        }
    ir::Mesh mesh = surface::surfaceMesh(map, center);
    if (mesh.triangles.empty()) return ev.newNode(ir::NodeKind::Group, inst.loc);
    mesh.name = "surface";
    mesh.loc = inst.loc;
    meshio::weldMesh(mesh);
    int index = addMesh(ev, std::move(mesh));
    return primitive(ev, ir::MeshPrim{index}, inst, f);
}

Value callDxfFunction(Evaluator &ev, bool cross, const ArgumentList &args, const FramePtr &f,
                      const SourceLoc &loc) {
    const std::string who = cross ? "dxf_cross" : "dxf_dim";
    std::string rawName, path, layer, name;
    double ox = 0, oy = 0, scale = 1;
    // 2021.01 reads the arguments by name only; others are warned about and ignored
    for (const auto &arg : args) {
        Value v = ev.eval(*arg.expr, f);
        std::string n = arg.name.empty() ? std::string() : arg.name.str();
        if (n == "file") {
            rawName = v.toString(false);
            path = resolveImportPath(ev, rawName, loc);
        } else if (n == "layer") {
            layer = v.toString(false);
        } else if (n == "origin") {
            bool ok = getVec2(v, ox, oy) && std::isfinite(ox) && std::isfinite(oy);
            if (!ok) {
                ox = oy = 0;
                ev.warn(arg.loc,
                        who + "(..., origin=" + v.toEchoString() + ") could not be converted");
            }
        } else if (n == "scale") {
            if (v.isNumber()) scale = v.toNumber();
        } else if (n == "name" && !cross) {
            name = v.toString(false);
        } else {
            ev.warn(arg.loc, who + "(..., " + n + "=...) is not supported");
        }
    }
    ev.step(loc);
    std::error_code ec;
    if (path.empty() || !fs::exists(path, ec)) {
        ev.warn(loc, "Can't open DXF file '" + rawName + "'!");
        return Value();
    }
    if (!std::isfinite(scale)) {
        ev.warn(loc, who + "(): scale " + formatNumber(scale) + " is not finite; returning undef");
        return Value();
    }
    dxf::ReadOptions opts;
    opts.layer = layer;
    opts.originX = ox;
    opts.originY = oy;
    opts.scale = scale;
    opts.fragments = ir::Fragments{36, 0, 0};
    dxf::Data data;
    std::optional<std::string> bytes = readNamedFile(path, dxf::kMaxFileBytes, who, loc);
    if (!bytes) {
        ev.warn(loc, "Can't open DXF file '" + path + "'.");
        return Value();
    }
    dxf::read(*bytes, path, opts, data, [&](const std::string &m) { ev.warn(loc, m); });
    if (cross) {
        double x, y;
        if (dxf::cross(data, x, y)) {
            ev.checkElementBudget(2, loc);
            return Value::vector({Value::number(x), Value::number(y)});
        }
        ev.warn(loc, "Can't find cross in '" + rawName + "', layer '" + layer + "'!");
        return Value();
    }
    double value;
    bool unsupported;
    if (dxf::dimension(data, name, value, unsupported)) return Value::number(value);
    ev.warn(loc, unsupported ? "Dimension '" + name + "' in '" + rawName + "', layer '" + layer +
                                   "' has unsupported type!"
                             : "Can't find dimension '" + name + "' in '" + rawName + "', layer '" +
                                   layer + "'!");
    return Value();
}

/// dxf_dim() and dxf_cross() read their arguments by name (2021.01 dxfdim.cc).
Value fnDxfDim(Evaluator &ev, const ArgumentList &args, const FramePtr &f, const SourceLoc &loc) {
    return callDxfFunction(ev, false, args, f, loc);
}
Value fnDxfCross(Evaluator &ev, const ArgumentList &args, const FramePtr &f, const SourceLoc &loc) {
    return callDxfFunction(ev, true, args, f, loc);
}

}  // namespace

BuiltinFamily importBuiltins() {
    static constexpr BuiltinModuleEntry kModules[] = {
        {"import", moduleImport},
        {"import_stl", moduleImportDeprecated},
        {"import_off", moduleImportDeprecated},
        {"import_dxf", moduleImportDeprecated},
        {"surface", moduleSurface},
    };
    static constexpr BuiltinFunctionEntry kFunctions[] = {
        {"dxf_dim", nullptr, fnDxfDim},
        {"dxf_cross", nullptr, fnDxfCross},
    };
    return {kModules, kFunctions};
}

}  // namespace rt::scad
