// SPDX-License-Identifier: MIT
// POV-Ray writer: a golden file, and the rules that make POV-Ray render what scadray renders
// (handedness, merge for transparent solids only, one interior per solid, no single-child CSG,
// the matrix convention, every finish value explicit, only used materials).
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>

#include "core/ir/scene_defaults.h"
#include "exporters/povray/pov_format.h"
#include "exporters/povray/pov_writer.h"
#include "importers/scad/scad_importer.h"

namespace rt {
namespace {

std::string exportText(const std::string &scad, const std::string &name = "test.scad") {
    DiagnosticSink diag;
    scad::ImportOptions io;
    io.libraryPaths = {std::string(SCADRAY_SOURCE_DIR) + "/scenes"};
    ir::Scene scene = scad::importScadSource(scad, name, diag, io);
    ir::completeScene(scene, diag);
    return pov::writeSdl(scene, name);
}

int count(const std::string &text, const std::string &what) {
    int n = 0;
    for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
    return n;
}

TEST(PovFormat, NumbersRoundTripExactly) {
    for (double v : {0.1, 1.0 / 3, 1e-300, 123456789.123, -2.5e17})
        EXPECT_EQ(std::stod(pov::num(v)), v);
    EXPECT_EQ(pov::num(-0.0), "0");
    EXPECT_EQ(pov::num(0.5), "0.5");
}

TEST(PovFormat, MatrixIsTheTransposedColumnMatrix) {
    // p' = A p with A = translate(1,2,3) * scale(2,3,4): POV-Ray rows are images of the axes
    Mat4 a = Mat4::translate(Vec3(1, 2, 3)) * Mat4::scale(Vec3(2, 3, 4));
    a.m[0][1] = 0.5;  // a shear: x' depends on y
    EXPECT_EQ(pov::matrix(a), "matrix <2, 0, 0,  0.5, 3, 0,  0, 0, 4,  1, 2, 3>");
}

TEST(PovFormat, SimpleTransformsAreWrittenSimply) {
    EXPECT_EQ(pov::transform(Mat4::translate(Vec3(1, -2, 0.5))), "translate <1, -2, 0.5>");
    EXPECT_EQ(pov::transform(Mat4::scale(Vec3(2, 3, -1))), "scale <2, 3, -1>");
    EXPECT_EQ(pov::transform(Mat4::translate(Vec3(1, 0, 0)) * Mat4::scale(Vec3(2))),
              "matrix <2, 0, 0,  0, 2, 0,  0, 0, 2,  1, 0, 0>");
}

TEST(PovWriter, GoldenFile) {
    std::string text = exportText(R"(
use <scadray.scad>
camera(location=[10, -20, 8], look_at=[0, 0, 1], fov=35);
point_light(position=[5, -5, 10], color=[0.9, 0.8, 0.7], fade_distance=10, fade_power=2);
point_light(position=[-5, -5, 5], shadowless=true);
background(color=[0.1, 0.2, 0.3]);
render_settings(max_trace_level=7, adc_bailout=0.001);
material(color="red", phong=0.5, reflection=[0.1, 0.6], fresnel=true, ior=1.3)
    difference() {
        cube([2, 2, 2], center=true);
        rotate([0, 0, 45]) cylinder(r=0.5, h=3, center=true);
    }
material(color=[1, 1, 1], transmit=0.9, ior=1.5, fade_distance=2, fade_power=1)
    translate([3, 0, 1]) union() { sphere(1); translate([0, 0, 1]) sphere(0.7); }
)",
                                  "golden.scad");
    std::string path = std::string(SCADRAY_SOURCE_DIR) + "/tests/golden/export_basic.pov";
    if (std::getenv("UPDATE_GOLDEN")) {
        std::ofstream(path) << text;
        GTEST_SKIP() << "golden file rewritten: " << path;
    }
    std::ifstream in(path);
    ASSERT_TRUE(in) << "missing " << path << " (run with UPDATE_GOLDEN=1)";
    std::stringstream ss;
    ss << in.rdbuf();
    EXPECT_EQ(text, ss.str()) << "run with UPDATE_GOLDEN=1 if the change is intended";
}

TEST(PovWriter, CameraIsMadeRightHanded) {
    std::string t = exportText("use <scadray.scad> camera(location=[1,-9,3], fov=50); cube(1);");
    EXPECT_NE(t.find("right <-image_width / image_height, 0, 0>"), std::string::npos);
    EXPECT_NE(t.find("sky <0, 0, 1>"), std::string::npos);
    EXPECT_NE(t.find("angle 50\n"), std::string::npos);
    // The automatic camera's vertical field of view becomes POV-Ray's horizontal angle
    std::string a = exportText("cube(1);");
    EXPECT_NE(
        a.find("angle degrees(2 * atan(tan(radians(22.5 / 2)) * image_width / image_height))"),
        std::string::npos);
}

TEST(PovWriter, MergeOnlyForTransparentSolids) {
    std::string opaque =
        exportText("difference() { union() { cube(2); translate([1,1,1]) cube(2); } sphere(1); }");
    EXPECT_EQ(count(opaque, "merge {"), 0);
    EXPECT_EQ(count(opaque, "union {"), 1);
    std::string glass = exportText(
        "use <scadray.scad> material(transmit=0.8, ior=1.5) difference() { union() { cube(2); "
        "translate([1,1,1]) cube(2); } sphere(1); }");
    EXPECT_EQ(count(glass, "merge {"), 1);
    EXPECT_EQ(count(glass, "union {"), 0);
    // One interior for the whole solid, on the outermost object
    EXPECT_EQ(count(glass, "interior {"), 1);
    EXPECT_EQ(count(glass, "interior { ior 1.5 }"), 1);
}

TEST(PovWriter, NoSingleChildCsgAndTransformsCompose) {
    std::string t =
        exportText("translate([1,0,0]) union() { rotate([0,0,90]) difference() { cube(1); } }");
    EXPECT_EQ(count(t, "difference"), 0);
    EXPECT_EQ(count(t, "union"), 0);
    EXPECT_EQ(count(t, "box {"), 1);
    // rotate 90 about z then translate x: the x axis maps to +y, origin to (1,0,0)
    EXPECT_NE(t.find("matrix <0, 1, 0,  -1, 0, 0,  0, 0, 1,  1, 0, 0>"), std::string::npos) << t;
}

/// The finish block of the material declared `index`-th.
std::string finishOf(const std::string &t, int index) {
    size_t at = t.find("#declare Material_" + std::to_string(index) + " = texture");
    if (at == std::string::npos) return "";
    size_t begin = t.find("finish {", at), end = t.find("\n    }\n", begin);
    return t.substr(begin, end - begin);
}

TEST(PovWriter, FinishTermsOnlyWhereTheyHaveAnEffectAndOnlyUsedMaterials) {
    std::string t = exportText(
        "use <scadray.scad> color(\"red\") cube(1);\n"
        "material(phong=0.3) translate([3,0,0]) sphere(1);\n"
        "material(phong=0.3, phong_size=10, specular=0.2, roughness=0.01, metallic=0.5, "
        "brilliance=2, emission=0.2, reflection=[0.1, 0.5], fresnel=true, reflection_falloff=2, "
        "reflection_exponent=0.8, conserve_energy=true) translate([6,0,0]) sphere(1);\n"
        "material(diffuse=0, brilliance=3, roughness=0.2, metallic=1) translate([9,0,0]) "
        "sphere(1);\n"
        "%material(color=\"blue\") translate([12,0,0]) sphere(1);\n"
        "material(color=\"green\", reflection=0.4) intersection() { sphere(1); "
        "translate([5,0,0]) sphere(1); }");
    // ambient and diffuse always: POV-Ray's defaults (0.1, 0.6) differ from ours
    EXPECT_EQ(count(t, "        ambient "), 5);
    EXPECT_EQ(count(t, "        diffuse "), 5);
    // Nothing at POV-Ray's default or without effect
    std::string plain = finishOf(t, 0), phong = finishOf(t, 1), full = finishOf(t, 2),
                dark = finishOf(t, 3);
    for (const std::string &f : {plain, phong, dark})
        for (const char *kw : {"emission", "phong_size", "specular", "roughness", "metallic",
                               "reflection", "brilliance", "conserve_energy"})
            EXPECT_EQ(count(f, kw), 0) << kw << " in " << f;
    EXPECT_EQ(count(phong, "phong 0.3"), 1);
    EXPECT_EQ(count(plain, "phong"), 0);
    // Every term that changes the picture
    for (const char *kw : {"emission rgb <0.2, 0.2, 0.2>", "brilliance 2", "phong 0.3",
                           "phong_size 10", "specular 0.2", "roughness 0.01", "metallic 0.5",
                           "rgb <0.1, 0.1, 0.1>, rgb <0.5, 0.5, 0.5>", "fresnel on", "falloff 2",
                           "exponent 0.8", "conserve_energy"})
        EXPECT_EQ(count(full, kw), 1) << kw << " not in " << full;
    // A `%` part's material is not declared; an empty intersection's still is (POV-Ray gets
    // the CSG as written)
    EXPECT_EQ(count(t, "#declare Material_"), 5);
    EXPECT_EQ(count(t, "rgbft <0, 0, 1, 0, 0>"), 0);
    EXPECT_EQ(count(t, "rgbft <1, 0, 0, 0, 0>"), 1);
}

TEST(PovWriter, AreaLightsKeepEveryGridSetting) {
    std::string t = exportText(
        "use <scadray.scad> cube(1);\n"
        "area_light(position=[0,0,9], axis1=[2,0,0], axis2=[0,3,0], samples=[5,3], adaptive=1);\n"
        "translate([1,0,0]) area_light(position=[0,0,9], axis1=[2,0,0], axis2=[0,2,0], "
        "samples=[4,4], jitter=true, orient=true);");
    EXPECT_EQ(count(t, "area_light <2, 0, 0>, <0, 3, 0>, 5, 3\n    adaptive 1\n}"), 1);
    EXPECT_EQ(count(t, "<1, 0, 9>"), 1);  // moved by the transform around the call
    EXPECT_EQ(count(t, "area_light <2, 0, 0>, <0, 2, 0>, 4, 4\n    adaptive 100\n    jitter"), 1);
    // POV-Ray's orient works only with circular (it warns and adds it otherwise)
    EXPECT_EQ(count(t, "    circular\n    orient\n"), 1);
}

TEST(PovWriter, BlurredMaterialsAreSharpWithAComment) {
    std::string t = exportText(
        "use <scadray.scad> material(reflection=0.5, glossy=4) cube(1);\n"
        "material(transmit=0.9, ior=1.5, frosted=3, blur_lobe=\"phong\") sphere(1);");
    EXPECT_EQ(count(t,
                    "// scadray: glossy reflection spread 4 deg (normal lobe) cannot be "
                    "expressed in POV-Ray 3.7; written as the sharp mirror reflection"),
              1);
    EXPECT_EQ(count(t,
                    "// scadray: frosted refraction spread 3 deg (phong lobe) cannot be "
                    "expressed in POV-Ray 3.7; written as the sharp refraction"),
              1);
    EXPECT_EQ(count(t, "rgb <0.5, 0.5, 0.5>, rgb <0.5, 0.5, 0.5>"),
              1);  // the reflection itself stays
    EXPECT_EQ(count(t, "ior 1.5"), 1);
}

TEST(PovWriter, IniRendersHeadlessLinear16BitSupersampled) {
    pov::IniOptions o;
    o.povFile = "a.pov";
    o.outputFile = "a.png";
    o.width = 320;
    o.height = 240;
    o.supersample = 3;
    std::string ini = pov::writeIni(o);
    for (const char *line : {"Width=960", "Height=720", "Antialias=Off", "Bits_Per_Color=16",
                             "File_Gamma=1.0", "Display=Off", "Output_File_Type=N"})
        EXPECT_NE(ini.find(line), std::string::npos) << line;
}

}  // namespace
}  // namespace rt
