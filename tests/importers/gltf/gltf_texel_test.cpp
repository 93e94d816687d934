// SPDX-License-Identifier: MIT
// glTF materials evaluated per texel: known-answer renders of generated models. A
// normal-mapped flat quad shades like the faceted relief it encodes, a roughness texture like
// quads of constant roughness, alpha MASK cuts holes that rays and shadow rays pass, BLEND
// alpha from a texture equals the factor's, occlusion scales only the ambient term; and the
// pieces: generated tangents, the extension mappings, the unmapped-extension warning.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "core/materials/pbr_material.h"
#include "core/render/render_scene.h"
#include "core/render/renderer.h"
#include "importers/gltf/gltf_tangents.h"
#include "tests/importers/gltf/gltf_test_support.h"

namespace rt::gltf::test {
namespace {

std::string bmpUri(const std::vector<unsigned char> &bmp) {
    return "data:image/bmp;base64," + base64Encode(bmp);
}

/// One glTF primitive: positions (x, y, z triples), optional TEXCOORD_0, triangles.
struct Prim {
    std::vector<float> pos, uv;
    std::vector<uint32_t> idx;
    int material = 0;
};

/// A quad [x0,x1] x [y0,y1] at height z (glTF axes), facing +z, with u = x, v = 1 - y.
Prim quad(double x0, double x1, double y0, double y1, double z, int material) {
    Prim p;
    p.pos = {float(x0), float(y0), float(z), float(x1), float(y0), float(z),
             float(x1), float(y1), float(z), float(x0), float(y1), float(z)};
    p.uv = {float(x0), float(1 - y0), float(x1), float(1 - y0),
            float(x1), float(1 - y1), float(x0), float(1 - y1)};
    p.idx = {0, 1, 2, 0, 2, 3};
    p.material = material;
    return p;
}

/// A glTF with one node and one mesh holding `prims`, the given materials JSON array and
/// images (one texture each, clamped, bilinear).
std::string gltfOf(const std::vector<Prim> &prims, const std::string &materials,
                   const std::vector<std::string> &imageUris, const std::string &extra = "") {
    TestBuffer buf;
    std::string views, accessors, primitives;
    int view = 0;
    auto addView = [&](size_t offset, size_t length) {
        views += (view ? "," : "") + viewJson(offset, length);
        return view++;
    };
    int acc = 0;
    auto addAccessor = [&](int v, int type, size_t count, const char *kind, const std::string &mm) {
        accessors += (acc ? "," : "") + std::string("{\"bufferView\":") + std::to_string(v) +
                     ",\"componentType\":" + std::to_string(type) +
                     ",\"count\":" + std::to_string(count) + ",\"type\":\"" + kind + "\"" + mm +
                     "}";
        return acc++;
    };
    for (size_t i = 0; i < prims.size(); ++i) {
        const Prim &p = prims[i];
        float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
        for (size_t k = 0; k < p.pos.size(); ++k) {
            lo[k % 3] = std::min(lo[k % 3], p.pos[k]);
            hi[k % 3] = std::max(hi[k % 3], p.pos[k]);
        }
        std::string mm = ",\"min\":[" + std::to_string(lo[0]) + "," + std::to_string(lo[1]) + "," +
                         std::to_string(lo[2]) + "],\"max\":[" + std::to_string(hi[0]) + "," +
                         std::to_string(hi[1]) + "," + std::to_string(hi[2]) + "]";
        int posAcc = addAccessor(addView(buf.add(p.pos), p.pos.size() * 4), 5126, p.pos.size() / 3,
                                 "VEC3", mm);
        std::string attrs = "\"POSITION\":" + std::to_string(posAcc);
        if (!p.uv.empty()) {
            int uvAcc = addAccessor(addView(buf.add(p.uv), p.uv.size() * 4), 5126, p.uv.size() / 2,
                                    "VEC2", "");
            attrs += ",\"TEXCOORD_0\":" + std::to_string(uvAcc);
        }
        int idxAcc = addAccessor(addView(buf.add(p.idx), p.idx.size() * 4), 5125, p.idx.size(),
                                 "SCALAR", "");
        primitives += (i ? "," : "") + std::string("{\"attributes\":{") + attrs +
                      "},\"indices\":" + std::to_string(idxAcc) +
                      ",\"material\":" + std::to_string(p.material) + "}";
    }
    std::string images, textures;
    for (size_t i = 0; i < imageUris.size(); ++i) {
        images += (i ? "," : "") + std::string("{\"uri\":\"") + imageUris[i] + "\"}";
        textures +=
            (i ? "," : "") + std::string("{\"source\":") + std::to_string(i) + ",\"sampler\":0}";
    }
    std::string text = R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
                       R"("nodes":[{"mesh":0}],"meshes":[{"primitives":[)" +
                       primitives + "]}],\"materials\":" + materials + ",\"buffers\":[" +
                       buf.json() + "],\"bufferViews\":[" + views + "],\"accessors\":[" +
                       accessors + "]";
    if (!imageUris.empty())
        text += ",\"images\":[" + images + "],\"textures\":[" + textures +
                "],\"samplers\":[{\"wrapS\":33071,\"wrapT\":33071}]";
    return text + extra + "}";
}

struct Imported {
    ir::Scene scene;
    DiagnosticSink diag;
};

std::unique_ptr<Imported> importText(const TempDir &tmp, const std::string &text,
                                     const std::string &name = "texel.gltf") {
    auto result = std::make_unique<Imported>();
    writeText(tmp.file(name), text);
    result->scene = importGltf(tmp.file(name), result->diag);
    return result;
}

/// What the renders see: an orthographic camera looking down glTF's -z at the square
/// [cx - size/2, cx + size/2] x [cy - size/2, cy + size/2] of the glTF xy plane, a directional
/// light shining along `lightDir` (glTF axes), a blue background.
struct View {
    double cx = 0.5, cy = 0.5, size = 1.2;
    Vec3 lightDir{0.2, -0.1, -1};
    bool light = true;
    int pixels = 48;
};

/// glTF (x, y, z) in the importer's world.
Vec3 world(const Vec3 &g) { return zUp(g); }

Image render(ir::Scene &scene, const View &v) {
    ir::Camera cam;
    cam.projection = ir::Projection::Orthographic;
    cam.orthoHeight = v.size;
    cam.location = world(Vec3(v.cx, v.cy, 10));
    cam.lookAt = world(Vec3(v.cx, v.cy, 0));
    cam.sky = world(Vec3(0, 1, 0));
    scene.camera = cam;
    scene.lights.clear();
    if (v.light) {
        ir::Light l;
        l.kind = ir::Light::Kind::Directional;
        l.direction = normalize(world(v.lightDir));
        l.position = world(Vec3(v.cx, v.cy, 0)) - l.direction * 100;
        scene.lights.push_back(l);
    }
    scene.settings.background = Rgb(0, 0, 0.5);
    scene.settings.adcBailout = 0;
    DiagnosticSink diag;
    auto rs = RenderScene::compile(scene, diag);
    RenderOptions o;
    o.width = v.pixels;
    o.height = v.pixels;
    o.threads = 1;
    return renderImage(*rs, o).image;
}

/// The pixel that sees glTF point (x, y) of the plane.
Rgb pixelAt(const Image &img, const View &v, double x, double y) {
    int px = static_cast<int>(std::floor((x - (v.cx - v.size / 2)) / v.size * v.pixels));
    int py = static_cast<int>(std::floor(((v.cy + v.size / 2) - y) / v.size * v.pixels));
    return img.at(px, py);
}

void expectSameRgb(const Rgb &a, const Rgb &b, double tol, const std::string &where) {
    EXPECT_NEAR(a.r, b.r, tol) << where;
    EXPECT_NEAR(a.g, b.g, tol) << where;
    EXPECT_NEAR(a.b, b.b, tol) << where;
}

/// Appends to `p` the facet over [x0, x1] x [0, 1] (glTF xy) of the plane with normal `n`
/// through (xz, 0, 0): the relief a normal map encodes, as geometry.
void addFacet(Prim &p, const Vec3 &n, double x0, double x1, double xz) {
    auto z = [&](double x, double y) { return -(n.x * (x - xz) + n.y * y) / n.z; };
    uint32_t b = static_cast<uint32_t>(p.pos.size() / 3);
    for (auto [x, y] : {std::pair{x0, 0.0}, {x1, 0.0}, {x1, 1.0}, {x0, 1.0}})
        for (double c : {x, y, z(x, y)}) p.pos.push_back(float(c));
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) p.idx.push_back(b + i);
}

const std::string kGrey =
    R"({"pbrMetallicRoughness":{"baseColorFactor":[0.8,0.7,0.6,1],"metallicFactor":0,"roughnessFactor":1}})";

// (a) A flat quad with a normal map shades like the sawtooth of facets it encodes.
TEST(GltfTexel, NormalMappedQuadShadesLikeTheFacetsItEncodes) {
    // Four bands, each a tilt towards +x (and a little +y), 4 texels wide so band interiors
    // see one value through the bilinear filter
    const int red[4] = {150, 175, 200, 225};
    const int green = 140;
    Vec3 normals[4];
    std::vector<int> blue(4);
    for (int k = 0; k < 4; ++k) {
        double x = 2 * red[k] / 255.0 - 1, y = 2 * green / 255.0 - 1;
        blue[static_cast<size_t>(k)] =
            static_cast<int>(std::lround((std::sqrt(1 - x * x - y * y) * 0.5 + 0.5) * 255));
        normals[k] = normalize(Vec3(x, y, 2 * blue[static_cast<size_t>(k)] / 255.0 - 1));
    }
    auto normalMap = bmp32(16, 4, [&](int x, int) {
        int k = x / 4;
        return uint32_t(red[k]) << 24 | uint32_t(green) << 16 |
               uint32_t(blue[static_cast<size_t>(k)]) << 8 | 0xff;
    });
    std::string mapped = R"([{"pbrMetallicRoughness":{"baseColorFactor":[0.8,0.7,0.6,1],)"
                         R"("metallicFactor":0,"roughnessFactor":1},"normalTexture":{"index":0}}])";
    TempDir tmp;
    auto flat =
        importText(tmp, gltfOf({quad(0, 1, 0, 1, 0, 0)}, mapped, {bmpUri(normalMap)}), "flat.gltf");
    EXPECT_EQ(flat->diag.count(Severity::Warning), 0);
    ASSERT_EQ(flat->scene.meshes.size(), 1u);
    EXPECT_EQ(flat->scene.meshes[0]->tangents.size(), 4u) << "tangents generated";

    // The same relief as geometry: band k is the plane through (k/4, 0, 0) with normal n_k
    Prim facets;
    for (int k = 0; k < 4; ++k) addFacet(facets, normals[k], k / 4.0, (k + 1) / 4.0, k / 4.0);
    auto relief = importText(tmp, gltfOf({facets}, "[" + kGrey + "]", {}), "relief.gltf");

    View v;
    Image a = render(flat->scene, v), b = render(relief->scene, v);
    Rgb previous(0);
    for (int k = 0; k < 4; ++k)
        for (double y : {0.3, 0.5, 0.7}) {
            double x = (k + 0.5) / 4;
            Rgb pa = pixelAt(a, v, x, y), pb = pixelAt(b, v, x, y);
            expectSameRgb(pa, pb, 2e-3, "band " + std::to_string(k) + " y " + std::to_string(y));
            if (y != 0.5) continue;
            if (k > 0) {
                EXPECT_GT(std::abs(pa.r - previous.r), 0.01) << "bands differ";
            }
            previous = pa;
        }
    // Without the map the quad is one flat shade
    auto plain = importText(tmp, gltfOf({quad(0, 1, 0, 1, 0, 0)}, "[" + kGrey + "]", {}), "p.gltf");
    Image c = render(plain->scene, v);
    EXPECT_GT(std::abs(pixelAt(c, v, 0.875, 0.5).r - pixelAt(a, v, 0.875, 0.5).r), 0.02);
}

// (a') Mirrored texture coordinates: the two halves of a quad read the same normal-map texels
// with u running opposite ways, so the relief is mirrored about the seam. The vertices on the
// seam carry both handednesses: without MikkTSpace's vertex split their tangents average to
// nothing and the halves shade wrongly near (and, interpolated, across) them.
TEST(GltfTexel, MirroredUvSeamSplitsTangentsAndShadesLikeTheMirroredRelief) {
    // One tilt everywhere in the texture: towards +u and a little +v' (up the image)
    const int red = 200, green = 150;
    double x = 2 * red / 255.0 - 1, y = 2 * green / 255.0 - 1;
    int blue = static_cast<int>(std::lround((std::sqrt(1 - x * x - y * y) * 0.5 + 0.5) * 255));
    Vec3 n = normalize(Vec3(x, y, 2 * blue / 255.0 - 1));
    auto normalMap = bmp32(4, 4, [&](int, int) {
        return uint32_t(red) << 24 | uint32_t(green) << 16 | uint32_t(blue) << 8 | 0xff;
    });
    // Six vertices: x = 0, 0.5, 1 at y = 0 and y = 1; u = x on the left, 1 - x on the right
    Prim mirrored;
    mirrored.pos = {0, 0, 0, 0.5f, 0, 0, 1, 0, 0, 0, 1, 0, 0.5f, 1, 0, 1, 1, 0};
    mirrored.uv = {0, 1, 0.5f, 1, 0, 1, 0, 0, 0.5f, 0, 0, 0};
    mirrored.idx = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4};
    std::string mapped = R"([{"pbrMetallicRoughness":{"baseColorFactor":[0.8,0.7,0.6,1],)"
                         R"("metallicFactor":0,"roughnessFactor":1},"normalTexture":{"index":0}}])";
    TempDir tmp;
    auto flat = importText(tmp, gltfOf({mirrored}, mapped, {bmpUri(normalMap)}), "mirror.gltf");
    ASSERT_EQ(flat->scene.meshes.size(), 1u);
    EXPECT_EQ(flat->scene.meshes[0]->tangents.size(), 8u) << "the two seam vertices split";

