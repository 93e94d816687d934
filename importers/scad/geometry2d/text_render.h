// SPDX-License-Identifier: MIT
// OpenSCAD 2021.01's text renderer (FreetypeRenderer, DrawingCallback, FontCache): a font found
// by fontconfig, the text shaped by HarfBuzz and each glyph's outline flattened to polygons.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "importers/scad/geometry2d/shape2d.h"

namespace rt::scad::text {

/// The glyph outlines are read at this character size (FreetypeRenderer::scale, in 26.6
/// points at 100 dpi, so about 2170 pixels to the em; hinted there, as FT_LOAD_DEFAULT does)
/// and divided by it; `size` then multiplies every point. [verified against the 2021.01
/// binary: 1e5 with hinting matches its points to the SVG export's 6 digits; 1000 (the
/// value before 2021.01, which multiplied the size into the character size) is off by up to
/// 0.3 units at size 10, and 1e5 unhinted by 8e-4]
constexpr double kFontScale = 1e5;
/// The divisor of HarfBuzz's positions (26.6 units): OpenSCAD's 64 * 16, times the ratio of
/// kFontScale to the 1000 it had before (see hbUnits in text_render.cpp).
constexpr double kPositionScale = 64.0 * 16.0 * (kFontScale / 1000);

/// Points one text() may make before it is refused (the curve segment count follows $fn, so
/// a huge $fn would otherwise exhaust memory): 20 million, about 320 MB of outline points.
constexpr size_t kMaxTextPoints = 20'000'000;

/// One text()'s parameters as FreetypeRenderer::Params holds them after text.cc.
struct TextParams {
    std::string text;
    double size = 10;
    double spacing = 1;
    std::string font;       ///< fontconfig pattern ("Name:style=Bold"); empty: Liberation Sans
    std::string direction;  ///< "ltr", "rtl", "ttb", "btt" (HarfBuzz reads the first letter)
    std::string language = "en";
    std::string script;  ///< ISO 15924 tag; empty: detected from the text
    std::string halign = "left";
    std::string valign = "baseline";
    long segments = 2;  ///< points per Bezier curve of an outline
};

/// A message OpenSCAD prints while rendering text, with whether it is one of scadray's own
/// (OpenSCAD is silent there).
struct TextMessage {
    std::string text;
    bool scadrayOnly = false;
    /// The parameter it is about (kFontArg, kHalignArg, kValignArg), else -1.
    int arg = -1;
};
constexpr int kFontArg = 2, kHalignArg = 6, kValignArg = 7;  ///< text()'s parameter order

/// What rendering one text() gives: one entry of outlines per glyph that has any (each set
/// filled non-zero, as OpenSCAD marks the glyph polygons sanitized), and the messages.
struct TextResult {
    std::vector<std::vector<Outline>> glyphs;
    std::vector<TextMessage> messages;
    size_t points = 0;     ///< outline points; above kMaxTextPoints none are made
    std::string fontUsed;  ///< family and style of the face found ("" when none)
};

/// FreetypeRenderer::detect_properties: the script (when not given) from the characters'
/// Unicode scripts, and the direction (when HarfBuzz cannot read the one given) from the
/// script's horizontal direction.
void detectProperties(TextParams &p);

/// Renders the text as OpenSCAD 2021.01 does (FreetypeRenderer::render), with the font files
/// a program registered (use <x.ttf>) added to fontconfig's application fonts.
TextResult renderText(const TextParams &p, const std::vector<std::string> &fontFiles);

}  // namespace rt::scad::text
