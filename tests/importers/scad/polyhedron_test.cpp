// SPDX-License-Identifier: MIT
// polyhedron(): OpenSCAD's clockwise faces become outward IR meshes; bad faces warn and are
// skipped; 2-vector points, the deprecated triangles=, polygons and materials.
#include <gtest/gtest.h>

#include "core/ir/scene_defaults.h"
#include "importers/mesh/mesh_reader.h"
#include "importers/scad/test_support.h"

namespace rt::scad::test {
namespace {

/// The tetrahedron of docs/design/openscad-subset.md section 8.5: faces clockwise seen from
/// outside.
const std::string kPoints = "[[0, 0, 0], [10, 0, 0], [0, 10, 0], [0, 0, 10]]";
const std::string kFaces = "[[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]";

const ir::Node &onlyPrimitive(const Imported &r) {
    auto p = primitives(*r.scene.root);
    EXPECT_EQ(p.size(), 1u);
    return *p.at(0).node;
}

const ir::Mesh &meshOf(const Imported &r, const ir::Node &n) {
    const auto &prim = std::get<ir::MeshPrim>(n.shape);
    EXPECT_GE(prim.mesh, 0);
    EXPECT_LT(prim.mesh, static_cast<int>(r.scene.meshes.size()));
    return *r.scene.meshes.at(prim.mesh);
}

const ir::Mesh &onlyMesh(const Imported &r) { return meshOf(r, onlyPrimitive(r)); }

TEST(Polyhedron, ClockwiseTetrahedronBecomesAnOutwardClosedMesh) {
    Imported r = importText("polyhedron(" + kPoints + ", " + kFaces + ");");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().at(0);
    const ir::Node &n = onlyPrimitive(r);
    EXPECT_EQ(n.loc.line, 1);
    EXPECT_EQ(n.loc.col, 1);
    ASSERT_EQ(r.scene.meshes.size(), 1u);
    const ir::Mesh &m = meshOf(r, n);
    EXPECT_EQ(m.loc.line, 1);
    EXPECT_EQ(m.positions.size(), 4u);
    EXPECT_EQ(m.triangles.size(), 4u);
    EXPECT_TRUE(ir::analyzeMesh(m).oriented());
    EXPECT_NEAR(meshio::signedVolume(m), 1000.0 / 6, 1e-9);
    EXPECT_EQ(m.bounds().min, Vec3(0, 0, 0));
    EXPECT_EQ(m.bounds().max, Vec3(10, 10, 10));
    // Every normal points away from the centroid
    Vec3 centroid(2.5, 2.5, 2.5);
    for (const auto &t : m.triangles) {
        const Vec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
        EXPECT_GT(dot(cross(b - a, c - a), a - centroid), 0);
    }
}

TEST(Polyhedron, CounterClockwiseFacesGiveAnInsideOutWarning) {
    Imported r =
        importText("polyhedron(" + kPoints + ", [[2, 1, 0], [1, 3, 0], [3, 2, 0], [2, 3, 1]]);");
    const ir::Mesh &m = onlyMesh(r);
    EXPECT_NEAR(meshio::signedVolume(m), -1000.0 / 6, 1e-9);
    EXPECT_EQ(r.warning("inside out").message,
              "polyhedron() is inside out (its enclosed volume is negative); OpenSCAD needs a "
              "closed surface whose faces are listed clockwise seen from outside");
}

TEST(Polyhedron, MaterialIsResolvedLikeOtherPrimitives) {
    Imported r = importText("color(\"red\") { polyhedron(" + kPoints + ", " + kFaces +
                            "); cube(); }\npolyhedron(" + kPoints + ", " + kFaces + ");");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 3u);
    EXPECT_EQ(p[0].node->material, p[1].node->material);
    EXPECT_EQ(r.scene.materials.at(p[0].node->material).color, Rgb(1, 0, 0));
    EXPECT_EQ(r.scene.materials.at(p[2].node->material).color, ir::kOpenScadDefaultColor);
    // Each call has its own mesh
    EXPECT_EQ(r.scene.meshes.size(), 2u);
}

TEST(Polyhedron, OutOfRangeIndexWarnsAndSkipsThatFace) {
    Imported r =
        importText("polyhedron(" + kPoints + ",\n  [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 9]]);");
    Diagnostic w = r.warning("out of bounds");
    EXPECT_EQ(w.message, "Point index 9 is out of bounds (from faces[3][2]); face skipped");
    EXPECT_EQ(w.loc.line, 2);
    EXPECT_EQ(w.loc.col, 3);
    const ir::Mesh &m = onlyMesh(r);
    EXPECT_EQ(m.triangles.size(), 3u);
    // The hole is reported too
    EXPECT_TRUE(r.hasWarning("polyhedron() is not closed (3 edges belong to one triangle only"));
}

TEST(Polyhedron, BadFacesWarnAndAreSkipped) {
    Imported r = importText("polyhedron(" + kPoints +
                            ", [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2], [1, 1, 2], 5, "
                            "[0, \"a\", 1], [0, -1, 2], [3, 3]]);");
    EXPECT_TRUE(r.hasWarning("faces[4] has fewer than 3 distinct points; face skipped"));
    EXPECT_TRUE(r.hasWarning("faces[5] = 5 is not a vector of point indices; face skipped"));
    EXPECT_TRUE(r.hasWarning("faces[6][1] = \"a\" is not a point index; face skipped"));
    EXPECT_TRUE(r.hasWarning("Point index -1 is out of bounds (from faces[7][1]); face skipped"));
    EXPECT_TRUE(r.hasWarning("faces[8] has fewer than 3 distinct points; face skipped"));
    EXPECT_EQ(r.warnings().size(), 5u);
    EXPECT_TRUE(ir::analyzeMesh(onlyMesh(r)).oriented());
}

TEST(Polyhedron, TwoVectorPointsHaveZeroZ) {
    Imported r = importText("polyhedron([[0, 0], [10, 0], [0, 10], [0, 0, 10]], " + kFaces + ");");
    EXPECT_TRUE(r.warnings().empty());
    const ir::Mesh &m = onlyMesh(r);
    EXPECT_EQ(m.bounds().min, Vec3(0, 0, 0));
    EXPECT_NEAR(meshio::signedVolume(m), 1000.0 / 6, 1e-9);
}

TEST(Polyhedron, DeprecatedTrianglesIsUsedOnlyWithoutFaces) {
    Imported r = importText("polyhedron(points = " + kPoints + ",\n  triangles = " + kFaces + ");");
    Diagnostic w = r.warning("DEPRECATED");
    EXPECT_EQ(w.message,
              "DEPRECATED: polyhedron(triangles=[]) will be removed in future releases. Use "
              "polyhedron(faces=[]) instead.");
    EXPECT_EQ(w.loc.line, 2);
    EXPECT_NEAR(meshio::signedVolume(onlyMesh(r)), 1000.0 / 6, 1e-9);

    // With faces given, triangles is ignored without a word
    Imported both = importText("polyhedron(" + kPoints + ", " + kFaces +
                               ", triangles = [[0, 1, 2]], convexity = 4);");
    EXPECT_TRUE(both.warnings().empty());
    EXPECT_EQ(onlyMesh(both).triangles.size(), 4u);
}

TEST(Polyhedron, QuadsAndConcaveFacesAreTriangulated) {
    // OpenSCAD manual's cube: quads listed clockwise from outside
    Imported cube = importText(
        "polyhedron([[0,0,0],[10,0,0],[10,7,0],[0,7,0],[0,0,5],[10,0,5],[10,7,5],[0,7,5]],\n"
        "  [[0,1,2,3],[4,5,1,0],[7,6,5,4],[5,6,2,1],[6,7,3,2],[7,4,0,3]]);");
    EXPECT_TRUE(cube.warnings().empty());
    const ir::Mesh &m = onlyMesh(cube);
    EXPECT_EQ(m.triangles.size(), 12u);
    EXPECT_TRUE(ir::analyzeMesh(m).oriented());
    EXPECT_NEAR(meshio::signedVolume(m), 350.0, 1e-9);

    // A prism over the concave pentagon (0,0) (4,0) (4,4) (2,1) (0,4) of area 10
    Imported prism = importText(
        "p = [[0,0],[4,0],[4,4],[2,1],[0,4]];\n"
        "polyhedron(concat(p, [for (q = p) [q.x, q.y, 2]]),\n"
        "  concat([[0,1,2,3,4], [9,8,7,6,5]], [for (i = [0:4]) [i, i + 5, (i + 1) % 5 + 5, "
        "(i + 1) % 5]]));");
    EXPECT_TRUE(prism.warnings().empty()) << prism.warnings().at(0);
    const ir::Mesh &pm = onlyMesh(prism);
    EXPECT_EQ(pm.triangles.size(), 16u);
    EXPECT_TRUE(ir::analyzeMesh(pm).oriented());
    EXPECT_EQ(ir::analyzeMesh(pm).degenerateTriangles, 0u);
    EXPECT_NEAR(meshio::signedVolume(pm), 20.0, 1e-9);
    // Volume and topology alone would not notice a fan over the notch: triangles sticking out
    // and folded back cancel. Every cap triangle must face out.
    int capTriangles = 0;
    for (const auto &t : pm.triangles) {
        const Vec3 &a = pm.positions[t[0]], &b = pm.positions[t[1]], &c = pm.positions[t[2]];
        if (a.z != b.z || a.z != c.z) continue;
        ++capTriangles;
        double nz = cross(b - a, c - a).z;
        EXPECT_GT(a.z == 2 ? nz : -nz, 0) << a.toString() << b.toString() << c.toString();
    }
    EXPECT_EQ(capTriangles, 6);
}

TEST(Polyhedron, EmptyResultsAreEmptyGroupsWithAWarning) {
    for (const std::string &call :
         {std::string("polyhedron();"), "polyhedron(" + kPoints + ");",
          "polyhedron(5, " + kFaces + ");", "polyhedron(" + kPoints + ", 7);",
          std::string("polyhedron([[0, 0, \"x\"], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]]);"),
          "polyhedron(" + kPoints + ", [[0, 0, 1]]);"}) {
        Imported r = importText(call);
        EXPECT_EQ(r.scene.root->primitiveCount(), 0u) << call;
        ASSERT_EQ(r.scene.root->children.size(), 1u) << call;
        EXPECT_EQ(r.scene.root->children[0]->kind, ir::NodeKind::Group);
        EXPECT_TRUE(r.scene.meshes.empty()) << call;
        ASSERT_FALSE(r.warnings().empty()) << call;
        EXPECT_NE(r.warnings().back().find("OpenSCAD makes empty geometry"), std::string::npos)
            << r.warnings().back();
    }
    Imported r = importText("polyhedron([[0, 0, 1/0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]]);");
    EXPECT_EQ(r.warnings().at(0),
              "polyhedron(): points[0] = [0, 0, inf] is not a vector of 3 finite numbers; "
              "OpenSCAD makes empty geometry");
}

TEST(Polyhedron, ArgumentsAndModifiers) {
    Imported r = importText("polyhedron(" + kPoints + ", " + kFaces + ", 1, 2) cube();");
    EXPECT_TRUE(r.hasWarning("Too many unnamed arguments supplied"));
    EXPECT_TRUE(r.hasWarning("module polyhedron() does not support child modules"));
    EXPECT_EQ(r.scene.root->primitiveCount(), 1u);
    // A `%` part is left out, and so is its mesh
    Imported bg = importText("%polyhedron(" + kPoints + ", " + kFaces + ");");
    EXPECT_EQ(bg.scene.root->primitiveCount(), 0u);
    EXPECT_TRUE(bg.scene.meshes.empty());
    EXPECT_EQ(bg.scene.stats.backgroundParts, 1);
}

}  // namespace
}  // namespace rt::scad::test