    // The relief as geometry: left half tilted by n, right half by n mirrored in x, meeting
    // along x = 0.5
    Prim ridge;
    addFacet(ridge, n, 0, 0.5, 0.5);
    addFacet(ridge, Vec3(-n.x, n.y, n.z), 0.5, 1, 0.5);
    auto relief = importText(tmp, gltfOf({ridge}, "[" + kGrey + "]", {}), "ridge.gltf");

    View v;
    v.lightDir = Vec3(0.5, -0.3, -1);
    Image a = render(flat->scene, v), b = render(relief->scene, v);
    for (double px : {0.1, 0.3, 0.45, 0.55, 0.7, 0.9})
        for (double py : {0.2, 0.5, 0.8})
            expectSameRgb(pixelAt(a, v, px, py), pixelAt(b, v, px, py), 2e-3,
                          "at " + std::to_string(px) + "," + std::to_string(py));
    EXPECT_GT(std::abs(pixelAt(a, v, 0.3, 0.5).r - pixelAt(a, v, 0.7, 0.5).r), 0.02)
        << "the halves face different ways";
}

// (b) A roughness texture in four bands equals four quads of those constant roughnesses.
TEST(GltfTexel, RoughnessTextureEqualsQuadsOfConstantRoughness) {
    const int rough[4] = {40, 90, 150, 220};
    auto mr = bmp32(16, 4, [&](int x, int) {
        return uint32_t(rough[x / 4]) << 16 | uint32_t(255) << 8 | 0xff;  // G rough, B metal
    });
    std::string textured = R"([{"pbrMetallicRoughness":{"baseColorFactor":[0.9,0.6,0.3,1],)"
                           R"("metallicFactor":0.5,"roughnessFactor":1,)"
                           R"("metallicRoughnessTexture":{"index":0}}}])";
    std::string constants = "[";
    std::vector<Prim> quads;
    for (int k = 0; k < 4; ++k) {
        constants +=
            std::string(k ? "," : "") +
            R"({"pbrMetallicRoughness":{"baseColorFactor":[0.9,0.6,0.3,1],"metallicFactor":0.5,"roughnessFactor":)" +
            std::to_string(rough[k] / 255.0) + "}}";
        quads.push_back(quad(k / 4.0, (k + 1) / 4.0, 0, 1, 0, k));
    }
    constants += "]";
    TempDir tmp;
    auto a = importText(tmp, gltfOf({quad(0, 1, 0, 1, 0, 0)}, textured, {bmpUri(mr)}), "a.gltf");
    auto b = importText(tmp, gltfOf(quads, constants, {}), "b.gltf");
    View v;
    v.lightDir = Vec3(0.1, 0.05, -1);  // a highlight on every band
    Image ia = render(a->scene, v), ib = render(b->scene, v);
    for (int k = 0; k < 4; ++k)
        for (double y : {0.25, 0.5, 0.75}) {
            double x = (k + 0.5) / 4;
            expectSameRgb(pixelAt(ia, v, x, y), pixelAt(ib, v, x, y), 1e-4,
                          "band " + std::to_string(k));
        }
    EXPECT_GT(std::abs(pixelAt(ia, v, 0.125, 0.5).r - pixelAt(ia, v, 0.875, 0.5).r), 0.01);
}

