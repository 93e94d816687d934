// SPDX-License-Identifier: MIT
// How builtins find and read the files they name: paths, DXF arguments, 2D file imports.
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
#include "importers/scad/builtins/file_support.h"
#include "importers/scad/builtins/placeholders2d.h"
#include "importers/scad/formats/dxf.h"
#include "importers/scad/formats/surface.h"
#include "importers/scad/formats/svg.h"

namespace rt::scad {

namespace {

namespace fs = std::filesystem;

ir::NodePtr dxfShapeNode(Evaluator &ev, const std::string &path, const Dxf2dArgs &args,
                         const ModuleInstantiation &inst) {
    dxf::ReadOptions opts;
    opts.layer = args.layer;
    opts.originX = args.originX;
    opts.originY = args.originY;
    opts.scale = args.scale;
    opts.fragments = ev.currentFragments(inst.loc);
    dxf::Data data;
    Shape2d s;
    s.kind = Shape2dKind::Polygon;
    std::optional<std::string> bytes =
        readNamedFile(path, dxf::kMaxFileBytes, inst.name.str(), inst.loc);
    if (!bytes) {
        // OpenSCAD warns and goes on with empty geometry
        ev.warn(inst.loc, "Can't open DXF file '" + path + "'.");
    } else {
        dxf::read(*bytes, path, opts, data, [&](const std::string &m) { ev.warn(inst.loc, m); });
        for (Outline &o : dxf::outlines(data))
            if (o.size() > 2) s.outlines.push_back(std::move(o));
    }
    return shape2dNode(ev, std::move(s), inst);
}

ir::NodePtr importSvg(Evaluator &ev, const std::string &path, const BoundArgs &a,
                      const ModuleInstantiation &inst) {
    svg::Options opts;
    opts.center = a[9].isBool() && a[9].boolValue();
    if (a[10].isNumber()) {
        double dpi = a[10].toNumber();
        if (dpi >= svg::kMinDpi && std::isfinite(dpi))
            opts.dpi = dpi;
        else
            ev.warn(a.loc(10), "Invalid dpi value giving, using default of " +
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
            ev.warn(inst.loc, "import(): " + std::to_string(count) + " <" + element +
                                  "> element(s) of '" + path +
                                  "' left out (not drawn by OpenSCAD "
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
        ev.diag().report(Severity::Error, inst.loc, error);
    }
    return shape2dNode(ev, std::move(s), inst);
}

}  // namespace

std::string textOf(const Value &v) { return v.isUndef() ? std::string() : v.toString(false); }

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

std::string resolveImportPath(Evaluator &ev, const std::string &name, const SourceLoc &loc) {
    fs::path p(name);
    if (p.is_absolute()) return p.lexically_normal().string();
    fs::path dir = loc.file ? fs::path(*loc.file).parent_path() : fs::path();
    fs::path candidate = (dir / p).lexically_normal();
    std::error_code ec;
    if (!fs::exists(candidate, ec) && ev.hasMainFile()) {
        // 2021.01 lookup_file: the main file's folder as a deprecated fallback
        fs::path fallback = (fs::path(ev.mainFile().path).parent_path() / p).lexically_normal();
        if (fallback != candidate && fs::exists(fallback, ec)) {
            ev.warn(loc, "DEPRECATED: Imported file (" + name +
                             ") found in document root instead of relative to the importing "
                             "module. This behavior is deprecated");
            return fallback.string();
        }
    }
    return candidate.string();
}

Dxf2dArgs dxfArgs(Evaluator &ev, const std::string &who, const Value &layer, const Value &origin,
                  const SourceLoc &originLoc, const Value &scale, const SourceLoc &scaleLoc) {
    Dxf2dArgs d;
    d.layer = textOf(layer);
    if (!origin.isUndef()) {
        double x = 0, y = 0;
        if (getVec2(origin, x, y) && std::isfinite(x) && std::isfinite(y)) {
            d.originX = x;
            d.originY = y;
        } else {
            ev.warn(originLoc,
                    who + "(..., origin=" + origin.toEchoString() + ") could not be converted");
        }
    }
    // A scale that is not a positive number is 1, as in OpenSCAD
    if (scale.isNumber()) {
        double s = scale.toNumber();
        if (std::isfinite(s) && s > 0)
            d.scale = s;
        else if (!(s <= 0))
            ev.warn(scaleLoc,
                    who + "(..., scale=" + scale.toEchoString() + ") is not finite; using 1");
    }
    return d;
}

ir::NodePtr importFile2d(Evaluator &ev, const std::string &ext, const std::string &name,
                         const BoundArgs &a, const ModuleInstantiation &inst) {
    std::string path = resolveImportPath(ev, name, inst.loc);
    // Left out with its `%` subtree: the file need not be read
    if (ev.state().backgroundDepth > 0) return ev.newNode(ir::NodeKind::Group, inst.loc);
    if (ext == ".svg") return importSvg(ev, path, a, inst);
    // The deprecated layername= counts only when layer is undef
    const Value &layer = a[1].isUndef() ? a[8] : a[1];
    Dxf2dArgs d = dxfArgs(ev, "import", layer, a[3], a.loc(3), a[4], a.loc(4));
    return dxfShapeNode(ev, path, d, inst);
}

ir::NodePtr dxfFileShape(Evaluator &ev, const Value &file, const Dxf2dArgs &args,
                         const ModuleInstantiation &inst) {
    return dxfShapeNode(ev, resolveImportPath(ev, textOf(file), inst.loc), args, inst);
}

}  // namespace rt::scad
