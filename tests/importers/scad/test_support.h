// SPDX-License-Identifier: MIT
// Header-only helpers shared by the .scad importer tests (the suite globs only *_test.cpp).
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/ir/diagnostics.h"
#include "core/ir/scene_ir.h"
#include "importers/scad/scad_importer.h"

namespace rt::scad::test {

/// Folder with the test inputs (tests/importers/scad/data).
inline std::string dataDir() {
    return std::string(SCADRAY_SOURCE_DIR) + "/tests/importers/scad/data";
}

struct Imported {
    ir::Scene scene;
    DiagnosticSink diag;

    /// Echo output without the "ECHO: " prefix, in order.
    std::vector<std::string> echoes() const {
        std::vector<std::string> out;
        for (const auto &d : diag.all())
            if (d.severity == Severity::Note && d.message.rfind("ECHO: ", 0) == 0)
                out.push_back(d.message.substr(6));
        return out;
    }
    /// Warning messages, in order.
    std::vector<std::string> warnings() const {
        std::vector<std::string> out;
        for (const auto &d : diag.all())
            if (d.severity == Severity::Warning) out.push_back(d.message);
        return out;
    }
    bool hasWarning(const std::string &part) const {
        for (const auto &w : warnings())
            if (w.find(part) != std::string::npos) return true;
        return false;
    }
    /// The first warning containing `part`, or an empty diagnostic.
    Diagnostic warning(const std::string &part) const {
        for (const auto &d : diag.all())
            if (d.severity == Severity::Warning && d.message.find(part) != std::string::npos)
                return d;
        return {};
    }
};

/// Imports source text named `path` (default: a file in the data folder, so relative
/// include<>/use<> find the test libraries).
inline Imported importText(const std::string &src, const std::string &path = "",
                           const ImportOptions &opts = {}) {
    Imported r;
    r.scene = importScadSource(src, path.empty() ? dataDir() + "/inline.scad" : path, r.diag, opts);
    return r;
}

/// The single echo line of a program (fails the test when there is not exactly one).
inline std::string echoOf(const std::string &src) {
    Imported r = importText(src);
    auto e = r.echoes();
    EXPECT_EQ(e.size(), 1u) << src;
    return e.empty() ? std::string() : e[0];
}

/// A primitive with the product of the transforms above it.
struct PlacedPrimitive {
    const ir::Node *node;
    Mat4 worldFromObject;
};

inline void collectPrimitives(const ir::Node &n, const Mat4 &m, std::vector<PlacedPrimitive> &out) {
    Mat4 here = n.kind == ir::NodeKind::Transform ? m * n.matrix : m;
    if (n.kind == ir::NodeKind::Primitive) out.push_back({&n, here});
    for (const auto &c : n.children) collectPrimitives(*c, here, out);
}

/// Primitives of a subtree in tree order.
inline std::vector<PlacedPrimitive> primitives(const ir::Node &root) {
    std::vector<PlacedPrimitive> out;
    collectPrimitives(root, Mat4(), out);
    return out;
}

/// Whether a 2D shape's placeholder is left in the subtree (a finished scene has none).
inline bool anyPlaceholder(const ir::Node &n) {
    if (n.shape2d >= 0) return true;
    for (const auto &c : n.children)
        if (anyPlaceholder(*c)) return true;
    return false;
}

}  // namespace rt::scad::test