/// A texture in four bands read by an extension (`ext`, its `textureKey` read in channel
/// `channel` of 0xRRGGBBAA, multiplying `factorKey` set to 1) renders as four quads whose
/// materials have the band values as factors.
void expectBandsEqualFactors(const std::string &ext, const std::string &textureKey,
                             const std::string &factorKey, int channel,
                             const std::string &otherFactors) {
    const int value[4] = {30, 100, 170, 240};
    auto tex = bmp32(16, 4, [&](int x, int) {
        uint32_t px = 0x808080ffu;
        int shift = 24 - 8 * channel;
        px = (px & ~(0xffu << shift)) | uint32_t(value[x / 4]) << shift;
        return px;
    });
    const std::string base = R"("pbrMetallicRoughness":{"baseColorFactor":[0.3,0.4,0.5,1],)"
                             R"("metallicFactor":0,"roughnessFactor":0.4})";
    std::string textured = "[{" + base + R"(,"extensions":{")" + ext + R"(":{")" + factorKey +
                           R"(":1,")" + textureKey + R"(":{"index":0})" + otherFactors + "}}}]";
    std::string constants = "[";
    std::vector<Prim> quads;
    for (int k = 0; k < 4; ++k) {
        constants += std::string(k ? "," : "") + "{" + base + R"(,"extensions":{")" + ext +
                     R"(":{")" + factorKey + "\":" + std::to_string(value[k] / 255.0) +
                     otherFactors + "}}}";
        quads.push_back(quad(k / 4.0, (k + 1) / 4.0, 0, 1, 0, k));
    }
    constants += "]";
    std::string used = ",\"extensionsUsed\":[\"" + ext + "\"]";
    TempDir tmp;
    auto a =
        importText(tmp, gltfOf({quad(0, 1, 0, 1, 0, 0)}, textured, {bmpUri(tex)}, used), "a.gltf");
    auto b = importText(tmp, gltfOf(quads, constants, {}, used), "b.gltf");
    EXPECT_EQ(a->diag.count(Severity::Warning), 0);
    ASSERT_EQ(a->scene.materials.size(), 1u);
    EXPECT_TRUE(a->scene.materials[0].texel.pbr) << "evaluated per texel";
    View v;
    v.lightDir = Vec3(0.1, 0.05, -1);  // a highlight on every band
    v.cy = 0.45;
    Image ia = render(a->scene, v), ib = render(b->scene, v);
    for (int k = 0; k < 4; ++k)
        for (double y : {0.25, 0.5, 0.75}) {
            double x = (k + 0.5) / 4;
            expectSameRgb(pixelAt(ia, v, x, y), pixelAt(ib, v, x, y), 1e-4,
                          ext + " band " + std::to_string(k));
        }
    Rgb first = pixelAt(ia, v, 0.125, 0.5), last = pixelAt(ia, v, 0.875, 0.5);
    EXPECT_GT(std::abs(first.r - last.r) + std::abs(first.b - last.b), 0.01) << "bands differ";
    // The constant fields (POV-Ray export, check) are the mapping of the texture's mean
    std::string meanMaterial = "[{" + base + R"(,"extensions":{")" + ext + R"(":{")" + factorKey +
                               "\":" + std::to_string(135 / 255.0) + otherFactors + "}}}]";
    auto c = importText(tmp, gltfOf({quad(0, 1, 0, 1, 0, 0)}, meanMaterial, {}, used), "c.gltf");
    const ir::Finish &fa = a->scene.materials[0].finish, &fc = c->scene.materials[0].finish;
    EXPECT_NEAR(fa.reflectionMin.r, fc.reflectionMin.r, 1e-6);
    EXPECT_NEAR(fa.reflectionMax.r, fc.reflectionMax.r, 1e-6);
    EXPECT_NEAR(fa.specular, fc.specular, 1e-6);
    EXPECT_NEAR(fa.diffuse, fc.diffuse, 1e-6);
}

