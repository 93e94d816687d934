// SPDX-License-Identifier: MIT
// The families of builtins, each defined in its own file, and the passes they run on the scene.
#pragma once

#include "importers/scad/lang/builtin_table.h"
#include "importers/scad/lang/evaluator.h"

namespace rt::scad {

// Modules
BuiltinFamily primitives3dBuiltins();   ///< primitives3d.cpp
BuiltinFamily transformBuiltins();      ///< transforms.cpp
BuiltinFamily booleanBuiltins();        ///< booleans.cpp
BuiltinFamily shape2dBuiltins();        ///< shapes2d.cpp
BuiltinFamily extrusionBuiltins();      ///< extrusions.cpp
BuiltinFamily hullMinkowskiBuiltins();  ///< hull_minkowski.cpp
BuiltinFamily textBuiltins();           ///< text.cpp
BuiltinFamily importBuiltins();         ///< import.cpp (modules and the DXF functions)
BuiltinFamily metadataBuiltins();       ///< metadata.cpp

// Functions
BuiltinFamily mathFunctionBuiltins();    ///< math_functions.cpp
BuiltinFamily stringFunctionBuiltins();  ///< string_functions.cpp
BuiltinFamily listFunctionBuiltins();    ///< list_functions.cpp
BuiltinFamily typeFunctionBuiltins();    ///< type_functions.cpp

// Scene passes
/// Draws the 2D shapes left outside any extrusion as OpenSCAD's preview does
/// (placeholders2d.cpp).
void finish2dPass(Evaluator &ev, const SourceFile &main);
/// The camera set by the main file's $vpt/$vpr/$vpd/$vpf when no camera() gave one
/// (metadata.cpp).
void viewportCameraPass(Evaluator &ev, const SourceFile &main);

}  // namespace rt::scad
