// SPDX-License-Identifier: MIT
// Metadata module tests: scenes/scadray.scad, camera/lights/settings, material resolution,
// the $vp* viewport camera, and validation of metadata arguments.
#include <gtest/gtest.h>

#include "core/ir/scene_defaults.h"
#include "importers/scad/test_support.h"

namespace rt::scad::test {
namespace {

const std::string kUse = "use <scadray.scad>\n";

ir::Material materialOf(const Imported &r, size_t i = 0) {
    auto p = primitives(*r.scene.root);
    return r.scene.materials.at(p.at(i).node->material);
}

TEST(MetadataLibrary, FullSceneThroughUse) {
    DiagnosticSink diag;
    ir::Scene s = importScad(dataDir() + "/metadata_scene.scad", diag);
    EXPECT_EQ(diag.count(Severity::Warning), 0);
    ASSERT_TRUE(s.camera);
    EXPECT_EQ(s.camera->location, Vec3(1, -8, 4));
    EXPECT_EQ(s.camera->lookAt, Vec3(0, 0, 1));
    EXPECT_EQ(s.camera->sky, Vec3(0, 0, 1));
    EXPECT_EQ(s.camera->fov, 50);
    EXPECT_EQ(s.camera->fovAxis, ir::FovAxis::Horizontal);
    EXPECT_EQ(s.camera->source, ir::CameraSource::Explicit);
    EXPECT_EQ(s.camera->loc.line, 3);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].position, Vec3(5, -5, 8));
    EXPECT_EQ(s.lights[0].color, Rgb(1, 1, 1));
    EXPECT_EQ(s.lights[0].fadeDistance, 10);
    EXPECT_EQ(s.lights[0].fadePower, 2);
    EXPECT_FALSE(s.lights[0].shadowless);
    EXPECT_EQ(s.settings.background, Rgb(0.1, 0.1, 0.2));
    EXPECT_EQ(s.settings.maxTraceLevel, 8);
    EXPECT_EQ(s.settings.adcBailout, 0.01);
    EXPECT_EQ(s.settings.ambientLight, Rgb(0.5));
    ASSERT_EQ(s.materials.size(), 1u);
    const ir::Material &m = s.materials[0];
    EXPECT_EQ(m.color, Rgb(1, 0, 0));
    EXPECT_EQ(m.transmit, 0.1);
    EXPECT_EQ(m.finish.ambient, 0.1);
    EXPECT_EQ(m.finish.diffuse, 0.7);
    EXPECT_EQ(m.finish.phong, 0.5);
    EXPECT_EQ(m.finish.phongSize, 60);
    EXPECT_EQ(m.finish.reflectionMin, Rgb(0));
    EXPECT_EQ(m.finish.reflectionMax, Rgb(0.3));
    EXPECT_TRUE(m.finish.fresnel);
    EXPECT_TRUE(m.finish.conserveEnergy);
    EXPECT_EQ(m.interior.ior, 1.5);
    EXPECT_EQ(m.interior.fadeDistance, 1);
    EXPECT_EQ(m.interior.fadePower, 2);
    EXPECT_EQ(m.interior.fadeColor, Rgb(0, 0, 1));
    EXPECT_EQ(m.loc.line, 7);
}

TEST(MetadataLibrary, DefaultsEqualTheIrDefaults) {
    Imported r = importText(
        kUse + "camera(); point_light(); material() cube(); background(); render_settings();");
    EXPECT_TRUE(r.warnings().empty());
    ir::Camera cam;
    ASSERT_TRUE(r.scene.camera);
    EXPECT_EQ(r.scene.camera->location, cam.location);
    EXPECT_EQ(r.scene.camera->lookAt, cam.lookAt);
    EXPECT_EQ(r.scene.camera->sky, cam.sky);
    EXPECT_EQ(r.scene.camera->fov, cam.fov);
    ir::Light light;
    ASSERT_EQ(r.scene.lights.size(), 1u);
    EXPECT_EQ(r.scene.lights[0].position, Vec3(10, -10, 10));
    EXPECT_EQ(r.scene.lights[0].color, light.color);
    ir::Material m;
    EXPECT_TRUE(materialOf(r).sameAppearance(m));
    ir::Settings s;
    EXPECT_EQ(r.scene.settings.background, s.background);
    EXPECT_EQ(r.scene.settings.maxTraceLevel, s.maxTraceLevel);
    EXPECT_EQ(r.scene.settings.adcBailout, s.adcBailout);
    EXPECT_EQ(r.scene.settings.ambientLight, s.ambientLight);
}