// (b') The textures of KHR_materials_clearcoat and _specular, per texel like the others
TEST(GltfTexel, ClearcoatTextureEqualsQuadsOfConstantClearcoat) {
    expectBandsEqualFactors("KHR_materials_clearcoat", "clearcoatTexture", "clearcoatFactor", 0,
                            ",\"clearcoatRoughnessFactor\":0.1");
}

TEST(GltfTexel, SpecularTextureEqualsQuadsOfConstantSpecular) {
    expectBandsEqualFactors("KHR_materials_specular", "specularTexture", "specularFactor", 3, "");
}

/// The checkerboard scene: a red quad (4 x 4 squares, alpha 0 or 1) at z = 0 over a grey
/// floor at z = -1; the light comes in at 45 degrees along +x, so the quad's shadow lies on
/// the floor one unit to the right.
std::unique_ptr<Imported> checkerScene(const TempDir &tmp, const std::string &alphaMode,
                                       uint32_t alphaOff, uint32_t alphaOn) {
    auto tex = bmp32(16, 16, [&](int x, int y) {
        bool on = ((x / 4) + (y / 4)) % 2 == 0;
        return 0xffffff00u | (on ? alphaOn : alphaOff);
    });
    std::string materials =
        R"([{"pbrMetallicRoughness":{"baseColorFactor":[1,0.1,0.1,1],"metallicFactor":0,"roughnessFactor":1,)"
        R"("baseColorTexture":{"index":0}},"alphaMode":")" +
        alphaMode + R"("},)" +
        R"({"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.5,0.5,1],"metallicFactor":0,"roughnessFactor":1}}])";
    return importText(
        tmp, gltfOf({quad(0, 1, 0, 1, 0, 0), quad(-1, 3, -1, 2, -1, 1)}, materials, {bmpUri(tex)}));
}

