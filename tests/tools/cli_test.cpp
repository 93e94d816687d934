// SPDX-License-Identifier: MIT
// End-to-end tests of the scadray binary: every scene renders, bad input gives a located error
// with a non-zero exit code, and no output file appears (or an old one survives) on failure.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

#include "core/image/image_io.h"
#include "tools/cli_fixture.h"

namespace rt {
namespace {

namespace fs = std::filesystem;
using test::CliRun;

class Cli : public test::CliTest {
  protected:
    Cli() : CliTest("scadray_cli_") {}
};

TEST_F(Cli, EverySceneRenders) {
    for (const auto &e : fs::directory_iterator(std::string(SCADRAY_SOURCE_DIR) + "/scenes")) {
        if (e.path().extension() != ".scad" || e.path().filename() == "scadray.scad") continue;
        SCOPED_TRACE(e.path().string());
        std::string out = (dir / (e.path().stem().string() + ".png")).string();
        CliRun r = run("render -q -W 64 -H 48 " + e.path().string() + " -o " + out);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
        ASSERT_TRUE(fs::exists(out));
        Image img = readImage(out);
        EXPECT_EQ(img.width(), 64);
        // Not a blank picture: some pixel differs from the top-left one
        bool varied = false;
        for (int y = 0; y < img.height() && !varied; ++y)
            for (int x = 0; x < img.width() && !varied; ++x)
                varied = std::abs(img.at(x, y).g - img.at(0, 0).g) > 0.05;
        EXPECT_TRUE(varied);
    }
}

TEST_F(Cli, VersionIsTheProjectVersion) {
    CliRun r = run("--version");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.out, "scadray " SCADRAY_VERSION "\n");
}

TEST_F(Cli, SummaryReportsRaysAndTime) {
    std::string out = (dir / "a.png").string();
    CliRun r = run("render -W 32 -H 24 " + scene("glass.scad") + " -o " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("rays:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("refraction"), std::string::npos);
    EXPECT_NE(r.err.find(" s\n"), std::string::npos);
}

TEST_F(Cli, SyntaxErrorIsLocatedAndWritesNothing) {
    std::string in = write("bad.scad", "cube(1);\nsphere(r=2;\n");
    std::string out = (dir / "bad.png").string();
    CliRun r = run("render " + in + " -o " + out);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("bad.scad:2:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("error"), std::string::npos);
    EXPECT_NE(r.err.find("sphere(r=2;"), std::string::npos) << "excerpt of the offending line";
    EXPECT_FALSE(fs::exists(out));
}

TEST_F(Cli, UnknownModuleIsAnError) {
    std::string in = write("unknown.scad", "translate([1,0,0])\n  frobnicate(3);\n");
    CliRun r = run("render " + in + " -o " + (dir / "u.png").string());
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("unknown.scad:2:3"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("frobnicate"), std::string::npos);
    EXPECT_FALSE(fs::exists(dir / "u.png"));
}

TEST_F(Cli, AbsurdSizesAreLocatedErrors) {
    std::string in = write("huge.scad", "cube(1);\ntranslate([0,0,1]) sphere(1e300);\n");
    CliRun r = run("render " + in + " -o " + (dir / "h.png").string());
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("huge.scad:2:20: error"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "h.png"));
    std::string big = write("big.scad", "cube(1);");
    EXPECT_EQ(run("render " + big + " -W 100000 -o " + (dir / "b.png").string()).exitCode, 2);
    EXPECT_EQ(run("render " + big + " -s 1000000 -o " + (dir / "b.png").string()).exitCode, 2);
}

TEST_F(Cli, BadNumbersAreLocatedNeverACrash) {
    // Every bad number in a .scad file: either a located error with nothing written, or
    // OpenSCAD's documented behaviour (ignore, clamp, empty geometry) with a located warning
    // and a finite picture. The scene sits on line 2, after a sound first line.
    struct Case {
        const char *src;
        int exitCode;
        const char *message;  // expected on line 2 of the file
    };
    const Case cases[] = {
        {"scale([0, 1, 1]) cube(2);", 0, "scale() is singular"},
        {"multmatrix([[1, 0, 0, 0], [1, 0, 0, 0], [0, 0, 1, 0]]) cube();", 0, "is singular"},
        {"multmatrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 0]]) cube();", 1,
         "non-affine"},
        {"scale(1e200) cube();", 1,
         "extends to [0, 0, 0] .. [1e+200, 1e+200, 1e+200], beyond the supported range"},
        {"scale(1e-200) cube();", 1, "below the supported minimum"},
        {"translate([1e300, 0, 0]) sphere(1);", 1, "beyond the supported range"},
        {"translate([0/0, 0, 0]) cube();", 0, "translate("},
        {"rotate(1/0) cube();", 0, "rotate(a=inf)"},
        {"rotate(a = 30, v = [0/0, 0, 1]) cube();", 0, "rotate("},
        {"mirror([0/0, 0, 1]) cube();", 0, "mirror("},
        {"multmatrix([[1, 0, 0, 1/0]]) cube();", 0, "non-finite"},
        {"cube([1, 0/0, 1]);", 0, "empty geometry"},
        {"sphere(-1);", 0, "empty geometry"},
        {"cylinder(h = 1/0, r = 1);", 0, "empty geometry"},
        {"polyhedron([[0, 0, 0/0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], "
         "[[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]);",
         0, "not a vector of 3 finite numbers"},
        {"color([0/0, 1, 1]) sphere();", 0, "color()"},
        {"camera(location = [0/0, 1, 1], look_at = [0, 0, 0]); sphere();", 0, "location = [nan"},
        {"camera(location = [1, 1, 1], look_at = [1, 1, 1]); sphere();", 1, "the same point"},
        {"point_light([1/0, 0, 0]); sphere();", 0, "position = [inf"},
        {"material(ior = 0, transmit = 0.5) sphere();", 0, "ior = 0"},
        {"material(reflection = 0/0) sphere();", 0, "reflection = nan"},
        {"background([0/0, 0, 0]); sphere();", 0, "color = [nan"},
        {"render_settings(max_trace_level = 0/0); sphere();", 0, "max_trace_level = nan"},
    };
    int n = 0;
    for (const Case &c : cases) {
        SCOPED_TRACE(c.src);
        std::string name = "n" + std::to_string(n++);
        std::string in = write(name + ".scad",
                               std::string("include <scadray.scad> sphere(0.5);\n") + c.src + "\n");
        std::string out = (dir / (name + ".png")).string();
        CliRun r = run("render -W 24 -H 16 " + in + " -o " + out);
        EXPECT_EQ(r.exitCode, c.exitCode) << r.err;
        EXPECT_NE(r.err.find(name + ".scad:2:"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_EQ(fs::exists(out), c.exitCode == 0);
        if (c.exitCode == 0) {
            EXPECT_NE(r.err.find("non-finite pixels: 0\n"), std::string::npos) << r.err;
        }
    }
}

TEST_F(Cli, PlanIsPrintedBeforeRendering) {
    std::string out = (dir / "p.png").string();
    CliRun r = run("render --plan -W 32 -H 24 " + scene("print_plate.scad") + " -o " + out);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    size_t plan = r.err.find("plan:\n"), summary = r.err.find("scadray: " + out);
    ASSERT_NE(plan, std::string::npos) << r.err;
    ASSERT_NE(summary, std::string::npos) << r.err;
    EXPECT_LT(plan, summary);
    EXPECT_NE(r.err.find("dropped: 1 behind the camera"), std::string::npos) << r.err;
    // A sharp scene is antialiased adaptively, and the plan says where the samples went
    EXPECT_NE(r.err.find("samples: adaptive, each pixel's centre; where a neighbour differs"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find(", adaptive "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("\nplan: samples: adaptive, pixels by samples: 1: "), std::string::npos)
        << r.err;
    // A Monte Carlo scene chooses 4 samples; -s overrides
    CliRun mc = run("render --plan -W 16 -H 12 " + scene("montecarlo/glossy.scad") + " -o " + out);
    EXPECT_NE(mc.err.find("samples: 4 per pixel (chosen: Monte Carlo"), std::string::npos)
        << mc.err;
    EXPECT_NE(mc.err.find(", 4 spp,"), std::string::npos) << mc.err;
    CliRun given =
        run("render --plan -s 2 -W 16 -H 12 " + scene("montecarlo/glossy.scad") + " -o " + out);
    EXPECT_NE(given.err.find("samples: 2 per pixel (given)"), std::string::npos) << given.err;
    // --aa-* there asks for sampling adaptive to the noise, at its own tolerance unless given
    CliRun noise = run("render --plan --aa-max 16 -W 16 -H 12 " + scene("montecarlo/glossy.scad") +
                       " -o " + out);
    EXPECT_NE(
        noise.err.find(
            "adaptive to Monte Carlo noise, every pixel 4, 16 ... up to 16 stratified samples "
            "until the standard error is below 0.02 (given)"),
        std::string::npos)
        << noise.err;
    EXPECT_NE(noise.err.find("\nplan: samples: adaptive, pixels by samples: 4: "),
              std::string::npos)
        << noise.err;
    CliRun loose = run("render --plan --aa-tolerance 0.5 -W 16 -H 12 " +
                       scene("montecarlo/glossy.scad") + " -o " + out);
    EXPECT_NE(loose.err.find("until the standard error is below 0.5 (given)"), std::string::npos)
        << loose.err;
    // Without the plan nothing is left out
    CliRun naive =
        run("render --plan --no-plan -W 16 -H 12 " + scene("print_plate.scad") + " -o " + out);
    EXPECT_NE(naive.err.find("plan (disabled"), std::string::npos) << naive.err;
    EXPECT_NE(naive.err.find("dropped: 0 behind the camera"), std::string::npos) << naive.err;
    EXPECT_NE(naive.err.find("0 pruned subtrees"), std::string::npos) << naive.err;
}

TEST_F(Cli, AdaptiveAntialiasingOptions) {
    std::string out = (dir / "aa.png").string(), in = scene("lecture_csg.scad");
    // The summary line gives the mean samples per pixel
    CliRun r = run("render -W 32 -H 24 --aa-max 16 --aa-threshold 0.1 --aa-tolerance 0.01 " + in +
                   " -o " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    size_t at = r.err.find("32x24, adaptive ");
    ASSERT_NE(at, std::string::npos) << r.err;
    double spp = std::atof(r.err.c_str() + at + std::strlen("32x24, adaptive "));
    EXPECT_GT(spp, 1);
    EXPECT_LE(spp, 17);
    EXPECT_NE(r.err.find(" spp, "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(" s CPU\n"), std::string::npos) << r.err;
    // Turned off, and -s: uniform
    CliRun off = run("render -W 32 -H 24 --no-aa " + in + " -o " + out);
    EXPECT_NE(off.err.find("32x24, 1 spp, "), std::string::npos) << off.err;
    CliRun given = run("render -W 32 -H 24 -s 4 " + in + " -o " + out);
    EXPECT_NE(given.err.find("32x24, 4 spp, "), std::string::npos) << given.err;
    // Out of range, not a power of 4, or combined with -s or --no-aa: usage errors
    for (const char *bad : {"--aa-max 2", "--aa-max 8192", "--aa-max 32", "--aa-threshold -0.1",
                            "--aa-threshold 2", "--aa-tolerance nan", "--aa-tolerance 1.5",
                            "-s 4 --aa-max 16", "--no-aa --aa-threshold 0.1", "-s 2 --no-aa"}) {
        CliRun b = run(std::string("render -W 8 -H 8 ") + bad + " " + in + " -o " + out);
        EXPECT_EQ(b.exitCode, 2) << bad << ": " << b.err;
    }
    CliRun notPower = run("render -W 8 -H 8 --aa-max 32 " + in + " -o " + out);
    EXPECT_NE(notPower.err.find("4, 16, 64, 256, 1024 or 4096"), std::string::npos) << notPower.err;
}

TEST_F(Cli, FailureKeepsAnExistingOutput) {
    std::string out = (dir / "keep.png").string();
    ASSERT_EQ(run("render -q -W 16 -H 16 " + scene("csg_part.scad") + " -o " + out).exitCode, 0);
    auto size = fs::file_size(out);
    std::string in = write("broken.scad", "cube(");
    EXPECT_EQ(run("render " + in + " -o " + out).exitCode, 1);
    EXPECT_EQ(fs::file_size(out), size);
}

TEST_F(Cli, BadOptionsAndFiles) {
    EXPECT_EQ(run("render " + scene("glass.scad") + " -W 0 -o x.png").exitCode, 2);
    EXPECT_EQ(run("render " + scene("glass.scad") + " -s 0 -o x.png").exitCode, 2);
    EXPECT_EQ(run("render " + scene("glass.scad") + " -s 70000 -o x.png").exitCode, 2);
    EXPECT_EQ(run("render " + scene("glass.scad") + " --bits 12 -o x.png").exitCode, 2);
    EXPECT_EQ(run("frobnicate").exitCode, 2);
    CliRun missing = run("render " + (dir / "nope.scad").string());
    EXPECT_EQ(missing.exitCode, 1);
    EXPECT_NE(missing.err.find("no such file"), std::string::npos);
    CliRun type = run("render " + write("x.txt", "cube(1);"));
    EXPECT_EQ(type.exitCode, 1);
    CliRun format =
        run("render -q " + scene("glass.scad") + " -W 8 -H 8 -o " + (dir / "x.bmpx").string());
    EXPECT_EQ(format.exitCode, 1);
    EXPECT_FALSE(fs::exists(dir / "x.bmpx"));
}

TEST_F(Cli, PlainScadGetsCameraAndLights) {
    std::string in =
        write("plain.scad", "difference() { cube(10, center=true); sphere(6.5, $fn=48); }\n");
    std::string out = (dir / "plain.exr").string();
    CliRun r = run("render -W 48 -H 36 " + in + " -o " + out);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("no camera()"), std::string::npos);
    EXPECT_NE(r.err.find("no lights"), std::string::npos);
    Image img = readImage(out);
    // The model is centred: the centre pixel shows OpenSCAD's yellow, lit
    Rgb c = img.at(24, 18);
    EXPECT_GT(c.r, c.b * 2);
    EXPECT_GT(c.g, c.b);
}

TEST_F(Cli, ExportWritesPovAndIni) {
    std::string pov = (dir / "lecture.pov").string();
    CliRun r = run("export " + scene("lecture_csg.scad") + " -o " + pov + " -W 200 -H 100");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::string text = slurp(pov), ini = slurp(dir / "lecture.ini");
    EXPECT_NE(text.find("#version 3.7;"), std::string::npos);
    EXPECT_NE(text.find("difference {"), std::string::npos);
    EXPECT_NE(ini.find("Input_File_Name=lecture.pov"), std::string::npos);
    EXPECT_NE(ini.find("Width=200"), std::string::npos);
    // Bad input: located error, nothing written
    std::string bad = write("bad.scad", "cube(1);\nfrob();\n");
    CliRun e = run("export " + bad + " -o " + (dir / "bad.pov").string());
    EXPECT_EQ(e.exitCode, 1);
    EXPECT_NE(e.err.find("bad.scad:2:1"), std::string::npos) << e.err;
    EXPECT_FALSE(fs::exists(dir / "bad.pov"));
    EXPECT_FALSE(fs::exists(dir / "bad.ini"));
    EXPECT_EQ(run("export " + bad + " -o " + (dir / "x.txt").string()).exitCode, 2);
}

TEST_F(Cli, CompareExitCodes) {
    std::string a = (dir / "a.exr").string(), b = (dir / "b.exr").string();
    ASSERT_EQ(run("render -q -W 64 -H 48 -s 4 " + scene("csg_part.scad") + " -o " + a).exitCode, 0);
    ASSERT_EQ(
        run("render -q -W 64 -H 48 -s 4 --seed 7 " + scene("csg_part.scad") + " -o " + b).exitCode,
        0);
    CliRun same = run("compare " + a + " " + b);
    EXPECT_EQ(same.exitCode, 0) << same.out;
    EXPECT_NE(same.out.find("PASS"), std::string::npos);
    EXPECT_NE(same.out.find("RMSE"), std::string::npos);
    std::string other = (dir / "other.exr").string();
    ASSERT_EQ(run("render -q -W 64 -H 48 " + scene("mirrors.scad") + " -o " + other).exitCode, 0);
    CliRun diff = run("compare " + other + " " + a + " --heat-map " + (dir / "heat.png").string());
    EXPECT_EQ(diff.exitCode, 1) << diff.out;
    EXPECT_NE(diff.out.find("DIFFERENT"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir / "heat.png"));
    std::string small = (dir / "small.exr").string();
    ASSERT_EQ(run("render -q -W 32 -H 24 " + scene("mirrors.scad") + " -o " + small).exitCode, 0);
    EXPECT_EQ(run("compare " + small + " " + a).exitCode, 2);
    EXPECT_EQ(run("compare " + (dir / "missing.exr").string() + " " + a).exitCode, 2);
}

TEST_F(Cli, CheckWithoutPovRayIsAClearError) {
    // PATH without povray: the check cannot run, and says why
    CliRun r = run("check " + scene("csg_part.scad") + " -o " + (dir / "chk").string(),
                   "PATH=/nonexistent");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("povray"), std::string::npos);
}

TEST_F(Cli, MeshFilesRenderOnTheirOwn) {
    // glTF, STL and OFF files are scenes by themselves: automatic camera and lights where the
    // file has none, the file's own camera and lights where it has them
    // (textured_camera.glb: its own camera, an embedded PNG texture, no lights)
    std::vector<std::string> files = {
        scene("gltf/lights_ortho.gltf"), scene("crosscheck/assets/torus.stl"),
        scene("crosscheck/assets/frustum.off"),
        std::string(SCADRAY_SOURCE_DIR) + "/tests/data/gltf/textured_camera.glb"};
    for (const auto &file : files) {
        SCOPED_TRACE(file);
        std::string out = (dir / (fs::path(file).stem().string() + ".png")).string();
        CliRun r = run("render -W 48 -H 36 " + file + " -o " + out);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_NE(r.err.find("triangles"), std::string::npos) << r.err;
        Image img = readImage(out);
        bool varied = false;
        for (int y = 0; y < img.height() && !varied; ++y)
            for (int x = 0; x < img.width() && !varied; ++x)
                varied = std::abs(img.at(x, y).g - img.at(0, 0).g) > 0.05;
        EXPECT_TRUE(varied) << "blank picture";
    }
}

TEST_F(Cli, BrokenMeshFilesAreLocatedErrorsAndWriteNothing) {
    struct Case {
        std::string name, text, where;
    };
    std::vector<Case> cases = {
        // JSON syntax error: line and column in the file
        {"syntax.gltf", "{\"asset\": {\"version\": \"2.0\"},\n  \"nodes\": [ }\n",
         "syntax.gltf:2:"},
        // Wrong index: the JSON path of the offending value
        {"index.gltf",
         "{\"asset\":{\"version\":\"2.0\"},\"scenes\":[{\"nodes\":[3]}],\"nodes\":[{}]}\n",
         "index.gltf"},
        // Truncated binary glTF
        {"cut.glb", std::string("glTF\x02\x00\x00\x00\xff\x00\x00\x00", 12), "cut.glb"},
        // Facet with a NaN vertex
        {"nan.stl",
         "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex nan 1 0\n"
         "endloop\nendfacet\nendsolid x\n",
         "nan.stl:6:"},
        // OFF face naming a vertex that does not exist
        {"index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "index.off:6:"},
    };
    for (const auto &c : cases) {
        SCOPED_TRACE(c.name);
        std::string in = write(c.name, c.text);
        std::string out = (dir / "broken.png").string();
        CliRun r = run("render " + in + " -o " + out);
        EXPECT_EQ(r.exitCode, 1) << r.err;
        EXPECT_NE(r.err.find(c.where), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("error"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(out));
    }
}

TEST_F(Cli, BadAreaLightIsALocatedErrorForEveryCommand) {
    // A circular light needs a 2 x 2 grid at least: render, export and converge all stop at
    // its line and column and write nothing
    std::string in = write("area.scad",
                           "use <scadray.scad>\ncube(1);\n"
                           "  area_light(samples=[1, 4], circular=true);\n");
    std::string lib = " -L " + std::string(SCADRAY_SOURCE_DIR) + "/scenes";
    for (const std::string &cmd :
         {"render " + in + lib + " -o " + (dir / "a.png").string(),
          "export " + in + lib + " -o " + (dir / "a.pov").string(),
          "converge " + in + lib + " --max-samples 2 -W 8 -H 8 -o " + (dir / "conv").string()}) {
        SCOPED_TRACE(cmd);
        CliRun r = run(cmd);
        EXPECT_EQ(r.exitCode, 1) << r.err;
        EXPECT_NE(r.err.find("area.scad:3:3"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("circular and orient need samples of at least [2, 2]"),
                  std::string::npos)
            << r.err;
    }
    EXPECT_FALSE(fs::exists(dir / "a.png"));
    EXPECT_FALSE(fs::exists(dir / "a.pov"));
    EXPECT_FALSE(fs::exists(dir / "conv"));
}

TEST_F(Cli, MaxStepsCapsEveryCommandAndIsNamedWhenHit) {
    std::string in = write("steps.scad", "x = 1;\n  y = [for (i = [0:99999]) i];\necho(len(y));\n");
    for (const std::string &cmd :
         {"dump " + in, "render " + in + " -W 8 -H 8 -o " + (dir / "s.png").string(),
          "export " + in + " -o " + (dir / "s.pov").string(),
          "converge " + in + " --max-samples 2 -W 8 -H 8 -o " + (dir / "conv").string()}) {
        SCOPED_TRACE(cmd);
        CliRun r = run(cmd + " --max-steps 1000");
        EXPECT_EQ(r.exitCode, 1) << r.err;
        EXPECT_NE(r.err.find("steps.scad:2:8: error: evaluation too long: more than 1000 steps"),
                  std::string::npos)
            << r.err;
        EXPECT_NE(r.err.find("--max-steps"), std::string::npos) << r.err;
    }
    EXPECT_FALSE(fs::exists(dir / "s.png"));
    // The default and no cap at all both let it through; a negative cap is a usage error
    EXPECT_EQ(run("dump " + in).exitCode, 0);
    CliRun r = run("dump --max-steps 0 " + in);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(run("dump --max-steps -1 " + in).exitCode, 2);
}

TEST_F(Cli, ProgressOfALongEvaluationOnlyOnATerminal) {
    // About 15 M steps: several seconds here, over the 1 s delay on any machine
    std::string in = write("long.scad",
                           "function f(n) = n == 0 ? 0 : f(n - 1);\n"
                           "x = [for (i = [0:149]) f(100000)];\ncube();\n");
    CliRun plain = run("dump " + in);
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    EXPECT_EQ(plain.err.find("evaluating"), std::string::npos) << plain.err;
    if (std::system("command -v script >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "script(1) is not installed: no terminal to test the progress line on";
    // script(1) gives the command a terminal; its output (stdout and stderr) lands in the file
    std::string typescript = (dir / "typescript").string();
    std::string cmd = "script -qec '" + std::string(SCADRAY_BINARY) + " dump --max-steps 0 " + in +
                      " >/dev/null' " + typescript + " >/dev/null 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    std::string tty = slurp(typescript);
    EXPECT_NE(tty.find("\revaluating: "), std::string::npos) << tty;
    EXPECT_NE(tty.find(" M steps"), std::string::npos) << tty;
    // Cleared at the end
    EXPECT_NE(tty.find("\r\033[K"), std::string::npos) << tty;
    // -q keeps it quiet
    cmd = "script -qec '" + std::string(SCADRAY_BINARY) + " render -q -W 8 -H 8 " + in + " -o " +
          (dir / "q.png").string() + "' " + typescript + " >/dev/null 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    EXPECT_EQ(slurp(typescript).find("evaluating"), std::string::npos);
}

TEST_F(Cli, EmptyMeshFileIsAnEmptyScene) {
    std::string in = write("empty.stl", "solid empty\nendsolid empty\n");
    CliRun r = run("render -W 8 -H 8 " + in + " -o " + (dir / "e.png").string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("no geometry"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(dir / "e.png"));
}

TEST_F(Cli, ExportWritesMeshesAsMesh2) {
    std::string pov = (dir / "meshes.pov").string();
    CliRun r = run("export " + scene("crosscheck/meshes.scad") + " -o " + pov);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::string text = slurp(pov);
    EXPECT_NE(text.find("mesh2 {"), std::string::npos);
    EXPECT_NE(text.find("inside_vector"), std::string::npos);
    EXPECT_NE(text.find("difference {"), std::string::npos) << "the cut torus stays CSG";
}

TEST_F(Cli, FacetsChooseHowRoundPrimitivesAreDrawn) {
    std::string in =
        write("f.scad", "cylinder(r=2, h=1, $fn=6);\ntranslate([5,0,0]) sphere(1, $fn=64);\n");
    auto polytopes = [](const std::string &text) {
        size_t n = 0;
        for (size_t at = text.find("polytope"); at != std::string::npos;
             at = text.find("polytope", at + 1))
            ++n;
        return n;
    };
    CliRun r = run("dump " + in);  // auto: the hexagon only
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(polytopes(r.out), 1u);
    EXPECT_NE(r.out.find("sphere r 1"), std::string::npos);
    EXPECT_EQ(polytopes(run("dump --facets openscad " + in).out), 2u);
    EXPECT_EQ(polytopes(run("dump --facets smooth " + in).out), 0u);
    r = run("render --plan --facets auto -W 8 -H 6 " + in + " -o " + (dir / "f.png").string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("facets: auto:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("(1 faceted, 1 round)"), std::string::npos) << r.err;
    EXPECT_EQ(run("render --facets round " + in).exitCode, 2);
    // check --openscad compares OpenSCAD's own facets: another mode is bad usage
    r = run("check --openscad --facets smooth " + in + " -o " + (dir / "chk").string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--facets smooth cannot be used"), std::string::npos) << r.err;
}

TEST_F(Cli, DumpPrintsTheIr) {
    std::string in = write("d.scad", "translate([1,2,3]) cube(2);\n");
    CliRun r = run("dump " + in);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("transform [[1, 0, 0, 1], [0, 1, 0, 2], [0, 0, 1, 3]]"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("box min [0, 0, 0] max [2, 2, 2]"), std::string::npos);
    EXPECT_NE(r.out.find("camera automatic"), std::string::npos);
}

}  // namespace
}  // namespace rt
