// SPDX-License-Identifier: MIT
// Base colour textures in POV-Ray SDL: the pigment written for each wrap mode, filter,
// KHR_texture_transform and alpha mode, and (with povray installed) POV-Ray's picture of a
// flat, unlit textured quad against scadray's sampler evaluated at every pixel centre.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/image/image_io.h"
#include "core/ir/scene_defaults.h"
#include "core/materials/texture_sampler.h"
#include "exporters/povray/pov_format.h"
#include "exporters/povray/pov_runner.h"
#include "exporters/povray/pov_texture.h"
#include "exporters/povray/pov_writer.h"

namespace rt {
namespace {

using Wrap = ir::Texture::Wrap;
using Mode = pov::TextureAlpha::Mode;

/// 5 x 3 texture with distinct texels (and alpha falling left to right).
ir::Texture texture(Wrap u, Wrap v, bool nearest) {
    ir::Texture t;
    t.width = 5;
    t.height = 3;
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x)
            t.rgba.insert(t.rgba.end(),
                          {x / 4.0f, y / 2.0f, float((x * 7 + y * 3) % 5) / 4, 1.0f - x / 4.0f});
    t.wrapU = u;
    t.wrapV = v;
    t.nearest = nearest;
    return t;
}

int count(const std::string &text, const std::string &what) {
    int n = 0;
    for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
    return n;
}

pov::UvRange range(double u0, double u1, double v0, double v1) {
    pov::UvRange r;
    r.add(u0, v0);
    r.add(u1, v1);
    return r;
}

TEST(PovTexture, RepeatLinearIsThePlainImageMap) {
    ir::Texture t = texture(Wrap::Repeat, Wrap::Repeat, false);
    pov::TexturePigment p =
        pov::texturePigment(t, {}, Rgb(1), {}, range(0, 1, 0, 1), 0, 0.25, "tex");
    ASSERT_EQ(p.files.size(), 1u);
    EXPECT_EQ(p.files[0].image.width(), 5);
    EXPECT_EQ(p.files[0].image.height(), 3);
    EXPECT_EQ(count(p.sdl,
                    "image_map { png \"tex.png\" gamma 1.0 interpolate 2 filter all 0 "
                    "transmit all 0.25 }"),
              1);
    EXPECT_EQ(count(p.sdl, "matrix"), 0);
}

TEST(PovTexture, NearestLeavesOutInterpolation) {
    ir::Texture t = texture(Wrap::Repeat, Wrap::Repeat, true);
    pov::TexturePigment p = pov::texturePigment(t, {}, Rgb(1), {}, {}, 0, 0, "tex");
    EXPECT_EQ(count(p.sdl, "interpolate"), 0);
}

TEST(PovTexture, ClampPadsAsFarAsTheCoordinatesReach) {
    ir::Texture t = texture(Wrap::ClampToEdge, Wrap::MirroredRepeat, false);
    // u from -1 to 2: 5 texels each side, plus 2 spare; v mirrored: the image doubled
    pov::TexturePigment p =
        pov::texturePigment(t, {}, Rgb(0.5), {}, range(-1, 2, 0, 1), 0, 0, "tex");
    ASSERT_EQ(p.files.size(), 1u);
    const Image &img = p.files[0].image;
    EXPECT_EQ(img.width(), 5 + 7 + 7);
    EXPECT_EQ(img.height(), 6);
    // Edge texels copied outwards, rows mirrored, the factor applied
    EXPECT_FLOAT_EQ(img.at(0, 0).r, 0.0f);
    EXPECT_FLOAT_EQ(img.at(18, 0).r, 0.5f);
    EXPECT_FLOAT_EQ(img.at(9, 2).g, 0.5f);  // row 2
    EXPECT_FLOAT_EQ(img.at(9, 3).g, 0.5f);  // row 2 mirrored
    EXPECT_FLOAT_EQ(img.at(9, 5).g, 0.0f);  // row 0 mirrored
    EXPECT_EQ(count(p.sdl, "matrix"), 1);
}

TEST(PovTexture, ClampPaddingStopsAtTheLimitAndSaysSo) {
    ir::Texture t = texture(Wrap::ClampToEdge, Wrap::Repeat, false);
    pov::TexturePigment p =
        pov::texturePigment(t, {}, Rgb(1), {}, range(-1e6, 1e6, 0, 1), 0, 0, "tex");
    EXPECT_LE(p.files[0].image.width(), pov::kMaxBakedTextureSide);
    EXPECT_EQ(count(p.sdl, "clamp to edge along u holds for texture coordinates"), 1);
}

TEST(PovTexture, AlphaModesSelectBetweenClearAndOpaqueByTheAlphaImage) {
    ir::Texture t = texture(Wrap::Repeat, Wrap::Repeat, false);
    pov::TextureAlpha mask{Mode::Mask, 0.8, 0.3};
    pov::TexturePigment p = pov::texturePigment(t, {}, Rgb(1), mask, {}, 0, 0, "tex");
    ASSERT_EQ(p.files.size(), 2u);
    EXPECT_EQ(p.files[1].fileName, "tex_alpha.png");
    EXPECT_FLOAT_EQ(p.files[1].image.at(0, 0).r, 0.8f);  // alpha 1 x factor 0.8
    // MASK: a texture_map whose cut-out entry has neither colour nor finish (POV-Ray would add
    // the highlights of a transmit 1 pigment), the material's finish on the texels there
    std::string body = p.body("    finish { specular 0.5 }\n");
    EXPECT_EQ(count(body, "image_pattern { png \"tex_alpha.png\""), 1);
    EXPECT_EQ(count(body, "[0.3 pigment { rgbt 1 } finish { ambient 0 diffuse 0 }]"), 1);
    EXPECT_EQ(count(body, "finish { specular 0.5 }"), 1);
    EXPECT_EQ(count(body, "image_map"), 1);
    pov::TextureAlpha blend{Mode::Blend, 1, 0.5};
    p = pov::texturePigment(t, {}, Rgb(1), blend, {}, 0, 0, "tex");
    EXPECT_EQ(count(p.sdl, "[0 image_map"), 1);
    EXPECT_EQ(count(p.sdl, "[1 image_map"), 1);
}

TEST(PovWriter, MeshCarriesTheCoordinateSetItsTextureReads) {
    ir::Scene s;
    auto mesh = std::make_shared<ir::Mesh>();
    mesh->positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    mesh->triangles = {{0, 1, 2}};
    mesh->uvs = {{0, 0}, {1, 0}, {0, 1}};
    mesh->uvs1 = {{0.25f, 0.5f}, {0.75f, 0.5f}, {0.25f, 0.75f}};
    s.meshes.push_back(mesh);
    s.textures.push_back(std::make_shared<ir::Texture>(texture(Wrap::Repeat, Wrap::Repeat, false)));
    ir::Material m;
    m.baseColorTexture.texture = 0;
    m.baseColorTexture.texCoord = 1;
    int mat = s.addMaterial(m);
    auto primitive = [](int material) {
        auto node = std::make_unique<ir::Node>();
        node->kind = ir::NodeKind::Primitive;
        node->shape = ir::MeshPrim{0};
        node->material = material;
        return node;
    };
    s.root = std::make_unique<ir::Node>();
    s.root->children.push_back(primitive(mat));
    DiagnosticSink diag;
    ir::completeScene(s, diag);
    std::string sdl = pov::writeSdl(s, "uv1");
    EXPECT_EQ(count(sdl, "<0.25, 0.5>"), 1);  // TEXCOORD_1 (0.25, 0.5) with v flipped
    EXPECT_EQ(count(sdl, "<1, 1>"), 0);       // not TEXCOORD_0's (1, 0)

    // A second material on the same mesh reading TEXCOORD_0: the conflict is named
    ir::Material m0 = m;
    m0.baseColorTexture.texCoord = 0;
    m0.color = Rgb(0.5);
    s.root->children.push_back(primitive(s.addMaterial(m0)));
    sdl = pov::writeSdl(s, "uv01");
    EXPECT_EQ(count(sdl, "read both TEXCOORD_0 and TEXCOORD_1"), 1);
    EXPECT_EQ(count(sdl, "<1, 1>"), 1);
}

// ---- POV-Ray against the sampler -------------------------------------------------------------

constexpr int kSize = 48;
/// The quad's texture coordinates: u from kU0 (left) to kU1, v from kV0 (top) to kV1.
constexpr double kU0 = -0.7, kU1 = 1.9, kV0 = -0.45, kV1 = 1.6;
const Rgb kBackground(0.1, 0.2, 0.9);

/// The texture coordinates (before the transform) at the centre of pixel (x, y).
void pixelUv(int x, int y, double *u, double *v) {
    *u = kU0 + (x + 0.5) / kSize * (kU1 - kU0);
    *v = kV0 + (y + 0.5) / kSize * (kV1 - kV0);
}

/// One textured quad of a POV-Ray test picture.
struct Case {
    ir::Texture texture;
    ir::TextureRef ref;
    pov::TextureAlpha alpha;
    std::string label;
};

/// POV-Ray's picture of unit quads in a grid (kSize pixels each, case k in column k % side,
/// row k / side from the top) filling an orthographic view, unlit (ambient 1), each with the
/// pigment texturePigment writes for its case.
Image povrayQuads(const std::vector<Case> &cases, const std::string &name, int side) {
    auto dir = std::filesystem::temp_directory_path() / "scadray_pov_texture";
    std::filesystem::create_directories(dir);
    WriteOptions wo;
    wo.pngDepth = PngDepth::Bits16;
    wo.linearPng = true;
    std::ofstream sdl(dir / (name + ".pov"));
    sdl << "#version 3.7;\n"
        << "global_settings { assumed_gamma 1.0 ambient_light 1 }\n"
        << "background { " << pov::rgb(kBackground) << " }\n"
        << "camera { orthographic location <" << side / 2.0 << ", " << side / 2.0
        << ", -1> direction z right x*" << side << " up y*" << side << " look_at <" << side / 2.0
        << ", " << side / 2.0 << ", 0> }\n";
    // Quad corners (x, y) in POV-Ray space, glTF uv (u, v) there, written as (u, 1 - v)
    auto uv = [](double fx, double fy) {
        return "<" + pov::num(kU0 + fx * (kU1 - kU0)) + ", " +
               pov::num(1 - (kV0 + (1 - fy) * (kV1 - kV0))) + ">";
    };
    for (size_t k = 0; k < cases.size(); ++k) {
        const Case &c = cases[k];
        pov::UvRange r;
        for (double u : {kU0, kU1})
            for (double v : {kV0, kV1}) {
                double tu = u, tv = v;
                transformTexCoord(c.ref, &tu, &tv);
                r.add(tu, tv);
            }
        std::string stem = name + "_" + std::to_string(k);
        pov::TexturePigment p =
            pov::texturePigment(c.texture, c.ref, Rgb(1), c.alpha, r, 0, 0, stem);
        for (const pov::TextureFile &f : p.files)
            writeImage(f.image, (dir / f.fileName).string(), wo);
        int col = int(k) % side, row = int(k) / side;
        sdl << "mesh2 { vertex_vectors { 4, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0> }\n"
            << "    uv_vectors { 4, " << uv(0, 0) << ", " << uv(1, 0) << ", " << uv(1, 1) << ", "
            << uv(0, 1) << " }\n"
            << "    face_indices { 2, <0, 1, 2>, <0, 2, 3> }\n"
            << "    texture { uv_mapping\n"
            << p.body("    finish { ambient 1 diffuse 0 }\n") << " }\n"
            << "    translate <" << col << ", " << side - 1 - row << ", 0> }\n";
    }
    sdl.close();
    pov::IniOptions ini;
    ini.povFile = name + ".pov";
    ini.outputFile = name + ".png";
    ini.width = ini.height = kSize * side;
    ini.threads = 2;
    std::ofstream((dir / (name + ".ini")).string()) << pov::writeIni(ini);
    pov::runPovRay(dir.string(), name + ".ini", 2, 60);
    return readImage((dir / ini.outputFile).string(), true);
}

/// What the sampler says at pixel (x, y) of a quad, over the background as POV-Ray composes
/// transmit.
Rgb expected(const Case &c, int x, int y) {
    double u, v;
    pixelUv(x, y, &u, &v);
    transformTexCoord(c.ref, &u, &v);
    float s[4];
    sampleTexture(c.texture, u, v, s);
    double a = std::clamp(s[3] * c.alpha.factor, 0.0, 1.0);
    double transmit = c.alpha.mode == Mode::Blend  ? 1 - a
                      : c.alpha.mode == Mode::Mask ? (a < c.alpha.cutoff ? 1 : 0)
                                                   : 0;
    return Rgb(s[0], s[1], s[2]) * (1 - transmit) + kBackground * transmit;
}

/// For each case, the pixels where POV-Ray's picture differs from the sampler by more than
/// `tol` (any channel), and the largest difference.
std::vector<std::pair<int, double>> differing(const std::vector<Case> &cases,
                                              const std::string &name, double tol) {
    int side = int(std::ceil(std::sqrt(double(cases.size()))));
    Image img = povrayQuads(cases, name, side);
    std::vector<std::pair<int, double>> out;
    for (size_t k = 0; k < cases.size(); ++k) {
        int x0 = int(k) % side * kSize, y0 = int(k) / side * kSize;
        int off = 0;
        double maxDiff = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                Rgb e = expected(cases[k], x, y), g = img.at(x0 + x, y0 + y);
                double d =
                    std::max({std::abs(e.r - g.r), std::abs(e.g - g.g), std::abs(e.b - g.b)});
                maxDiff = std::max(maxDiff, d);
                off += d > tol;
            }
        std::printf("%-40s %4d pixels off, max difference %.2g\n", cases[k].label.c_str(), off,
                    maxDiff);
        out.push_back({off, maxDiff});
    }
    return out;
}

