// SPDX-License-Identifier: MIT
// Geometry mapping tests: primitives, transforms (exact matrices), CSG, null vs empty
// children, color(), modifiers and the modules that are skipped.
#include <gtest/gtest.h>

#include <cmath>

#include "importers/scad/test_support.h"

namespace rt::scad::test {
namespace {

/// Top-level node `i` of a program.
const ir::Node &top(const Imported &r, size_t i = 0) {
    EXPECT_GT(r.scene.root->children.size(), i);
    return *r.scene.root->children.at(i);
}

Mat4 rows(std::initializer_list<std::initializer_list<double>> r) {
    Mat4 m;
    int i = 0;
    for (const auto &row : r) {
        int j = 0;
        for (double v : row) m.m[i][j++] = v;
        ++i;
    }
    return m;
}

const ir::Node &onlyPrimitive(const Imported &r) {
    auto p = primitives(*r.scene.root);
    EXPECT_EQ(p.size(), 1u);
    return *p.at(0).node;
}

ir::CylinderPrim cylinderOf(const std::string &call) {
    Imported r = importText(call + ";");
    return std::get<ir::CylinderPrim>(onlyPrimitive(r).shape);
}

TEST(Transforms, RotateNinetyIsExact) {
    Imported r = importText("rotate([90, 0, 0]) cube();");
    const ir::Node &t = top(r);
    ASSERT_EQ(t.kind, ir::NodeKind::Transform);
    EXPECT_EQ(t.matrix, rows({{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}}));
    EXPECT_EQ(t.children.size(), 1u);
}

TEST(Transforms, RotateVectorIsRzRyRx) {
    Imported r =
        importText("rotate([90, 0, 90]) cube(); rotate([90, 0, 0]) rotate([0, 0, 90]) cube();");
    EXPECT_EQ(top(r, 0).matrix, rows({{0, 0, 1, 0}, {1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0, 1}}));
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 2u);
    // The chained form is Rx(90) * Rz(90): a different matrix
    EXPECT_EQ(p[1].worldFromObject,
              rows({{0, -1, 0, 0}, {0, 0, -1, 0}, {1, 0, 0, 0}, {0, 0, 0, 1}}));
}

TEST(Transforms, RotateGeneralAnglesMatchProductOfAxisRotations) {
    Imported r =
        importText("rotate([30, 45, 60]) cube(); rotate([10]) cube(); rotate([10, 20]) cube();");
    EXPECT_EQ(top(r, 0).matrix, Mat4::rotateZ(60) * Mat4::rotateY(45) * Mat4::rotateX(30));
    EXPECT_EQ(top(r, 1).matrix, Mat4::rotateX(10));
    EXPECT_EQ(top(r, 2).matrix, Mat4::rotateY(20) * Mat4::rotateX(10));
}

TEST(Transforms, RotateScalarAndAxisAngle) {
    Imported r = importText(
        "rotate(90) cube(); rotate(a = 180, v = [1, 1, 0]) cube();"
        "rotate(33, [0, 0, 0]) cube(); rotate(a = [90, 0, 0], v = [1, 0, 0]) cube();");
    EXPECT_EQ(top(r, 0).matrix, rows({{0, -1, 0, 0}, {1, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}));
    Mat4 m = top(r, 1).matrix;
    Mat4 expected = rows({{0, 1, 0, 0}, {1, 0, 0, 0}, {0, 0, -1, 0}, {0, 0, 0, 1}});
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_NEAR(m.m[i][j], expected.m[i][j], 1e-15);
    EXPECT_TRUE(top(r, 2).matrix.isIdentity());
    EXPECT_TRUE(r.hasWarning("When parameter a is supplied as vector, v is ignored"));
}

TEST(Transforms, TranslateScaleMirror) {
    Imported r = importText(
        "translate([1, 2]) cube(); scale(2) cube(); scale([1, 2]) cube();"
        "mirror([1, 0, 0]) cube(); mirror([1, 1, 0]) cube();");
    EXPECT_EQ(top(r, 0).matrix, Mat4::translate(Vec3(1, 2, 0)));
    EXPECT_EQ(top(r, 1).matrix, Mat4::scale(Vec3(2, 2, 2)));
    EXPECT_EQ(top(r, 2).matrix, Mat4::scale(Vec3(1, 2, 1)));
    EXPECT_EQ(top(r, 3).matrix, Mat4::scale(Vec3(-1, 1, 1)));
    EXPECT_EQ(top(r, 4).matrix, rows({{0, -1, 0, 0}, {-1, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}));
}

TEST(Transforms, BadArgumentsWarnAndKeepIdentityOrDefault) {
    Imported r = importText(
        "translate(5) cube(); mirror() cube(); scale(\"a\") cube(); rotate(\"x\") cube();");
    EXPECT_TRUE(top(r, 0).matrix.isIdentity());
    EXPECT_TRUE(r.hasWarning("Unable to convert translate(5) parameter"));
    // mirror() without a vector mirrors X (transform.cc)
    EXPECT_EQ(top(r, 1).matrix, Mat4::scale(Vec3(-1, 1, 1)));
    EXPECT_TRUE(r.hasWarning("Unable to convert mirror(undef)"));
    EXPECT_TRUE(top(r, 2).matrix.isIdentity());
    EXPECT_TRUE(top(r, 3).matrix.isIdentity());
    EXPECT_TRUE(r.hasWarning("Problem converting rotate(a=\"x\") parameter"));
}

TEST(Transforms, NonFiniteTransformsAreIgnoredWithWarning) {
    Imported r = importText(
        "translate([1, 0/0, 0]) cube();\nscale([1, 1/0, 1]) cube();\n"
        "multmatrix([[1, 0, 0, 1/0]]) cube();\nrotate([0/0, 0, 0]) cube();");
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_TRUE(top(r, i).matrix.isFinite()) << i;
        EXPECT_TRUE(top(r, i).matrix.isIdentity()) << i;
    }
    Diagnostic w = r.warning("translate(");
    EXPECT_EQ(w.loc.line, 1);
    EXPECT_TRUE(r.hasWarning("multmatrix() has non-finite entries; ignored"));
}

TEST(Transforms, MultmatrixThreeByFourAndNormalisation) {
    Imported r = importText(
        "multmatrix([[1, 0, 0, 1], [0, 1, 0, 2], [0, 0, 1, 3]]) cube();"
        "multmatrix([[2, 0, 0, 2], [0, 2, 0, 0], [0, 0, 2, 0], [0, 0, 0, 2]]) cube();"
        "multmatrix([[1, 0.5], [0, 1]]) cube();");
    EXPECT_EQ(top(r, 0).matrix, Mat4::translate(Vec3(1, 2, 3)));
    EXPECT_EQ(top(r, 1).matrix, Mat4::translate(Vec3(1, 0, 0)));
    EXPECT_EQ(top(r, 2).matrix, rows({{1, 0.5, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}));
}

TEST(Transforms, WorldTransformOfNestedCalls) {
    Imported r = importText("translate([1, 0, 0]) rotate([0, 0, 90]) translate([1, 0, 0]) cube();");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(p[0].worldFromObject.transformPoint(Vec3(0, 0, 0)), Vec3(1, 1, 0));
}

TEST(Primitives, CubeForms) {
    auto box = [](const std::string &src) {
        return std::get<ir::BoxPrim>(onlyPrimitive(importText(src)).shape);
    };
    ir::BoxPrim b = box("cube();");
    EXPECT_EQ(b.min, Vec3(0, 0, 0));
    EXPECT_EQ(b.max, Vec3(1, 1, 1));
    b = box("cube(2);");
    EXPECT_EQ(b.max, Vec3(2, 2, 2));
    b = box("cube([1, 2, 3], true);");
    EXPECT_EQ(b.min, Vec3(-0.5, -1, -1.5));
    EXPECT_EQ(b.max, Vec3(0.5, 1, 1.5));
    // center must be a real boolean
    b = box("cube(size = [1, 2, 3], center = 1);");
    EXPECT_EQ(b.min, Vec3(0, 0, 0));
    // A 2-vector falls back to the default 1x1x1 with a warning
    Imported r = importText("cube([1, 2]);");
    EXPECT_EQ(std::get<ir::BoxPrim>(onlyPrimitive(r).shape).max, Vec3(1, 1, 1));
    EXPECT_TRUE(r.hasWarning("Unable to convert cube(size=[1, 2], ...) parameter"));
}

TEST(Primitives, SphereRadiusAndDiameter) {
    auto radius = [](const std::string &src) {
        return std::get<ir::SpherePrim>(onlyPrimitive(importText(src)).shape).radius;
    };
    EXPECT_EQ(radius("sphere();"), 1);
    EXPECT_EQ(radius("sphere(2);"), 2);
    EXPECT_EQ(radius("sphere(d = 3);"), 1.5);
    Imported r = importText("sphere(r = 1, d = 4);");
    EXPECT_EQ(std::get<ir::SpherePrim>(onlyPrimitive(r).shape).radius, 2);
    EXPECT_TRUE(r.hasWarning("Ignoring radius variable 'r' as diameter 'd' is defined too."));
}

TEST(Primitives, CylinderArgumentResolution) {
    struct Row {
        const char *call;
        double z0, z1, r1, r2;
    };
    const Row table[] = {
        {"cylinder()", 0, 1, 1, 1},
        {"cylinder(5)", 0, 5, 1, 1},
        {"cylinder(5, 2)", 0, 5, 2, 1},
        {"cylinder(5, 2, 0.5)", 0, 5, 2, 0.5},
        {"cylinder(4, 1, 1, true)", -2, 2, 1, 1},
        {"cylinder(h = 4, r = 1, center = true)", -2, 2, 1, 1},
        {"cylinder(h = 2, d = 3)", 0, 2, 1.5, 1.5},
        {"cylinder(r = 1, r1 = 2)", 0, 1, 2, 1},
        {"cylinder(d = 1, r2 = 0, h = 2)", 0, 2, 0.5, 0},
        {"cylinder(h = 3, d1 = 4, d2 = 2)", 0, 3, 2, 1},
        {"cylinder(h = 3, r1 = 1, d1 = 6)", 0, 3, 3, 1},
        {"cylinder(h = 3, r1 = 0, r2 = 2)", 0, 3, 0, 2},
        {"cylinder(h = 2, r = 1, center = 1)", 0, 2, 1, 1},
    };
    for (const Row &row : table) {
        ir::CylinderPrim c = cylinderOf(row.call);
        EXPECT_EQ(c.z0, row.z0) << row.call;
        EXPECT_EQ(c.z1, row.z1) << row.call;
        EXPECT_EQ(c.r1, row.r1) << row.call;
        EXPECT_EQ(c.r2, row.r2) << row.call;
    }
    EXPECT_TRUE(importText("cylinder(r = 1, r1 = 2);").hasWarning("Cylinder parameters ambiguous"));
}

TEST(Primitives, DegenerateSizesGiveEmptyGroupWithWarning) {
    const char *calls[] = {"cube(0)",
                           "cube([1, -1, 1])",
                           "cube(1/0)",
                           "cube([1, 0/0, 1])",
                           "sphere(0)",
                           "sphere(-1)",
                           "sphere(1/0)",
                           "cylinder(h = 0)",
                           "cylinder(h = 1, r = 0)",
                           "cylinder(h = 1, r1 = -1)",
                           "cylinder(h = 0/0)"};
    for (const char *call : calls) {
        Imported r = importText(std::string(call) + ";");
        ASSERT_EQ(r.scene.root->children.size(), 1u) << call;
        const ir::Node &n = top(r);
        EXPECT_EQ(n.kind, ir::NodeKind::Group) << call;
        EXPECT_TRUE(n.children.empty()) << call;
        EXPECT_TRUE(r.hasWarning("OpenSCAD makes empty geometry")) << call;
        EXPECT_EQ(r.warning("empty geometry").loc.col, 1) << call;
    }
}

TEST(Primitives, FragmentsAreRecordedAndClamped) {
    Imported r = importText("sphere(1, $fn = 20); $fa = 5; sphere(1, $fs = 0.001);");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(p[0].node->fragments.fn, 20);
    EXPECT_EQ(p[0].node->fragments.fa, 5);
    EXPECT_EQ(p[0].node->fragments.fs, 2);
    EXPECT_EQ(p[1].node->fragments.fs, 0.01);
    EXPECT_TRUE(r.hasWarning("$fs too small - clamping to 0.010000"));
}

TEST(Primitives, LeafWithChildrenWarns) {
    Imported r = importText("cube() sphere();");
    EXPECT_TRUE(r.hasWarning("module cube() does not support child modules"));
    EXPECT_EQ(r.scene.root->primitiveCount(), 1u);
}

/// Number of children of the first top-level node (a CSG operation).
size_t operands(const std::string &src) {
    Imported r = importText(src);
    return top(r).children.size();
}

TEST(Csg, NullChildrenAreDroppedEmptyOnesKept) {
    // Null: if(false) without else, echo()/assert() without children, `*`, children() at top
    EXPECT_EQ(operands("difference() { if (false) cube(5); sphere(1); }"), 1u);
    EXPECT_EQ(operands("difference() { echo(\"x\"); sphere(1); }"), 1u);
    EXPECT_EQ(operands("difference() { assert(true); sphere(1); }"), 1u);
    EXPECT_EQ(operands("difference() { *cube(5); sphere(1); }"), 1u);
    EXPECT_EQ(operands("difference() { children(); sphere(1); }"), 1u);
    // Empty: for over nothing, a module producing nothing, cube(0), union(){}, if/else with empty
    // else
    EXPECT_EQ(operands("difference() { for (i = []) cube(5); sphere(1); }"), 2u);
    EXPECT_EQ(operands("module m() {} difference() { m(); sphere(1); }"), 2u);
    EXPECT_EQ(operands("difference() { cube(0); sphere(1); }"), 2u);
    EXPECT_EQ(operands("difference() { union() {} sphere(1); }"), 2u);
    EXPECT_EQ(operands("difference() { if (false) cube(); else {} sphere(1); }"), 2u);
    EXPECT_EQ(operands("difference() { let(a = 1); sphere(1); }"), 2u);
    Imported r = importText("difference() { for (i = []) cube(5); sphere(1); }");
    EXPECT_EQ(top(r).kind, ir::NodeKind::Difference);
    EXPECT_EQ(top(r).children[0]->kind, ir::NodeKind::Group);
    EXPECT_TRUE(top(r).children[0]->children.empty());
}

TEST(Csg, OperationKinds) {
    Imported r = importText(
        "union() { cube(); } intersection() { cube(); sphere(); }"
        "render() cube(); group() cube();"
        "intersection_for (i = [0:2]) rotate(i * 60) cube(2, center = true);");
    EXPECT_EQ(top(r, 0).kind, ir::NodeKind::Union);
    EXPECT_EQ(top(r, 1).kind, ir::NodeKind::Intersection);
    EXPECT_EQ(top(r, 2).kind, ir::NodeKind::Group);
    EXPECT_EQ(top(r, 3).kind, ir::NodeKind::Group);
    const ir::Node &ifor = top(r, 4);
    EXPECT_EQ(ifor.kind, ir::NodeKind::Intersection);
    ASSERT_EQ(ifor.children.size(), 3u);
    for (const auto &c : ifor.children) EXPECT_EQ(c->kind, ir::NodeKind::Group);
}

TEST(Csg, UserModuleBecomesLabelledGroup) {
    Imported r = importText("module gear() cube(); gear();");
    EXPECT_EQ(top(r).kind, ir::NodeKind::Group);
    EXPECT_EQ(top(r).label, "module gear");
}

ir::Material materialOf(const Imported &r, size_t i = 0) {
    auto p = primitives(*r.scene.root);
    return r.scene.materials.at(p.at(i).node->material);
}

TEST(Color, NamesHexVectorsAndAlpha) {
    EXPECT_EQ(materialOf(importText("color(\"red\") cube();")).color, Rgb(1, 0, 0));
    EXPECT_EQ(materialOf(importText("color(\"DarkOliveGreen\") cube();")).color,
              Rgb(85 / 255.0, 107 / 255.0, 47 / 255.0));
    EXPECT_EQ(materialOf(importText("color(\"#f80\") cube();")).color, Rgb(1, 136 / 255.0, 0));
    EXPECT_EQ(materialOf(importText("color(\"#FF8000\") cube();")).color, Rgb(1, 128 / 255.0, 0));
    EXPECT_EQ(materialOf(importText("color([0.5]) cube();")).color, Rgb(0.5, 1, 1));
    ir::Material m = materialOf(importText("color(\"#ff000080\") cube();"));
    EXPECT_EQ(m.color, Rgb(1, 0, 0));
    EXPECT_DOUBLE_EQ(m.transmit, 1 - 128 / 255.0);
    EXPECT_DOUBLE_EQ(materialOf(importText("color(\"blue\", 0.25) cube();")).transmit, 0.75);
    EXPECT_DOUBLE_EQ(materialOf(importText("color([1, 0, 0, 0.5], 0.2) cube();")).transmit, 0.8);
    EXPECT_DOUBLE_EQ(materialOf(importText("color(\"transparent\") cube();")).transmit, 1);
}

TEST(Color, OutermostValidColorWins) {
    EXPECT_EQ(materialOf(importText("color(\"red\") color(\"blue\") cube();")).color, Rgb(1, 0, 0));
    Imported r = importText("color(\"nosuchcolor\") color(\"green\") cube();");
    EXPECT_EQ(materialOf(r).color, Rgb(0, 128 / 255.0, 0));
    EXPECT_TRUE(r.hasWarning("Unable to parse color \"nosuchcolor\""));
    // Without any color(), OpenSCAD's default face colour
    EXPECT_EQ(materialOf(importText("cube();")).color, ir::kOpenScadDefaultColor);
}

TEST(Color, MaterialsAreDeduplicated) {
    Imported r = importText("color(\"red\") cube(); color([1, 0, 0]) sphere(); cube(); sphere();");
    EXPECT_EQ(r.scene.materials.size(), 2u);
    auto p = primitives(*r.scene.root);
    EXPECT_EQ(p[0].node->material, p[1].node->material);
    EXPECT_EQ(p[2].node->material, p[3].node->material);
    EXPECT_NE(p[0].node->material, p[2].node->material);
}

TEST(Modifiers, DisableBackgroundRootHighlight) {
    Imported r = importText("*cube(); %sphere(); #cylinder(); cube(2);");
    EXPECT_EQ(r.scene.stats.disabledParts, 1);
    EXPECT_EQ(r.scene.stats.backgroundParts, 1);
    ASSERT_EQ(r.scene.root->children.size(), 2u);
    EXPECT_TRUE(top(r, 0).highlight);
    EXPECT_FALSE(top(r, 1).highlight);
    // `%` is excluded from the render, so the sphere becomes the minuend
    EXPECT_EQ(operands("difference() { %cube(); sphere(1); }"), 1u);
}

TEST(Modifiers, RootReplacesTheSceneWithoutItsParents) {
    Imported r =
        importText("color(\"red\") translate([10, 0, 0]) !cube(); sphere();\n!cylinder();");
    ASSERT_EQ(r.scene.root->children.size(), 1u);
    const ir::Node &n = top(r);
    EXPECT_EQ(n.kind, ir::NodeKind::Primitive);
    EXPECT_TRUE(std::holds_alternative<ir::BoxPrim>(n.shape));
    EXPECT_EQ(r.scene.materials.at(n.material).color, ir::kOpenScadDefaultColor);
    EXPECT_TRUE(r.hasWarning("More than one Root Modifier (!)"));
}

TEST(SkippedModules, WarnAndLeaveAnEmptyGroup) {
    // 3D formats import() does not read (OpenSCAD 2021.01 reads AMF and 3MF)
    for (const char *ext : {"amf", "3mf"}) {
        Imported r =
            importText(std::string("difference() { import(\"part.") + ext + "\"); sphere(); }");
        EXPECT_EQ(r.scene.stats.skippedModules, 1) << ext;
        Diagnostic w = r.warning("not supported");
        EXPECT_EQ(w.message,
                  std::string("import of .") + ext + " files is not supported yet; skipped");
        EXPECT_EQ(w.loc.col, 16) << ext;
        const ir::Node &diff = top(r);
        ASSERT_EQ(diff.children.size(), 2u) << ext;
        EXPECT_EQ(diff.children[0]->kind, ir::NodeKind::Group);
        EXPECT_TRUE(diff.children[0]->children.empty());
    }
}

TEST(SkippedModules, NoWarningInsideBackgroundOrDisabledParts) {
    // Both are left out of the scene, so nothing is lost; `%` is still evaluated (its echo
    // prints, as in OpenSCAD), `*` is not
    Imported r = importText(
        "%hull() cube(); %translate([1, 0, 0]) { import(\"x.amf\"); echo(\"bg\"); }\n"
        "*minkowski() cube(); *echo(\"off\"); %import(\"part.3mf\");\n"
        "%import(); import(\"part.amf\");");
    EXPECT_EQ(r.warnings(),
              (std::vector<std::string>{"import of .amf files is not supported yet; skipped"}));
    EXPECT_EQ(r.echoes(), (std::vector<std::string>{"\"bg\""}));
    EXPECT_EQ(r.scene.stats.skippedModules, 1);
    EXPECT_EQ(r.scene.stats.backgroundParts, 4);
    EXPECT_EQ(r.scene.stats.disabledParts, 2);
}

TEST(SourceLocations, NodesCarryTheirCallSite) {
    Imported r = importText("translate([1, 0, 0])\n  cube();");
    EXPECT_EQ(top(r).loc.line, 1);
    EXPECT_EQ(top(r).loc.col, 1);
    EXPECT_EQ(top(r).children[0]->loc.line, 2);
    EXPECT_EQ(top(r).children[0]->loc.col, 3);
    EXPECT_EQ(top(r).loc.fileName(), dataDir() + "/inline.scad");
}

}  // namespace
}  // namespace rt::scad::test

namespace rt::scad::test {
namespace {

TEST(Transforms, SingularTransformLeavesAnEmptyGroup) {
    Imported r = importText(
        "scale([1, 0, 1]) cube(); multmatrix([[1, 0, 0], [1, 0, 0], [0, 0, 1]]) cube();");
    for (size_t i = 0; i < 2; ++i) {
        const ir::Node &n = *r.scene.root->children.at(i);
        EXPECT_EQ(n.kind, ir::NodeKind::Group);
        EXPECT_TRUE(n.children.empty());
    }
    EXPECT_TRUE(r.hasWarning("scale() is singular and flattens its children to no volume"));
    EXPECT_EQ(r.scene.root->primitiveCount(), 0u);
}

}  // namespace
}  // namespace rt::scad::test