// (c) MASK: cut-out squares show what lies behind, and the shadow is a checkerboard.
TEST(GltfTexel, MaskCutsHolesThatRaysAndShadowsPass) {
    TempDir tmp;
    auto im = checkerScene(tmp, "MASK", 0x00, 0xff);
    EXPECT_EQ(im->diag.countContaining("not rendered"), 0);
    View v;
    v.cx = 1;
    v.size = 2.4;
    v.lightDir = Vec3(1, 0, -1);
    Image img = render(im->scene, v);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            bool on = (i + j) % 2 == 0;  // texel column i, row j (row 0 at the top, y = 1)
            double x = (i + 0.5) / 4, y = 1 - (j + 0.5) / 4;
            Rgb quadPixel = pixelAt(img, v, x, y);
            std::string where = "square " + std::to_string(i) + "," + std::to_string(j);
            if (on) {
                EXPECT_GT(quadPixel.r, 3 * quadPixel.g) << where << ": the red quad";
            } else {
                EXPECT_NEAR(quadPixel.r, quadPixel.g, 1e-6) << where << ": the grey floor";
            }
            // The shadow, one unit to the right on the floor
            Rgb floor = pixelAt(img, v, x + 1, y);
            Rgb lit = pixelAt(img, v, 2.1, 0.5);  // beyond the shadow
            if (on) {
                EXPECT_LT(floor.r, 0.5 * lit.r) << where << ": in the square's shadow";
            } else {
                EXPECT_NEAR(floor.r, lit.r, 1e-6) << where << ": lit through the hole";
            }
        }
    // Its object is not opaque to the shadow plan
    EXPECT_TRUE(im->scene.materials[0].isTransparent() || im->scene.materials[1].isTransparent());
}

