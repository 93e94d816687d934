// SPDX-License-Identifier: MIT
// Builtin text(): glyph outlines as a 2D shape (OpenSCAD 2021.01 text.cc).
#include <cctype>
#include <climits>
#include <cmath>

#include "importers/scad/builtins/families.h"
#include "importers/scad/builtins/module_support.h"
#include "importers/scad/builtins/placeholders2d.h"
#include "importers/scad/geometry2d/text_render.h"

namespace rt::scad {

namespace {

/// Calc::GRID_FINE: below this radius a circle has 3 fragments.
constexpr double kGridFine = 0.00000095367431640625;

/// A double converted to int as x86-64 does it (cvttsd2si): out of range or NaN gives INT_MIN.
int x86Int(double d) {
    return d > -2147483649.0 && d < 2147483648.0 ? static_cast<int>(d) : INT_MIN;
}

/// text.cc: Calc::get_fragments_from_r(size, $fn, $fs, $fa) with the raw special variables
/// (no clamping of $fa and $fs, unlike circle()), then one point per eighth of those
/// fragments plus one, at least 2, for each Bezier curve of an outline.
long textSegments(double size, double fn, double fs, double fa) {
    int fragments;
    if (size < kGridFine || std::isinf(fn) || std::isnan(fn))
        fragments = 3;
    else if (fn > 0)
        fragments = x86Int(fn >= 3 ? fn : 3);
    else
        fragments = x86Int(std::ceil(std::fmax(std::fmin(360.0 / fa, size * 2 * M_PI / fs), 5)));
    return static_cast<long>(std::max(std::floor(fragments / 8) + 1, 2.0));
}

ir::NodePtr moduleText(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    // text, size and font may be given by position; the rest only by name
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = ev.bindBuiltin(
        inst,
        {"text", "size", "font", "direction", "language", "script", "halign", "valign", "spacing"},
        f, dollars.get(), 3);
    FrameGuard g(ev.dynamicScope(), dollars.get());
    warnLeafChildren(ev, inst);

    // Context::lookup_variable_with_default: a value of another type than the default's is
    // the default, silently in OpenSCAD (scadray says so)
    auto wrongType = [&](size_t i, const char *kind, const std::string &meaning) {
        if (a.given[i] && !a[i].isUndef())
            ev.warn(a.loc(i), "text(): " + std::string(a.names[i]) + " = " + a[i].toEchoString() +
                                  " is not " + kind + "; OpenSCAD 2021.01 " + meaning);
    };
    auto stringArg = [&](size_t i, const char *dflt) {
        if (a[i].isString()) return a[i].toStr();
        wrongType(i, "a string",
                  std::string("uses ") +
                      (*dflt ? "\"" + std::string(dflt) + "\"" : std::string("the default")));
        return std::string(dflt);
    };
    auto numberArg = [&](size_t i, double dflt) {
        if (a[i].isNumber()) return a[i].toNumber();
        wrongType(i, "a number", "uses " + formatNumber(dflt));
        return dflt;
    };
    text::TextParams p;
    if (a[0].isString())
        p.text = a[0].toStr();
    else
        wrongType(0, "a string", "draws nothing for it");
    p.size = numberArg(1, 10);
    p.font = stringArg(2, "");
    p.direction = stringArg(3, "");
    p.language = stringArg(4, "en");
    p.script = stringArg(5, "");
    p.halign = stringArg(6, "left");
    p.valign = stringArg(7, "baseline");
    p.spacing = numberArg(8, 1);

    // $fn, $fa, $fs as numbers (0 otherwise, as Value::toDouble gives)
    auto special = [&](const char *name) {
        const Value *v = ev.dynamicScope().lookup(Symbol::intern(name));
        return v && v->isNumber() ? v->toNumber() : 0.0;
    };
    p.segments = textSegments(p.size, special("$fn"), special("$fs"), special("$fa"));
    std::string direction = p.direction;
    text::detectProperties(p);
    // HarfBuzz reads a direction by its first letter, and OpenSCAD silently takes the script's
    // direction for one it cannot read
    std::string lower = direction;
    for (char &c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (!direction.empty() && lower != "ltr" && lower != "rtl" && lower != "ttb" && lower != "btt")
        ev.warn(a.loc(3),
                "text(): direction = \"" + direction +
                    "\" is not \"ltr\", \"rtl\", \"ttb\" or \"btt\"; OpenSCAD 2021.01 lays "
                    "the text out " +
                    p.direction);

    ir::NodePtr empty = ev.newNode(ir::NodeKind::Group, inst.loc);
    if (p.text.empty()) return empty;
    if (!std::isfinite(p.size) || p.size == 0 || !std::isfinite(p.spacing)) {
        bool size = !std::isfinite(p.size) || p.size == 0;
        ev.warn(a.loc(size ? 1 : 8),
                "text(): " +
                    std::string(size ? "size = " + formatNumber(p.size)
                                     : "spacing = " + formatNumber(p.spacing)) +
                    (size && p.size == 0 ? " gives no area" : " is not finite") +
                    "; OpenSCAD makes no 2D object of it");
        return empty;
    }

    // The glyphs, each a polygon set OpenSCAD marks sanitized, united by Clipper
    text::TextResult r = text::renderText(p, ev.scene().fontFiles);
    for (const text::TextMessage &m : r.messages)
        ev.warn(m.arg >= 0 ? a.loc(m.arg) : inst.loc, m.scadrayOnly ? "text(): " + m.text : m.text);
    if (r.points > text::kMaxTextPoints)
        throw EvalError(
            inst.loc, "text(): " + std::to_string(r.points) + " outline points, more than " +
                          std::to_string(text::kMaxTextPoints) + " (" + std::to_string(p.segments) +
                          " per curve from $fn, $fa, $fs)");
    ev.chargeGeometryWork(inst.loc, "text()", static_cast<double>(r.points));
    std::vector<clipper2d::PolygonSet> glyphs;
    for (auto &outlines : r.glyphs) glyphs.push_back({std::move(outlines), true});
    if (glyphs.empty()) return empty;
    return polygonSetNode(
        ev,
        withClipper(inst.loc, [&] { return clipper2d::apply(glyphs, clipper2d::BoolOp::Union); }),
        inst);
}

}  // namespace

BuiltinFamily textBuiltins() {
    static constexpr BuiltinModuleEntry kModules[] = {
        {"text", moduleText},
    };
    return {kModules, {}};
}

}  // namespace rt::scad