TEST(PovTextureRender, EveryWrapModeAndFilterReadsTheSamplersTexels) {
    if (!pov::povrayAvailable()) GTEST_SKIP() << "POV-Ray (povray) is not installed";
    ir::TextureRef rotated;
    rotated.rotation = 0.4;
    rotated.scaleU = 1.3;
    rotated.scaleV = 0.8;
    rotated.offsetU = 0.2;
    rotated.offsetV = -0.1;
    const char *names[] = {"repeat", "clamp", "mirror"};
    std::vector<Case> cases;
    for (Wrap wu : {Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat})
        for (Wrap wv : {Wrap::Repeat, Wrap::ClampToEdge, Wrap::MirroredRepeat})
            for (bool nearest : {false, true})
                for (const ir::TextureRef &ref : {ir::TextureRef{}, rotated})
                    cases.push_back({texture(wu, wv, nearest),
                                     ref,
                                     {},
                                     std::string(names[int(wu)]) + " x " + names[int(wv)] +
                                         (nearest ? " nearest" : " linear") +
                                         (ref.hasTransform() ? " transformed" : "")});
    auto result = differing(cases, "wrap", 2e-3);
    for (size_t k = 0; k < cases.size(); ++k) {
        SCOPED_TRACE(cases[k].label);
        // 16-bit PNGs: differences of 1/65535; a nearest lookup may fall on the other side of
        // a texel edge that a pixel centre grazes
        EXPECT_LE(result[k].first, cases[k].texture.nearest ? 2 : 0) << result[k].second;
    }
}

