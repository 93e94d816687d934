// SPDX-License-Identifier: MIT
// Sine and cosine of angles in degrees that are exact at multiples of 30, 45 and 90 degrees,
// as OpenSCAD's degree_trig.cc is, so rotate([90,0,0]) gives exact 0/1 matrices.
#pragma once

namespace rt {

double sinDegrees(double deg);
double cosDegrees(double deg);

}  // namespace rt