TEST(MetadataLibrary, MissingLibraryWarnsButIsHonoured) {
    Imported r = importText("material(ior = 1.5) sphere();\npoint_light(position = [1, 2, 3]);");
    Diagnostic w = r.warning("scadray metadata module");
    EXPECT_EQ(w.message,
              "`material` is a scadray metadata module but scadray.scad is not used: OpenSCAD will "
              "ignore it and drop its children; add `use <scadray.scad>`");
    EXPECT_EQ(w.loc.line, 1);
    EXPECT_EQ(w.loc.col, 1);
    EXPECT_EQ(materialOf(r).interior.ior, 1.5);
    ASSERT_EQ(r.scene.lights.size(), 1u);
    EXPECT_EQ(r.scene.lights[0].position, Vec3(1, 2, 3));
    EXPECT_TRUE(r.hasWarning("`point_light` is a scadray metadata module"));
}

TEST(MetadataLibrary, IncludeWorksToo) {
    Imported r = importText("include <scadray.scad>\nmaterial(ior = 1.3) sphere();");
    EXPECT_TRUE(r.warnings().empty());
    EXPECT_EQ(materialOf(r).interior.ior, 1.3);
}

TEST(MetadataLibrary, SameNameFromAnotherFileIsAUserModule) {
    Imported r = importText("use <lib/fake_material.scad>\nmaterial(\"x\") sphere();");
    EXPECT_EQ(r.echoes(), std::vector<std::string>{"user_material = \"x\""});
    EXPECT_TRUE(materialOf(r).sameAppearance(ir::Material()));
    EXPECT_FALSE(r.hasWarning("metadata"));
}

TEST(MetadataLibrary, UnknownArgumentWarnsLikeOpenScad) {
    Imported r = importText(kUse + "material(reflect = 0.5) cube();");
    EXPECT_TRUE(r.hasWarning("variable reflect not specified as parameter"));
}

TEST(Lights, PositionFollowsEnclosingTransforms) {
    Imported r = importText(
        kUse +
        "translate([1, 2, 3]) rotate([0, 0, 90]) point_light(position = [1, 0, 0]);\n"
        "module lamp() translate([0, 0, 10]) children();\n"
        "lamp() point_light(position = [0, 0, 0], color = \"#ff0000\", shadowless = true);");
    ASSERT_EQ(r.scene.lights.size(), 2u);
    EXPECT_EQ(r.scene.lights[0].position, Vec3(1, 3, 3));
    EXPECT_EQ(r.scene.lights[1].position, Vec3(0, 0, 10));
    EXPECT_EQ(r.scene.lights[1].color, Rgb(1, 0, 0));
    EXPECT_TRUE(r.scene.lights[1].shadowless);
    EXPECT_EQ(r.scene.lights[1].loc.line, 4);
}

