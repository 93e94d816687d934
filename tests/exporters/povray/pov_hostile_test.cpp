// SPDX-License-Identifier: MIT
// Hostile names cannot inject SDL: a glTF mesh name, a source file name or an output name with
// a newline, `*/`, quotes, backslashes, `#` or non-UTF-8 bytes stays inside its comment; an
// .ini never takes a name that would add an option; POV-Ray runs under scadray's own conf.
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "core/ir/scene_defaults.h"
#include "exporters/povray/pov_format.h"
#include "exporters/povray/pov_runner.h"
#include "exporters/povray/pov_writer.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

const std::string kPayload =
    "x\n#fopen Pwned \"pwned.txt\" write #write(Pwned, \"owned\") #fclose Pwned\n"
    "*/ /* \"quoted\" back\\slash #declare \xff\xfe\r// end";

/// Every line of the SDL that is not a comment, with comments cut off.
std::vector<std::string> codeLines(const std::string &sdl) {
    std::vector<std::string> out;
    std::istringstream in(sdl);
    for (std::string line; std::getline(in, line);) {
        size_t c = line.find("//");
        out.push_back(c == std::string::npos ? line : line.substr(0, c));
    }
    return out;
}

ir::Scene hostileScene() {
    ir::Scene scene;
    auto mesh = std::make_shared<ir::Mesh>();
    mesh->name = kPayload;
    mesh->positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    mesh->triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    mesh->loc = SourceLoc{std::make_shared<std::string>("/models/" + kPayload + ".gltf"), 1, 1};
    scene.meshes.push_back(mesh);
    int mat = scene.addMaterial(ir::Material());
    scene.root = ir::Node::makeGroup(ir::NodeKind::Group, mesh->loc);
    scene.root->children.push_back(ir::Node::makePrimitive(ir::MeshPrim{0}, mat, mesh->loc));
    DiagnosticSink diag;
    ir::completeScene(scene, diag);
    return scene;
}

TEST(PovHostile, CommentTextKeepsEverythingInTheComment) {
    std::string c = pov::commentText(kPayload);
    EXPECT_EQ(c.find('\n'), std::string::npos);
    EXPECT_EQ(c.find('\r'), std::string::npos);
    EXPECT_EQ(c.find("*/"), std::string::npos);
    EXPECT_EQ(c.find("/*"), std::string::npos);
    for (char ch : c) EXPECT_TRUE(ch >= 0x20 && ch < 0x7f) << int(static_cast<unsigned char>(ch));
    EXPECT_NE(c.find("\\x0a#fopen"), std::string::npos);
    EXPECT_NE(c.find("\\xff\\xfe"), std::string::npos);
    EXPECT_NE(c.find("back\\x5cslash"), std::string::npos);
    EXPECT_EQ(pov::commentText("plain name.scad:3:4"), "plain name.scad:3:4");
    EXPECT_EQ(pov::safeFileName("a b\n\"c\".x"), "a_b__c_.x");
    EXPECT_FALSE(pov::iniSafe("out\nPre_Scene_Command=rm -rf ~"));
    EXPECT_FALSE(pov::iniSafe("a;b.png"));
    EXPECT_TRUE(pov::iniSafe("my scene.png"));
}

TEST(PovHostile, ExportedSdlHasNoInjectedDirective) {
    ir::Scene scene = hostileScene();
    std::string sdl = pov::writeSdl(scene, kPayload);
    for (const std::string &line : codeLines(sdl)) {
        EXPECT_EQ(line.find("#fopen"), std::string::npos) << line;
        EXPECT_EQ(line.find("#write"), std::string::npos) << line;
        EXPECT_EQ(line.find("/*"), std::string::npos) << line;
    }
}

TEST(PovHostile, IniRefusesNamesThatWouldAddOptions) {
    pov::IniOptions o;
    o.povFile = "scene.pov";
    o.outputFile = "x.png\nPre_Scene_Command=touch pwned";
    EXPECT_THROW(pov::writeIni(o), std::runtime_error);
    o.outputFile = "x.png";
    EXPECT_NO_THROW(pov::writeIni(o));
}

