// SPDX-License-Identifier: MIT
// Hostile names cannot inject SDL: a glTF mesh name, a source file name or an output name with
// a newline, `*/`, quotes, backslashes, `#` or non-UTF-8 bytes stays inside its comment; an
// .ini never takes a name that would add an option; POV-Ray runs under scadray's own conf.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <unistd.h>

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

TEST(PovHostile, PovRayRunsUnderItsOwnRestrictedConf) {
    if (!pov::povrayAvailable()) GTEST_SKIP() << "povray is not installed; run skipped";
    fs::path dir = fs::temp_directory_path() / ("scadray_hostile_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    // Writing in its own folder still works under the restricted conf
    std::ofstream(dir / "fine.pov") << "#fopen F \"inside.txt\" write\n#write(F, \"x\")\n"
                                       "#fclose F\nsphere { 0, 1 pigment { rgb 1 } }\n";
    pov::IniOptions o;
    o.povFile = "fine.pov";
    o.outputFile = "fine.png";
    o.width = 8;
    o.height = 8;
    std::ofstream(dir / "fine.ini") << pov::writeIni(o);
    EXPECT_NO_THROW(pov::runPovRay(dir.string(), "fine.ini", 1, 60));
    EXPECT_TRUE(fs::exists(dir / "inside.txt"));
    std::ifstream conf(dir / ".povray" / "3.7" / "povray.conf");
    std::string text((std::istreambuf_iterator<char>(conf)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("[Shellout Security]\nforbidden"), std::string::npos);
    EXPECT_NE(text.find("read+write = ."), std::string::npos);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace rt
