// SPDX-License-Identifier: MIT
// Placeholder translation unit until the evaluator lands.
#include "importers/scad/scad_importer.h"
