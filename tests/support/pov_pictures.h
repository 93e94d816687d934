// SPDX-License-Identifier: MIT
// Pictures of an IR scene by scadray and by POV-Ray, and their pixel comparisons, for export
// tests that check what a POV-Ray object means by rendering it.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "core/image/image_io.h"
#include "core/render/render_scene.h"
#include "core/render/renderer.h"
#include "exporters/povray/pov_runner.h"
#include "exporters/povray/pov_writer.h"

namespace rt::test {

/// How often `what` occurs in `text`.
inline int count(const std::string &text, const std::string &what) {
    int n = 0;
    for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
    return n;
}

/// scadray's picture of the scene (two threads).
inline Image scadrayPicture(const ir::Scene &s, int width, int height) {
    DiagnosticSink diag;
    auto rs = RenderScene::compile(s, diag);
    RenderOptions o;
    o.width = width;
    o.height = height;
    o.threads = 2;
    return renderImage(*rs, o).image;
}

/// POV-Ray's picture of `sdl`, rendered as `name` in the temporary folder `folder`.
inline Image povrayPicture(const std::string &sdl, const std::string &folder,
                           const std::string &name, int width, int height) {
    auto dir = std::filesystem::temp_directory_path() / folder;
    std::filesystem::create_directories(dir);
    pov::IniOptions ini;
    ini.povFile = name + ".pov";
    ini.outputFile = name + ".png";
    ini.width = width;
    ini.height = height;
    ini.threads = 2;
    std::ofstream((dir / ini.povFile).string()) << sdl;
    std::ofstream((dir / (name + ".ini")).string()) << pov::writeIni(ini);
    pov::runPovRay(dir.string(), name + ".ini", 2, 120);
    return readImage((dir / ini.outputFile).string(), true);
}

/// Pixels covered (brighter than half) in `a`, and those whose coverage differs in `b`.
inline std::pair<int, int> coverage(const Image &a, const Image &b) {
    int covered = 0, differ = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            bool p = a.at(x, y).g > 0.5, q = b.at(x, y).g > 0.5;
            covered += p;
            differ += p != q;
        }
    return {covered, differ};
}

/// Shading of two pictures away from silhouettes: the pixels whose 3x3 neighbourhood is
/// covered in both, their mean difference and how many differ by more than 0.02.
struct ShadingDifference {
    int compared = 0, off = 0;
    double mean = 0;
};

inline ShadingDifference shadingDifference(const Image &ours, const Image &theirs) {
    auto covered = [](const Image &img, int x, int y) { return img.at(x, y).g > 0.05; };
    ShadingDifference d;
    double sum = 0;
    for (int y = 1; y + 1 < ours.height(); ++y)
        for (int x = 1; x + 1 < ours.width(); ++x) {
            bool inner = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    inner =
                        inner && covered(ours, x + dx, y + dy) && covered(theirs, x + dx, y + dy);
            if (!inner) continue;
            ++d.compared;
            double diff = std::abs(ours.at(x, y).g - theirs.at(x, y).g);
            sum += diff;
            d.off += diff > 0.02;
        }
    d.mean = d.compared ? sum / d.compared : 0.0;
    return d;
}

/// Expects the same silhouettes, but for 1 % of the covered pixels (along silhouettes, where a
/// pixel centre's ray grazes the surface); returns the pixels covered in `ours`.
inline int expectSameSilhouettes(const Image &ours, const Image &theirs, const char *what) {
    auto [covered, differ] = coverage(ours, theirs);
    std::printf("%s silhouettes: %d pixels covered, %d differ\n", what, covered, differ);
    EXPECT_GT(covered, ours.width() * ours.height() / 10);
    EXPECT_LT(differ, covered / 100 + 5);
    return covered;
}

/// Expects the same shading away from silhouettes, but for 1 % of the pixels compared.
inline void expectSameShading(const Image &ours, const Image &theirs, const char *what) {
    ShadingDifference d = shadingDifference(ours, theirs);
    std::printf("%s shading: %d pixels compared, mean difference %.3g, %d off by > 0.02\n", what,
                d.compared, d.mean, d.off);
    EXPECT_GT(d.compared, ours.width() * ours.height() / 10);
    EXPECT_LT(d.off, d.compared / 100 + 5);
}

}  // namespace rt::test