// (d) BLEND: half alpha from the texture renders as half alpha from the factor.
TEST(GltfTexel, BlendAlphaFromTheTextureEqualsTheFactors) {
    TempDir tmp;
    auto textured = checkerScene(tmp, "BLEND", 0x80, 0x80);
    std::string materials =
        R"([{"pbrMetallicRoughness":{"baseColorFactor":[1,0.1,0.1,)" + std::to_string(128 / 255.0) +
        R"(],"metallicFactor":0,"roughnessFactor":1},"alphaMode":"BLEND"},)" +
        R"({"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.5,0.5,1],"metallicFactor":0,"roughnessFactor":1}}])";
    auto factor = importText(
        tmp, gltfOf({quad(0, 1, 0, 1, 0, 0), quad(-1, 3, -1, 2, -1, 1)}, materials, {}), "f.gltf");
    View v;
    v.cx = 1;
    v.size = 2.4;
    v.lightDir = Vec3(1, 0, -1);
    Image a = render(textured->scene, v), b = render(factor->scene, v);
    for (double x : {0.3, 0.6, 1.3, 1.7})
        for (double y : {0.3, 0.7})
            expectSameRgb(pixelAt(a, v, x, y), pixelAt(b, v, x, y), 1e-5,
                          "at " + std::to_string(x) + "," + std::to_string(y));
    // Half of each: neither the floor nor the quad alone
    Rgb mid = pixelAt(a, v, 0.5, 0.5);
    EXPECT_GT(mid.r, mid.g * 1.2);
    EXPECT_GT(mid.g, 0.02);
}