TEST(Lights, AreaLightGridAxesAndFlags) {
    Imported r = importText(
        kUse +
        "translate([0, 0, 1]) rotate([0, 0, 90]) area_light(position = [1, 0, 5], axis1 = [2, 0, "
        "0],\n"
        "    axis2 = [0, 3, 0], samples = [5, 3], adaptive = 2, jitter = true, circular = true);\n"
        "area_light();");
    ASSERT_EQ(r.scene.lights.size(), 2u);
    const ir::Light &l = r.scene.lights[0];
    EXPECT_TRUE(l.area);
    EXPECT_NEAR(length(l.position - Vec3(0, 1, 6)), 0, 1e-12);
    EXPECT_NEAR(length(l.areaLight.axis1 - Vec3(0, 2, 0)), 0, 1e-12);  // axes turn with it
    EXPECT_NEAR(length(l.areaLight.axis2 - Vec3(-3, 0, 0)), 0, 1e-12);
    EXPECT_EQ(l.areaLight.n1, 5);
    EXPECT_EQ(l.areaLight.n2, 3);
    EXPECT_EQ(l.areaLight.adaptive, 2);
    EXPECT_TRUE(l.areaLight.jitter);
    EXPECT_TRUE(l.areaLight.circular);
    EXPECT_FALSE(l.areaLight.orient);
    // Defaults: POV-Ray's (no jitter, full subdivision), a 5 x 5 grid
    const ir::Light &d = r.scene.lights[1];
    EXPECT_EQ(d.areaLight.n1, 5);
    EXPECT_EQ(d.areaLight.adaptive, 100);
    EXPECT_FALSE(d.areaLight.jitter);
}

TEST(Lights, BadAreaLightArgumentsWarnOrFail) {
    Imported r = importText(kUse + "area_light(samples = [0, 2.5], adaptive = -1);");
    EXPECT_TRUE(r.hasWarning("area_light(): samples = [0, 2.5] is not [n1, n2]"));
    EXPECT_TRUE(r.hasWarning("area_light(): adaptive = -1 is not a whole number from 0 to 100"));
    EXPECT_EQ(r.scene.lights.at(0).areaLight.n1, 5);
    try {
        importText(kUse + "area_light(samples = [1, 4], circular = true);");
        FAIL() << "expected EvalError";
    } catch (const EvalError &e) {
        EXPECT_EQ(e.loc().line, 2);
        EXPECT_NE(std::string(e.what()).find("circular and orient need samples of at least [2, 2]"),
                  std::string::npos);
    }
}

TEST(Materials, GlossyFrostedAndTheirLobe) {
    Imported r =
        importText(kUse +
                   "material(reflection = 0.5, glossy = 4, frosted = 2, blur_samples = 16,"
                   " blur_lobe = \"phong\") cube();\n"
                   "material(glossy = 100, blur_samples = 0, blur_lobe = \"gauss\") sphere();");
    ir::Material m = materialOf(r, 0);
    EXPECT_EQ(m.finish.glossy, 4);
    EXPECT_EQ(m.finish.frosted, 2);
    EXPECT_EQ(m.finish.blurSamples, 16);
    EXPECT_EQ(m.finish.blurLobe, ir::Finish::Lobe::Phong);
    ir::Material bad = materialOf(r, 1);
    EXPECT_EQ(bad.finish.glossy, 0);
    EXPECT_EQ(bad.finish.blurSamples, 8);
    EXPECT_EQ(bad.finish.blurLobe, ir::Finish::Lobe::Normal);
    EXPECT_TRUE(r.hasWarning("material(): glossy = 100 is not an angle from 0 to 90 degrees"));
    EXPECT_TRUE(r.hasWarning("material(): blur_lobe = \"gauss\" is not \"normal\" or \"phong\""));
}

TEST(Camera, TransformedFirstWinsAndLaterOnesWarn) {
    Imported r = importText(kUse +
                            "translate([0, 0, 1]) rotate([0, 0, 90]) camera(location = [0, -10, "
                            "0], look_at = [0, 0, 0], sky = [0, 0, 1]);\n"
                            "camera(location = [5, 5, 5]);");
    ASSERT_TRUE(r.scene.camera);
    EXPECT_EQ(r.scene.camera->location, Vec3(10, 0, 1));
    EXPECT_EQ(r.scene.camera->lookAt, Vec3(0, 0, 1));
    EXPECT_EQ(r.scene.camera->sky, Vec3(0, 0, 1));
    Diagnostic w = r.warning("camera() already given");
    EXPECT_EQ(w.loc.line, 3);
}

