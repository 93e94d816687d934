// SPDX-License-Identifier: MIT
// How builtins find and read the files they name: import(), surface() and the DXF forms.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "importers/scad/lang/evaluator.h"

namespace rt::scad {

/// Where and how a DXF file is read (import(), the file forms of the extrusions).
struct Dxf2dArgs {
    std::string layer;  ///< empty: all layers
    double originX = 0, originY = 0, scale = 1;
};

/// A parameter OpenSCAD reads with toString(): undef is "", other values as str() shows them.
std::string textOf(const Value &v);
/// The bytes of a file that import(), dxf_dim() or dxf_cross() names, through the input reader.
/// Nothing when it is missing, unreadable or a folder: OpenSCAD warns and goes on, and so does
/// the caller. A FIFO, device or socket (which would block, or never end) or a file past
/// `maxBytes` is a located error.
std::optional<std::string> readNamedFile(const std::string &path, uint64_t maxBytes,
                                         const std::string &who, const SourceLoc &loc);

/// The file an import() names: relative to the folder of the file holding the call, else
/// (deprecated, with OpenSCAD's warning) relative to the main file's folder.
std::string resolveImportPath(Evaluator &ev, const std::string &name, const SourceLoc &loc);
/// The layer, origin and scale of a DXF read by `who`, checked as OpenSCAD checks them.
Dxf2dArgs dxfArgs(Evaluator &ev, const std::string &who, const Value &layer, const Value &origin,
                  const SourceLoc &originLoc, const Value &scale, const SourceLoc &scaleLoc);
/// The file form of linear_extrude()/rotate_extrude(): the DXF named by `file`.
ir::NodePtr dxfFileShape(Evaluator &ev, const Value &file, const Dxf2dArgs &args,
                         const ModuleInstantiation &inst);
/// import() of a .dxf or .svg file named `name` (`a` bound as import() binds it).
ir::NodePtr importFile2d(Evaluator &ev, const std::string &ext, const std::string &name,
                         const BoundArgs &a, const ModuleInstantiation &inst);

}  // namespace rt::scad
