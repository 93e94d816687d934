// SPDX-License-Identifier: MIT
// Fuzz target: the POV-Ray writer's escaping. Arbitrary names (a mesh name, the file a mesh
// came from, the exported scene's source name, an output file name) go through the exporter;
// an independent reading of the result checks the contract of pov_format.h:
//  - commentText: printable ASCII only, no `/*` or `*/`, and decoding its \xNN escapes gives
//    back exactly the original bytes (nothing lost, nothing invented);
//  - the SDL, read as POV-Ray reads comments (// to the end of the line, where CR also ends a
//    line; /* */ nested) and strings ("..." with backslash escapes), has the same code outside
//    comments as the same scene with harmless names, and is printable ASCII lines;
//  - safeFileName keeps the length and only [A-Za-z0-9._-]; writeIni refuses a name iniSafe
//    refuses and otherwise adds no line.
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/ir/scene_defaults.h"
#include "exporters/povray/pov_format.h"
#include "exporters/povray/pov_writer.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

using rt::fuzz::fail;

std::string decodeComment(const std::string &c) {
    auto hexValue = [](char h) -> int {
        if (h >= '0' && h <= '9') return h - '0';
        if (h >= 'a' && h <= 'f') return h - 'a' + 10;
        return -1;
    };
    std::string out;
    for (size_t i = 0; i < c.size(); ++i) {
        if (c[i] != '\\') {
            out += c[i];
            continue;
        }
        if (i + 3 >= c.size()) fail("commentText: truncated escape");
        if (c[i + 1] != 'x' || hexValue(c[i + 2]) < 0 || hexValue(c[i + 3]) < 0)
            fail("commentText: backslash not starting a \\xNN escape");
        out += static_cast<char>(hexValue(c[i + 2]) * 16 + hexValue(c[i + 3]));
        i += 3;
    }
    return out;
}

void checkCommentText(const std::string &s) {
    std::string c = rt::pov::commentText(s);
    for (char ch : c)
        if (!(ch >= 0x20 && ch < 0x7f)) fail("commentText: byte outside printable ASCII");
    if (c.find("/*") != std::string::npos || c.find("*/") != std::string::npos)
        fail("commentText: block comment delimiter");
    if (decodeComment(c) != s) fail("commentText: does not decode to the original text");
}

/// The SDL with every comment replaced by one space, as POV-Ray's scanner separates them.
std::string codeOf(const std::string &sdl) {
    std::string out;
    size_t i = 0, n = sdl.size();
    while (i < n) {
        if (sdl.compare(i, 2, "//") == 0) {
            while (i < n && sdl[i] != '\n' && sdl[i] != '\r') ++i;
            out += ' ';
        } else if (sdl.compare(i, 2, "/*") == 0) {
            int depth = 0;
            do {
                if (sdl.compare(i, 2, "/*") == 0) {
                    ++depth;
                    i += 2;
                } else if (sdl.compare(i, 2, "*/") == 0) {
                    --depth;
                    i += 2;
                } else {
                    ++i;
                }
            } while (i < n && depth > 0);
            if (depth > 0) fail("SDL: unterminated block comment");
            out += ' ';
        } else if (sdl[i] == '"') {
            size_t start = i++;
            while (i < n && sdl[i] != '"' && sdl[i] != '\n') i += sdl[i] == '\\' ? 2 : 1;
            if (i >= n || sdl[i] != '"') fail("SDL: unterminated string");
            ++i;
            out.append(sdl, start, i - start);
        } else {
            out += sdl[i++];
        }
    }
    return out;
}

rt::ir::Scene sceneNamed(const std::string &meshName, const std::string &fileName) {
    rt::ir::Scene scene;
    auto mesh = std::make_shared<rt::ir::Mesh>();
    mesh->name = meshName;
    mesh->positions = {rt::Vec3(0, 0, 0), rt::Vec3(1, 0, 0), rt::Vec3(0, 1, 0), rt::Vec3(0, 0, 1)};
    mesh->triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    mesh->loc = rt::SourceLoc{std::make_shared<std::string>(fileName), 1, 1};
    scene.meshes.push_back(mesh);
    int mat = scene.addMaterial(rt::ir::Material());
    scene.root = rt::ir::Node::makeGroup(rt::ir::NodeKind::Group, mesh->loc);
    scene.root->children.push_back(
        rt::ir::Node::makePrimitive(rt::ir::MeshPrim{0}, mat, mesh->loc));
    rt::DiagnosticSink diag;
    rt::ir::completeScene(scene, diag);
    return scene;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    FuzzedDataProvider in(data, size);
    std::string meshName = in.ConsumeRandomLengthString(256);
    std::string fileName = in.ConsumeRandomLengthString(256);
    std::string sourceName = in.ConsumeRandomLengthString(256);
    std::string outputName = in.ConsumeRemainingBytesAsString();

    for (const std::string *s : {&meshName, &fileName, &sourceName, &outputName})
        checkCommentText(*s);

    std::string sdl = rt::pov::writeSdl(sceneNamed(meshName, fileName), sourceName);
    for (char ch : sdl)
        if (!((ch >= 0x20 && ch < 0x7f) || ch == '\n')) fail("SDL: byte outside printable ASCII");
    std::string plain = rt::pov::writeSdl(sceneNamed("mesh", "/models/mesh.gltf"), "scene.scad");
    if (codeOf(sdl) != codeOf(plain)) fail("SDL: a name changed the code outside comments");

    std::string safe = rt::pov::safeFileName(outputName);
    if (safe.size() != outputName.size()) fail("safeFileName: length changed");
    for (char ch : safe)
        if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '.' || ch == '-' || ch == '_'))
            fail("safeFileName: unsafe byte kept");

    rt::pov::IniOptions ini;
    ini.povFile = "scene.pov";
    ini.outputFile = outputName;
    bool safeIni = rt::pov::iniSafe(outputName);
    for (char ch : outputName)
        if (safeIni && (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f || ch == ';'))
            fail("iniSafe: accepted a control character or ';'");
    try {
        std::string text = rt::pov::writeIni(ini);
        if (!safeIni) fail("writeIni: wrote a name iniSafe refuses");
        ini.outputFile = "out.png";
        std::string plainIni = rt::pov::writeIni(ini);
        auto lines = [](const std::string &t) {
            return std::count(t.begin(), t.end(), '\n') + std::count(t.begin(), t.end(), '\r');
        };
        if (lines(text) != lines(plainIni)) fail("writeIni: a name added a line");
    } catch (const std::runtime_error &) {
        if (safeIni) fail("writeIni: refused a name iniSafe accepts");
    }
    return 0;
}