TEST(Camera, DegenerateCamerasAreLocatedErrors) {
    try {
        importText(kUse + "camera(location = [1, 1, 1], look_at = [1, 1, 1]);");
        FAIL() << "expected EvalError";
    } catch (const EvalError &e) {
        EXPECT_EQ(e.loc().line, 2);
        EXPECT_NE(std::string(e.what()).find("location and look_at are the same point"),
                  std::string::npos);
    }
    try {
        importText(kUse + "camera(location = [0, 0, 10], look_at = [0, 0, 0], sky = [0, 0, 1]);");
        FAIL() << "expected EvalError";
    } catch (const EvalError &e) {
        EXPECT_EQ(e.loc().line, 2);
        EXPECT_NE(std::string(e.what()).find("is parallel to the view direction"),
                  std::string::npos);
    }
}

TEST(Camera, InvalidArgumentsWarnAndUseDefaults) {
    Imported r = importText(kUse + "camera(location = [1, 2], fov = -5);");
    ASSERT_TRUE(r.scene.camera);
    EXPECT_EQ(r.scene.camera->location, Vec3(0, -10, 5));
    EXPECT_EQ(r.scene.camera->fov, 40);
    EXPECT_TRUE(r.hasWarning("camera(): location = [1, 2] is not a vector of 3 finite numbers"));
    EXPECT_TRUE(r.hasWarning("camera(): fov = -5 is not between 0 and 180 degrees"));
}

TEST(Camera, ViewportVariablesMakeTheCamera) {
    Imported r = importText("$vpr = [60, 0, 30];\n$vpt = [1, 2, 3];\n$vpd = 50;\ncube();");
    ASSERT_TRUE(r.scene.camera);
    ir::Camera expected = ir::cameraFromViewport(Vec3(1, 2, 3), Vec3(60, 0, 30), 50, 22.5);
    EXPECT_EQ(r.scene.camera->location, expected.location);
    EXPECT_EQ(r.scene.camera->lookAt, expected.lookAt);
    EXPECT_EQ(r.scene.camera->sky, expected.sky);
    EXPECT_EQ(r.scene.camera->fov, 22.5);
    EXPECT_EQ(r.scene.camera->fovAxis, ir::FovAxis::Vertical);
    EXPECT_EQ(r.scene.camera->source, ir::CameraSource::ViewportVariables);
    EXPECT_EQ(r.scene.camera->loc.line, 1);
    // Unset ones take OpenSCAD's builtin values
    Imported d = importText("$vpf = 30; cube();");
    ir::Camera e2 = ir::cameraFromViewport(ir::kOpenScadBuiltinVpt, ir::kOpenScadBuiltinVpr,
                                           ir::kOpenScadBuiltinVpd, 30);
    ASSERT_TRUE(d.scene.camera);
    EXPECT_EQ(d.scene.camera->location, e2.location);
    EXPECT_EQ(d.scene.camera->fov, 30);
}

TEST(Camera, ExplicitCameraBeatsViewportAndNoneLeavesItEmpty) {
    Imported r = importText(kUse + "$vpd = 50; camera(location = [0, -5, 0]);");
    ASSERT_TRUE(r.scene.camera);
    EXPECT_EQ(r.scene.camera->source, ir::CameraSource::Explicit);
    EXPECT_FALSE(importText("cube();").scene.camera.has_value());
    // $vp in a module or an included file's scope other than the main top level does not count
    EXPECT_FALSE(importText("module m() { $vpd = 5; cube(); } m();").scene.camera.has_value());
}