TEST(PovTextureRender, AlphaShowsTheBackgroundThroughCutOutAndBlendedTexels) {
    if (!pov::povrayAvailable()) GTEST_SKIP() << "POV-Ray (povray) is not installed";
    std::vector<Case> cases;
    for (bool nearest : {false, true}) {
        ir::Texture t = texture(Wrap::Repeat, Wrap::ClampToEdge, nearest);
        std::string f = nearest ? " nearest" : " linear";
        cases.push_back({t, {}, {Mode::Mask, 0.9, 0.5}, "mask" + f});
        cases.push_back({t, {}, {Mode::Blend, 0.7, 0.5}, "blend" + f});
    }
    auto result = differing(cases, "alpha", 2e-3);
    for (size_t k = 0; k < cases.size(); ++k) {
        SCOPED_TRACE(cases[k].label);
        EXPECT_LE(result[k].first, cases[k].texture.nearest ? 2 : 0) << result[k].second;
    }
    // Known pixels: the background shows through where the mask cuts (alpha x 0.9 < 0.5 at
    // the right, where the texture's alpha falls to 0), the texture where it does not
    Image img = povrayQuads({cases[0]}, "mask_only", 1);
    double u, v;
    pixelUv(kSize - 3, kSize / 2, &u, &v);  // u = 1.8: texel 4 (alpha 0) blended with 0
    EXPECT_NEAR(img.at(kSize - 3, kSize / 2).b, kBackground.b, 1e-3);
}

}  // namespace
}  // namespace rt