TEST(PovHostile, DirectiveScanReadsSdlAsPovRayDoes) {
    EXPECT_EQ(pov::sdlDirectiveProblem("#version 3.7;\n#declare A = 1;\n# declare B = 2;\n"), "");
    // Inside comments (nested block comments included) and strings nothing counts
    EXPECT_EQ(pov::sdlDirectiveProblem("// #fopen F \"x\" write\n/* a /* #write */ #system */\n"),
              "");
    EXPECT_EQ(pov::sdlDirectiveProblem("#declare S = \"quote \\\" #fopen\";\n"), "");
    // Everything else is refused, with its line
    EXPECT_NE(pov::sdlDirectiveProblem("sphere{0,1}\n#fopen F \"x\" write\n")
                  .find("line 2: directive #fopen"),
              std::string::npos);
    EXPECT_NE(pov::sdlDirectiveProblem("#  include \"/etc/passwd\"").find("#include"),
              std::string::npos);
    EXPECT_NE(pov::sdlDirectiveProblem("#macro M() #end").find("#macro"), std::string::npos);
    EXPECT_NE(pov::sdlDirectiveProblem("/* a /* b */ #write */ #write(F)").find("#write"),
              std::string::npos);
    // A `//` comment ends at a carriage return too, as in POV-Ray
    EXPECT_NE(pov::sdlDirectiveProblem("// x\r#fopen F").find("#fopen"), std::string::npos);
    EXPECT_NE(pov::sdlDirectiveProblem("/* open"), "");
    EXPECT_NE(pov::sdlDirectiveProblem("#declare S = \"open\n#fopen"), "");
    // The exporter's own output of the hostile scene passes
    EXPECT_EQ(pov::sdlDirectiveProblem(pov::writeSdl(hostileScene(), kPayload)), "");
}

struct PovRunDir {
    fs::path dir = fs::temp_directory_path() / ("scadray_hostile_" + std::to_string(::getpid()));
    PovRunDir() {
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    ~PovRunDir() { fs::remove_all(dir); }
    void write(const std::string &name, const std::string &text) const {
        std::ofstream(dir / name) << text;
    }
    void writeIni(const std::string &pov) const {
        pov::IniOptions o;
        o.povFile = pov;
        o.outputFile = "out.png";
        o.width = 8;
        o.height = 8;
        write("scene.ini", pov::writeIni(o));
    }
};

TEST(PovHostile, CheckRefusesScenesWithFileIoOrForeignIniOptions) {
    PovRunDir run;
    // Refused before POV-Ray starts, so this holds with or without POV-Ray installed
    run.write("io.pov",
              "#fopen F \"pwned.txt\" write\n#write(F, \"x\")\n#fclose F\nsphere { 0, 1 }\n");
    run.writeIni("io.pov");
    try {
        pov::runPovRay(run.dir.string(), "scene.ini", 1, 60);
        ADD_FAILURE() << "a scene with #fopen ran";
    } catch (const std::runtime_error &e) {
        EXPECT_NE(std::string(e.what()).find("line 1: directive #fopen"), std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(fs::exists(run.dir / "pwned.txt"));
    run.write("plain.pov", "sphere { 0, 1 pigment { rgb 1 } }\n");
    run.write("scene.ini", "Input_File_Name=plain.pov\nPre_Scene_Command=touch pwned.txt\n");
    EXPECT_THROW(pov::runPovRay(run.dir.string(), "scene.ini", 1, 60), std::runtime_error);
    run.write("scene.ini", "Input_File_Name=plain.pov\nInclude_Header=/etc/passwd\n");
    EXPECT_THROW(pov::runPovRay(run.dir.string(), "scene.ini", 1, 60), std::runtime_error);
    EXPECT_FALSE(fs::exists(run.dir / "pwned.txt"));
}

TEST(PovHostile, PovRayRunsUnderItsOwnRestrictedConf) {
    if (!pov::povrayAvailable()) GTEST_SKIP() << "povray is not installed; run skipped";
    PovRunDir run;
    run.write("plain.pov",
              "#version 3.7;\nbackground { rgb 1 }\nsphere { 0, 1 pigment { rgb 1 } }\n");
    run.writeIni("plain.pov");
    EXPECT_NO_THROW(pov::runPovRay(run.dir.string(), "scene.ini", 1, 60));
    EXPECT_TRUE(fs::exists(run.dir / "out.png"));
    std::ifstream conf(run.dir / ".povray" / "3.7" / "povray.conf");
    std::string text((std::istreambuf_iterator<char>(conf)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("[Shellout Security]\nforbidden"), std::string::npos);
    EXPECT_NE(text.find("read+write = ."), std::string::npos);
}

}  // namespace
}  // namespace rt