// (e) Occlusion darkens the ambient term and nothing else.
TEST(GltfTexel, OcclusionScalesOnlyTheAmbientTerm) {
    auto occ = bmp32(4, 4, [](int, int) { return 0x40404000u | 0xff; });  // R = 64
    std::string withOcc = R"([{"pbrMetallicRoughness":{"baseColorFactor":[0.8,0.7,0.6,1],)"
                          R"("metallicFactor":0,"roughnessFactor":0.5},)"
                          R"("occlusionTexture":{"index":0,"strength":0.8}}])";
    std::string without = R"([{"pbrMetallicRoughness":{"baseColorFactor":[0.8,0.7,0.6,1],)"
                          R"("metallicFactor":0,"roughnessFactor":0.5}}])";
    TempDir tmp;
    auto a = importText(tmp, gltfOf({quad(0, 1, 0, 1, 0, 0)}, withOcc, {bmpUri(occ)}), "a.gltf");
    auto b = importText(tmp, gltfOf({quad(0, 1, 0, 1, 0, 0)}, without, {}), "b.gltf");
    View lit, dark;
    dark.light = false;
    double o = 1 + 0.8 * (64 / 255.0 - 1);
    Rgb fullA = pixelAt(render(a->scene, lit), lit, 0.5, 0.5);
    Rgb fullB = pixelAt(render(b->scene, lit), lit, 0.5, 0.5);
    Rgb ambA = pixelAt(render(a->scene, dark), dark, 0.5, 0.5);
    Rgb ambB = pixelAt(render(b->scene, dark), dark, 0.5, 0.5);
    // Ambient (plus the reflected background) scaled by o in its ambient part only
    Rgb reflB = Rgb(0);  // the reflection of the background is the same in both
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(fullB[c] - fullA[c], ambB[c] - ambA[c], 1e-5) << "channel " << c;
        reflB[c] = ambB[c] - ambA[c];
    }
    // The material's own ambient term is 0.1 x the colour; the difference is (1 - o) of it
    EXPECT_NEAR(reflB.r, 0.1 * 0.8 * (1 - o), 1e-4);
    EXPECT_GT(fullA.r, ambA.r + 0.1) << "the light still shines";
}

// The constant fields hold the means (POV-Ray export); untextured materials carry no texel
// description; the per-texel ones compare by value.
TEST(GltfTexel, TexturedMaterialsKeepTheirMeansAndUntexturedOnesNoDescription) {
    auto mr = bmp32(2, 1, [](int x, int) { return (x ? 0x00ccff00u : 0x0044ff00u) | 0xff; });
    std::string materials =
        R"([{"pbrMetallicRoughness":{"metallicFactor":1,"roughnessFactor":1,"metallicRoughnessTexture":{"index":0}}},)"
        R"({"pbrMetallicRoughness":{"metallicFactor":1,"roughnessFactor":0.533333333}}])";
    TempDir tmp;
    auto im = importText(
        tmp, gltfOf({quad(0, 1, 0, 1, 0, 0), quad(2, 3, 0, 1, 0, 1)}, materials, {bmpUri(mr)}));
    ASSERT_EQ(im->scene.materials.size(), 2u);
    const ir::Material &textured = im->scene.materials[0], &plain = im->scene.materials[1];
    ASSERT_TRUE(textured.texel.pbr);
    EXPECT_FALSE(plain.texel.pbr);
    // Mean roughness (0x44 + 0xcc) / 2 / 255 = 0.5333: the constant fields are the plain one's
    EXPECT_NEAR(textured.finish.roughness, plain.finish.roughness, 1e-6);
    EXPECT_NEAR(textured.finish.specular, plain.finish.specular, 1e-6);
    EXPECT_FALSE(textured.sameAppearance(plain));
    ir::Material copy = textured;
    copy.texel.pbr = std::make_shared<const PbrMaterial>(*textured.texel.pbr);
    EXPECT_TRUE(copy.sameAppearance(textured)) << "compared by value";
    // The metallic-roughness data is linear, not sRGB-decoded
    const ir::Texture &tex =
        *im->scene
             .textures[static_cast<size_t>(textured.texel.pbr->metallicRoughnessTexture.texture)];
    EXPECT_NEAR(tex.rgba[1], 0x44 / 255.0, 1e-6);
}

