// SPDX-License-Identifier: MIT
// 2D file formats and height maps (OpenSCAD 2021.01 import.cc, dxfdim.cc, surface.cc and the
// file forms of linear_extrude/rotate_extrude): import() of DXF files, dxf_dim(),
// dxf_cross() and surface().
#include <cmath>
#include <filesystem>
#include <optional>

#include "core/system/input_file.h"
#include "importers/mesh/mesh_reader.h"
#include "importers/scad/dxf.h"
#include "importers/scad/evaluator.h"
#include "importers/scad/surface.h"
#include "importers/scad/svg.h"

namespace rt::scad {

namespace {

namespace fs = std::filesystem;

/// A parameter OpenSCAD reads with toString(): undef is "", other values as str() shows them.
std::string textOf(const Value &v) { return v.isUndef() ? std::string() : v.toString(false); }

/// The bytes of a file that import(), dxf_dim() or dxf_cross() names, through the input reader.
/// Nothing when it is missing, unreadable or a folder: OpenSCAD warns and goes on, and so does
/// the caller. A FIFO, device or socket (which would block, or never end) or a file past
/// `maxBytes` is a located error.
std::optional<std::string> readNamedFile(const std::string &path, uint64_t maxBytes,
                                         const std::string &who, const SourceLoc &loc) {
    std::error_code ec;
    if (path.empty() || fs::is_directory(path, ec)) return std::nullopt;
    try {
        return readInputFile(path, maxBytes);
    } catch (const InputFileError &e) {
        if (e.reason() == InputFileError::Reason::Missing ||
            e.reason() == InputFileError::Reason::Unreadable)
            return std::nullopt;
        throw EvalError(loc, who + "(): " + e.what());
    }
}

}  // namespace

Dxf2dArgs Evaluator::dxfArgs(const std::string &who, const Value &layer, const Value &origin,
                             const SourceLoc &originLoc, const Value &scale,
                             const SourceLoc &scaleLoc) {
    Dxf2dArgs d;
    d.layer = textOf(layer);
    if (!origin.isUndef()) {
        double x = 0, y = 0;
        if (getVec2(origin, x, y) && std::isfinite(x) && std::isfinite(y)) {
            d.originX = x;
            d.originY = y;
        } else {
            warn(originLoc, who + "(..., origin=" + origin.toEchoString() +
                                ") could not be converted");
        }
    }
    // A scale that is not a positive number is 1, as in OpenSCAD
    if (scale.isNumber()) {
        double s = scale.toNumber();
        if (std::isfinite(s) && s > 0) d.scale = s;
        else if (!(s <= 0)) warn(scaleLoc, who + "(..., scale=" + scale.toEchoString() +
                                               ") is not finite; using 1");
    }
    return d;
}

ir::NodePtr Evaluator::dxfShapeNode(const std::string &path, const Dxf2dArgs &args,
                                    const ModuleInstantiation &inst) {
    dxf::ReadOptions opts;
    opts.layer = args.layer;
    opts.originX = args.originX;
    opts.originY = args.originY;
    opts.scale = args.scale;
    opts.fragments = currentFragments(inst.loc);
    dxf::Data data;
    Shape2d s;
    s.kind = Shape2dKind::Polygon;
    std::optional<std::string> bytes = readNamedFile(path, dxf::kMaxFileBytes, inst.name.str(), inst.loc);
    if (!bytes) {
        // OpenSCAD warns and goes on with empty geometry
        warn(inst.loc, "Can't open DXF file '" + path + "'.");
    } else {
        dxf::read(*bytes, path, opts, data, [&](const std::string &m) { warn(inst.loc, m); });
        for (Outline &o : dxf::outlines(data))
            if (o.size() > 2) s.outlines.push_back(std::move(o));
    }
    return shape2dNode(std::move(s), inst);
}

ir::NodePtr Evaluator::importFile2d(const std::string &ext, const std::string &name,
                                    const BoundArgs &a, const ModuleInstantiation &inst) {
    std::string path = resolveImportPath(name, inst.loc);
    // Left out with its `%` subtree: the file need not be read
    if (backgroundDepth_ > 0) return newNode(ir::NodeKind::Group, inst.loc);
    if (ext == ".svg") return importSvg(path, a, inst);
    // The deprecated layername= counts only when layer is undef
    const Value &layer = a[1].isUndef() ? a[8] : a[1];
    Dxf2dArgs d = dxfArgs("import", layer, a[3], a.loc(3), a[4], a.loc(4));
    return dxfShapeNode(path, d, inst);
}

ir::NodePtr Evaluator::importSvg(const std::string &path, const BoundArgs &a,
                                 const ModuleInstantiation &inst) {
    svg::Options opts;
    opts.center = a[9].isBool() && a[9].boolValue();
    if (a[10].isNumber()) {
        double dpi = a[10].toNumber();
        if (dpi >= svg::kMinDpi && std::isfinite(dpi))
            opts.dpi = dpi;
        else
            warn(a.loc(10), "Invalid dpi value giving, using default of " +
                                formatNumber(svg::kDefaultDpi) +
                                " dpi. Value must be positive and >= 0.001");
    }
    Shape2d s;
    s.kind = Shape2dKind::Polygon;
    s.evaluated = true;
    s.sanitized = true;
    svg::Drawing drawing;
    std::string error;
    std::optional<std::string> bytes = readNamedFile(path, svg::kMaxFileBytes, "import", inst.loc);
    if (!bytes) error = "Can't open file '" + path + "'";
    if (error.empty() && svg::read(*bytes, path, opts, drawing, error)) {
        for (const auto &[element, count] : drawing.skipped)
            warn(inst.loc, "import(): " + std::to_string(count) + " <" + element +
                               "> element(s) of '" + path + "' left out (not drawn by OpenSCAD "
                               "2021.01's SVG import)");
        // Each shape is a polygon filled even-odd; OpenSCAD unites them
        std::vector<clipper2d::PolygonSet> operands;
        for (auto &outlines : drawing.shapes) {
            clipper2d::PolygonSet p;
            for (Outline &o : outlines)
                if (o.size() > 2) p.outlines.push_back(std::move(o));
            if (!p.empty()) operands.push_back(std::move(p));
        }
        if (!operands.empty())
            s.outlines = withClipper(inst.loc, [&] {
                             return clipper2d::apply(operands, clipper2d::BoolOp::Union);
                         }).outlines;
    } else {
        // OpenSCAD logs an error and goes on with empty geometry
        diag_.report(Severity::Error, inst.loc, error);
    }
    return shape2dNode(std::move(s), inst);
}

ir::NodePtr Evaluator::dxfFileShape(const Value &file, const Dxf2dArgs &args,
                                    const ModuleInstantiation &inst) {
    return dxfShapeNode(resolveImportPath(textOf(file), inst.loc), args, inst);
}

Value Evaluator::callDxfFunction(bool cross, const ArgumentList &args, const FramePtr &f,
                                 const SourceLoc &loc) {
    const std::string who = cross ? "dxf_cross" : "dxf_dim";
    std::string rawName, path, layer, name;
    double ox = 0, oy = 0, scale = 1;
    // 2021.01 reads the arguments by name only; others are warned about and ignored
    for (const auto &arg : args) {
        Value v = eval(*arg.expr, f);
        std::string n = arg.name.empty() ? std::string() : arg.name.str();
        if (n == "file") {
            rawName = v.toString(false);
            path = resolveImportPath(rawName, loc);
        } else if (n == "layer") {
            layer = v.toString(false);
        } else if (n == "origin") {
            bool ok = getVec2(v, ox, oy) && std::isfinite(ox) && std::isfinite(oy);
            if (!ok) {
                ox = oy = 0;
                warn(arg.loc, who + "(..., origin=" + v.toEchoString() + ") could not be converted");
            }
        } else if (n == "scale") {
            if (v.isNumber()) scale = v.toNumber();
        } else if (n == "name" && !cross) {
            name = v.toString(false);
        } else {
            warn(arg.loc, who + "(..., " + n + "=...) is not supported");
        }
    }
    step(loc);
    std::error_code ec;
    if (path.empty() || !fs::exists(path, ec)) {
        warn(loc, "Can't open DXF file '" + rawName + "'!");
        return Value();
    }
    if (!std::isfinite(scale)) {
        warn(loc, who + "(): scale " + formatNumber(scale) + " is not finite; returning undef");
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
        warn(loc, "Can't open DXF file '" + path + "'.");
        return Value();
    }
    dxf::read(*bytes, path, opts, data, [&](const std::string &m) { warn(loc, m); });
    if (cross) {
        double x, y;
        if (dxf::cross(data, x, y)) {
            checkElementBudget(2, loc);
            return Value::vector({Value::number(x), Value::number(y)});
        }
        warn(loc, "Can't find cross in '" + rawName + "', layer '" + layer + "'!");
        return Value();
    }
    double value;
    bool unsupported;
    if (dxf::dimension(data, name, value, unsupported)) return Value::number(value);
    warn(loc, unsupported ? "Dimension '" + name + "' in '" + rawName + "', layer '" + layer +
                                "' has unsupported type!"
                          : "Can't find dimension '" + name + "' in '" + rawName +
                                "', layer '" + layer + "'!");
    return Value();
}

ir::NodePtr Evaluator::moduleSurface(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = bindBuiltin(inst, {"file", "center", "convexity", "invert"}, f, dollars.get(), 3);
    FrameGuard g(dyn_, dollars.get());
    warnLeafChildren(inst);
    // `convexity` only matters for OpenSCAD's preview
    bool center = a[1].isBool() && a[1].boolValue();
    bool invert = a[3].isBool() && a[3].boolValue();
    std::string path = resolveImportPath(textOf(a[0]), inst.loc);
    if (backgroundDepth_ > 0) return newNode(ir::NodeKind::Group, inst.loc);
    surface::HeightMap map;
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
        warn(inst.loc, "The file '" + path + "' couldn't be opened.");
        return newNode(ir::NodeKind::Group, inst.loc);
    }
    surface::ReadResult r;
    try {
        r = surface::readHeightMap(path, invert, map,
                                   [&](const std::string &m) { warn(inst.loc, m); });
    } catch (const InputFileError &e) {
        throw EvalError(inst.loc, std::string("surface(): ") + e.what());
    }
    if (r == surface::ReadResult::TooLarge)
        throw EvalError(inst.loc, "surface(): '" + path + "' holds more than " +
                                      std::to_string(surface::kMaxCells) + " heights");
    for (double v : map.values)
        if (!std::isfinite(v)) {
            warn(inst.loc, "surface(): '" + path + "' holds a height that is not a finite "
                           "number; the surface is left out");
            return newNode(ir::NodeKind::Group, inst.loc);
        }
    ir::Mesh mesh = surface::surfaceMesh(map, center);
    if (mesh.triangles.empty()) return newNode(ir::NodeKind::Group, inst.loc);
    mesh.name = "surface";
    mesh.loc = inst.loc;
    meshio::weldMesh(mesh);
    int index = addMesh(std::move(mesh));
    return primitive(ir::MeshPrim{index}, inst, f);
}

}  // namespace rt::scad