TEST(MaterialResolution, ColorBeatsMaterialColorAndFinishComesFromInnermost) {
    Imported r = importText(kUse +
                            "material(color = \"blue\", phong = 0.9) {\n"
                            "  cube();\n"
                            "  color(\"red\") sphere();\n"
                            "  material(ior = 1.5) cylinder();\n"
                            "  color(\"lime\", 0.5) material(transmit = 0.2, ior = 2) cube();\n"
                            "}\n");
    ir::Material a = materialOf(r, 0), b = materialOf(r, 1), c = materialOf(r, 2),
                 d = materialOf(r, 3);
    EXPECT_EQ(a.color, Rgb(0, 0, 1));
    EXPECT_EQ(a.finish.phong, 0.9);
    EXPECT_EQ(b.color, Rgb(1, 0, 0));  // color() wins over material(color)
    EXPECT_EQ(b.finish.phong, 0.9);
    // The innermost material() supplies the finish: phong back at its default, pigment from
    // the outer material's colour
    EXPECT_EQ(c.color, Rgb(0, 0, 1));
    EXPECT_EQ(c.finish.phong, 0);
    EXPECT_EQ(c.interior.ior, 1.5);
    // color() alpha sets transmit, overriding the material's
    EXPECT_EQ(d.color, Rgb(0, 1, 0));
    EXPECT_EQ(d.transmit, 0.5);
    EXPECT_EQ(d.interior.ior, 2);
    EXPECT_EQ(r.scene.materials.size(), 4u);
    EXPECT_EQ(a.loc.line, 2);
}

TEST(MaterialResolution, ReflectionAndEmissionForms) {
    Imported r = importText(kUse +
                            "material(reflection = 0.4, emission = 0.5) cube();\n"
                            "material(reflection = [0.1, 0.6], emission = [1, 0.5, 0]) cube();\n"
                            "material(reflection = \"x\", ior = -1, roughness = 0) cube();");
    ir::Material a = materialOf(r, 0), b = materialOf(r, 1), c = materialOf(r, 2);
    EXPECT_EQ(a.finish.reflectionMin, Rgb(0.4));
    EXPECT_EQ(a.finish.reflectionMax, Rgb(0.4));
    EXPECT_EQ(a.finish.emission, Rgb(0.5));
    EXPECT_EQ(b.finish.reflectionMin, Rgb(0.1));
    EXPECT_EQ(b.finish.reflectionMax, Rgb(0.6));
    EXPECT_EQ(b.finish.emission, Rgb(1, 0.5, 0));
    EXPECT_TRUE(c.sameAppearance(ir::Material()));
    EXPECT_TRUE(r.hasWarning("material(): reflection = \"x\" is not a number or [min, max]"));
    EXPECT_TRUE(r.hasWarning("material(): ior = -1 is not a number > 0; using the default"));
    EXPECT_TRUE(r.hasWarning("material(): roughness = 0 is not a number > 0"));
    EXPECT_EQ(r.warning("ior = -1").loc.line, 4);
}

TEST(MaterialResolution, SameAppearanceIsShared) {
    Imported r = importText(kUse +
                            "material(phong = 1) cube(); material(phong = 1) sphere();"
                            "material(phong = 1, color = [1, 0, 0]) cube(); color(\"red\") "
                            "material(phong = 1) cube();");
    EXPECT_EQ(r.scene.materials.size(), 2u);
    auto p = primitives(*r.scene.root);
    EXPECT_EQ(p[0].node->material, p[1].node->material);
    EXPECT_EQ(p[2].node->material, p[3].node->material);
}

TEST(Settings, FirstCallWinsAndValuesAreValidated) {
    Imported r = importText(kUse +
                            "background(color = \"white\"); background(color = \"red\");\n"
                            "render_settings(max_trace_level = 2.5, adc_bailout = 2);");
    EXPECT_EQ(r.scene.settings.background, Rgb(1, 1, 1));
    EXPECT_TRUE(r.hasWarning("background() already given"));
    EXPECT_EQ(r.scene.settings.maxTraceLevel, 5);
    EXPECT_EQ(r.scene.settings.adcBailout, 1.0 / 255.0);
    EXPECT_TRUE(r.hasWarning("max_trace_level = 2.5 is not a whole number from 1 to 256"));
}

TEST(Metadata, BackgroundSubtreeIsIgnored) {
    Imported r = importText(kUse + "%point_light(); %camera();");
    EXPECT_TRUE(r.scene.lights.empty());
    EXPECT_FALSE(r.scene.camera.has_value());
}

}  // namespace
}  // namespace rt::scad::test