TEST(GltfTexel, GeneratedTangentsFollowUAndTheHandedness) {
    ir::Mesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)};
    m.uvs = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};  // v down the image: +y is "up"
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    ASSERT_TRUE(detail::generateTangents(m, 0));
    for (const auto &t : m.tangents) {
        EXPECT_NEAR(t[0], 1, 1e-6);
        EXPECT_NEAR(t[1], 0, 1e-6);
        EXPECT_EQ(t[3], 1);
    }
    // Mirrored in v: the bitangent flips
    for (auto &uv : m.uvs) uv[1] = 1 - uv[1];
    ASSERT_TRUE(detail::generateTangents(m, 0));
    for (const auto &t : m.tangents) EXPECT_EQ(t[3], -1);
    // Mirrored in u on the right half: the seam vertices 1 and 4 split, each side its own
    // tangent (+x on the left, -x on the right) and handedness
    ir::Mesh seam;
    seam.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0),
                      Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(2, 1, 0)};
    seam.uvs = {{0, 1}, {1, 1}, {0, 1}, {0, 0}, {1, 0}, {0, 0}};
    seam.colors.assign(6, {0.5f, 0.5f, 0.5f, 1});
    seam.triangles = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}};
    ASSERT_TRUE(detail::generateTangents(seam, 0));
    ASSERT_EQ(seam.positions.size(), 8u);
    ASSERT_EQ(seam.tangents.size(), 8u);
    EXPECT_EQ(seam.colors.size(), 8u);
    for (size_t k = 0; k < seam.triangles.size(); ++k)
        for (uint32_t v : seam.triangles[k]) {
            const auto &t = seam.tangents[v];
            bool left = k < 2;
            EXPECT_NEAR(t[0], left ? 1 : -1, 1e-6) << "triangle " << k;
            EXPECT_EQ(t[3], left ? 1 : -1) << "triangle " << k;
        }
    EXPECT_TRUE(seam.positions[6] == Vec3(1, 0, 0) && seam.positions[7] == Vec3(1, 1, 0));
    // No such coordinate set: untouched
    ir::Mesh bare;
    bare.positions = m.positions;
    bare.triangles = m.triangles;
    EXPECT_FALSE(detail::generateTangents(bare, 0));
    EXPECT_TRUE(bare.tangents.empty());
}

TEST(GltfTexel, ExtensionMappings) {
    PbrMaterial p;
    p.metallic = 0;
    p.roughness = 0.5;
    ir::Material base = classicMaterial(p, pbrFactors(p));
    // KHR_materials_specular scales the dielectric F0
    PbrMaterial s = p;
    s.specular = 0.5;
    EXPECT_NEAR(classicMaterial(s, pbrFactors(s)).finish.reflectionMin.r,
                base.finish.reflectionMin.r * 0.5, 1e-12);
    // Clearcoat adds a sharp dielectric reflection
    PbrMaterial c = p;
    c.clearcoat = 1;
    ir::Material coated = classicMaterial(c, pbrFactors(c));
    EXPECT_NEAR(coated.finish.reflectionMax.r, 1, 1e-12);
    EXPECT_NEAR(coated.finish.reflectionMin.r, base.finish.reflectionMin.r + 0.04, 1e-12);
    // Volume attenuation: POV-Ray's exponential fade reproduces A^(d/D)
    PbrMaterial v = p;
    v.transmission = 1;
    v.thickness = 1;
    v.attenuationColor = Rgb(0.5, 0.25, 1);
    v.attenuationDistance = 2;
    ir::Material vol = classicMaterial(v, pbrFactors(v));
    EXPECT_EQ(vol.interior.ior, 1.5);
    EXPECT_EQ(vol.interior.fadePower, 1001);
    for (int i = 0; i < 3; ++i) {
        double d = 3;
        double fade = std::exp(-(1 - vol.interior.fadeColor[i]) * d / vol.interior.fadeDistance);
        EXPECT_NEAR(fade, std::pow(v.attenuationColor[i], d / 2), 1e-12);
    }
    // Sheen flattens the diffuse falloff
    PbrMaterial sh = p;
    sh.sheenColor = Rgb(1);
    EXPECT_LT(classicMaterial(sh, pbrFactors(sh)).finish.brilliance, 1);
}

TEST(GltfTexel, UnmappedExtensionsWarnOncePerFile) {
    std::string materials =
        R"([{"extensions":{"KHR_materials_iridescence":{"iridescenceFactor":1},"KHR_materials_clearcoat":{"clearcoatFactor":1}}},)"
        R"({"extensions":{"KHR_materials_iridescence":{"iridescenceFactor":0.5}}}])";
    TempDir tmp;
    auto im = importText(
        tmp,
        gltfOf({quad(0, 1, 0, 1, 0, 0), quad(2, 3, 0, 1, 0, 1)}, materials, {},
               R"(,"extensionsUsed":["KHR_materials_iridescence","KHR_materials_clearcoat"])"),
        "shiny.gltf");
    EXPECT_EQ(im->diag.countContaining("KHR_materials_iridescence (used by"), 1);
    EXPECT_EQ(im->diag.countContaining("shiny.gltf) is not mapped"), 1);
    EXPECT_EQ(im->diag.countContaining("KHR_materials_clearcoat (used by"), 0);
}

}  // namespace
}  // namespace rt::gltf::test
