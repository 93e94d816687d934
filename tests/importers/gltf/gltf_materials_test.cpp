// SPDX-License-Identifier: MIT
// glTF materials, textures and KHR_lights_punctual mapped to the IR (generated files and samples).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/math/float_util.h"
#include "tests/importers/gltf/gltf_test_support.h"

namespace rt::gltf::test {
namespace {

constexpr double kTol = 1e-9;
constexpr double kExposure = 1 / kPi;  // the importer's light exposure constant

/// Imports a generated file and returns its only material (or fails).
struct Imported {
    ir::Scene scene;
    DiagnosticSink diag;
};

std::unique_ptr<Imported> importText(const TempDir &tmp, const std::string &text,
                                     const std::string &name = "test.gltf") {
    auto result = std::make_unique<Imported>();
    writeText(tmp.file(name), text);
    result->scene = importGltf(tmp.file(name), result->diag);
    return result;
}

const ir::Material &onlyMaterial(const Imported &im) {
    std::vector<Instance> inst = instances(im.scene);
    EXPECT_EQ(inst.size(), 1u);
    static const ir::Material kNone;
    if (inst.empty()) return kNone;
    return im.scene.materials[static_cast<size_t>(inst[0].material)];
}

void expectRgb(const Rgb &a, const Rgb &b, double tol) {
    EXPECT_NEAR(a.r, b.r, tol);
    EXPECT_NEAR(a.g, b.g, tol);
    EXPECT_NEAR(a.b, b.b, tol);
}

TEST(GltfMaterial, RoughDielectricFollowsTheTable) {
    TempDir tmp;
    auto im = importText(tmp, triangleGltf(R"({"pbrMetallicRoughness":{
        "baseColorFactor":[0.2,0.4,0.6,1],"metallicFactor":0,"roughnessFactor":0.5}})"));
    const ir::Material &m = onlyMaterial(*im);
    // F0 = 0.04, g = 0.25, nB = 2/0.5^4 - 2 = 30
    expectRgb(m.color, Rgb(0.2, 0.4, 0.6), kTol);
    EXPECT_EQ(m.filter, 0);
    EXPECT_EQ(m.transmit, 0);
    EXPECT_NEAR(m.finish.ambient, 0.1, kTol);
    EXPECT_NEAR(m.finish.diffuse, 1.0, kTol);
    EXPECT_NEAR(m.finish.specular, 0.04 * 38 / 8, kTol);
    EXPECT_NEAR(m.finish.roughness, 1.0 / 30, kTol);
    EXPECT_EQ(m.finish.metallic, 0);
    expectRgb(m.finish.reflectionMin, Rgb(0.01), kTol);
    expectRgb(m.finish.reflectionMax, Rgb(0.25), kTol);
    EXPECT_EQ(m.finish.reflectionFalloff, 5);
    EXPECT_FALSE(m.finish.fresnel);
    EXPECT_FALSE(m.finish.conserveEnergy);
    EXPECT_EQ(m.interior.ior, 1);
    EXPECT_EQ(m.baseColorTexture.texture, -1);
    EXPECT_EQ(m.finish.emission, Rgb(0));
}

TEST(GltfMaterial, SmoothMetalReflectsItsColour) {
    TempDir tmp;
    auto im = importText(tmp, triangleGltf(R"({"pbrMetallicRoughness":{
        "baseColorFactor":[0.9,0.6,0.2,1],"metallicFactor":1,"roughnessFactor":0}})"));
    const ir::Material &m = onlyMaterial(*im);
    EXPECT_NEAR(m.finish.diffuse, 0, kTol);
    EXPECT_NEAR(m.finish.ambient, 0, kTol);
    EXPECT_NEAR(m.finish.specular, 1, kTol);  // clamped
    EXPECT_NEAR(m.finish.roughness, 1.0 / 4000, kTol);
    EXPECT_EQ(m.finish.metallic, 1);
    expectRgb(m.finish.reflectionMin, Rgb(0.9, 0.6, 0.2), kTol);  // F0 = C
    expectRgb(m.finish.reflectionMax, Rgb(1), kTol);
}

TEST(GltfMaterial, NoMaterialIsARoughWhiteMetal) {
    TempDir tmp;
    auto im = importText(tmp, triangleGltf(""));
    const ir::Material &m = onlyMaterial(*im);
    EXPECT_EQ(m.color, Rgb(1));
    EXPECT_EQ(m.finish.metallic, 1);
    EXPECT_NEAR(m.finish.diffuse, 0.5, kTol);  // 0.5 m (1 - g), g = 0
    EXPECT_NEAR(m.finish.ambient, 0.1, kTol);
    EXPECT_NEAR(m.finish.roughness, 1.0, kTol);  // nB clamped to 1
    EXPECT_FALSE(m.finish.hasReflection());
}

TEST(GltfMaterial, ThinWalledTransmissionGoesStraightThrough) {
    TempDir tmp;
    auto thin = importText(tmp, triangleGltf(R"({"pbrMetallicRoughness":{"metallicFactor":0,
        "roughnessFactor":0.2},"extensions":{"KHR_materials_transmission":{"transmissionFactor":1},
        "KHR_materials_ior":{"ior":1.33}}})"));
    const ir::Material &m = onlyMaterial(*thin);
    EXPECT_NEAR(m.filter, 1, kTol);
    EXPECT_EQ(m.interior.ior, 1);  // no volume: no bending
    EXPECT_TRUE(m.finish.fresnel);
    EXPECT_TRUE(m.finish.conserveEnergy);
    expectRgb(m.finish.reflectionMin, Rgb(0), kTol);
    expectRgb(m.finish.reflectionMax, Rgb(0.64), kTol);  // g = 0.8^2
    EXPECT_NEAR(m.finish.diffuse, 0, kTol);

    auto solid = importText(tmp, triangleGltf(R"({"pbrMetallicRoughness":{"metallicFactor":0.5},
        "extensions":{"KHR_materials_transmission":{"transmissionFactor":1},
        "KHR_materials_ior":{"ior":1.33},"KHR_materials_volume":{"thicknessFactor":0.1}}})"));
    const ir::Material &v = onlyMaterial(*solid);
    EXPECT_NEAR(v.filter, 0.5, kTol);  // only the dielectric half transmits
    EXPECT_NEAR(v.interior.ior, 1.33, kTol);
}

TEST(GltfMaterial, IorZeroWarnsAndUsesOnePointFive) {
    TempDir tmp;
    auto im = importText(tmp, triangleGltf(R"({"pbrMetallicRoughness":{"metallicFactor":0},
        "extensions":{"KHR_materials_transmission":{"transmissionFactor":1},
        "KHR_materials_ior":{"ior":0},"KHR_materials_volume":{"thicknessFactor":1}}})"));
    EXPECT_NEAR(onlyMaterial(*im).interior.ior, 1.5, kTol);
    EXPECT_EQ(im->diag.countContaining("legacy"), 1);
}

TEST(GltfMaterial, AlphaModes) {
    TempDir tmp;
    auto blend = importText(tmp, triangleGltf(R"({"alphaMode":"BLEND","pbrMetallicRoughness":{
        "baseColorFactor":[1,1,1,0.25],"metallicFactor":0},
        "extensions":{"KHR_materials_transmission":{"transmissionFactor":1}}})"));
    const ir::Material &b = onlyMaterial(*blend);
    EXPECT_NEAR(b.transmit, 0.75, kTol);
    EXPECT_NEAR(b.filter, 0.25, kTol);  // filter + transmit <= 1

    auto hidden = importText(tmp, triangleGltf(R"({"alphaMode":"MASK","alphaCutoff":0.5,
        "pbrMetallicRoughness":{"baseColorFactor":[1,1,1,0.3]}})"));
    EXPECT_TRUE(instances(hidden->scene).empty());
    EXPECT_EQ(hidden->diag.countContaining("not rendered"), 1);

    auto shown = importText(tmp, triangleGltf(R"({"alphaMode":"MASK",
        "pbrMetallicRoughness":{"baseColorFactor":[1,1,1,0.7]}})"));
    EXPECT_EQ(onlyMaterial(*shown).transmit, 0);
    EXPECT_EQ(onlyMaterial(*shown).filter, 0);
}

TEST(GltfMaterial, EmissionIsDividedByTheColourPovRayMultipliesItWith) {
    TempDir tmp;
    auto im = importText(tmp, triangleGltf(R"({"emissiveFactor":[1,0.5,0],
        "pbrMetallicRoughness":{"baseColorFactor":[0.5,0,0.2,1]},
        "extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":2}}})"));
    const ir::Material &m = onlyMaterial(*im);
    expectRgb(m.color, Rgb(0.5, 1e-3, 0.2), kTol);  // green raised to carry emission
    expectRgb(m.finish.emission, Rgb(4, 1000, 0), 1e-6);
    expectRgb(m.color * m.finish.emission, Rgb(2, 1, 0), 1e-9);
}

TEST(GltfMaterial, UnlitHasNoShading) {
    TempDir tmp;
    auto im = importText(tmp, triangleGltf(R"({"pbrMetallicRoughness":{"baseColorFactor":
        [0.1,0.2,0.3,1],"roughnessFactor":0},"extensions":{"KHR_materials_unlit":{}}})"));
    const ir::Material &m = onlyMaterial(*im);
    EXPECT_EQ(m.finish.ambient, 1);
    EXPECT_EQ(m.finish.diffuse, 0);
    EXPECT_EQ(m.finish.specular, 0);
    EXPECT_EQ(m.finish.phong, 0);
    EXPECT_FALSE(m.finish.hasReflection());
    expectRgb(m.color, Rgb(0.1, 0.2, 0.3), kTol);
}

TEST(GltfMaterial, IdenticalMaterialsAreDeduplicated) {
    TempDir tmp;
    std::string text = triangleGltf(R"({"name":"a"},{"name":"b"})");
    // Two nodes with one mesh each, using materials 0 and 1 (which look the same)
    text = replaceOnce(text, R"("nodes":[{"mesh":0,"name":"tri"}])",
                       R"("nodes":[{"mesh":0},{"mesh":1}])");
    text = replaceOnce(text, R"("scenes":[{"nodes":[0]}])", R"("scenes":[{"nodes":[0,1]}])");
    text = replaceOnce(
        text, R"(]}],"materials")",
        R"(]},{"primitives":[{"attributes":{"POSITION":0},"material":1}]}],"materials")");
    auto im = importText(tmp, text);
    EXPECT_EQ(instances(im->scene).size(), 2u);
    EXPECT_EQ(im->scene.materials.size(), 1u);
    EXPECT_EQ(im->scene.meshes.size(), 1u);  // same accessors: one shared mesh
}

/// A textured triangle: positions, TEXCOORD_0, one material with the given base colour
/// texture info, one texture with the given sampler JSON and image URI.
std::string texturedTriangle(const std::string &imageUri, const std::string &sampler,
                             const std::string &textureInfo = R"({"index":0})") {
    TestBuffer buf;
    size_t pos = buf.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
    size_t uv = buf.add(std::vector<float>{0, 0, 1, 0, 0, 1});
    std::string text = meshGltf(R"({"attributes":{"POSITION":0,"TEXCOORD_0":1},"material":0})", buf,
                                viewJson(pos, 36) + "," + viewJson(uv, 24),
                                R"({"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
                                R"({"bufferView":1,"componentType":5126,"count":3,"type":"VEC2"})");
    std::string material = R"("materials":[{"pbrMetallicRoughness":{"baseColorTexture":)" +
                           textureInfo + R"(}}],"textures":[{"source":0,"sampler":0}],)" +
                           R"("samplers":[)" + sampler + R"(],"images":[{"uri":")" + imageUri +
                           R"("}],)";
    return text.insert(1, material);
}

TEST(GltfTexture, DecodesSrgbTopRowFirstWithWrapModes) {
    TempDir tmp;
    std::string uri =
        "data:image/bmp;base64," + base64Encode(bmp2x2(0xff0000, 0x808080, 0x000000, 0xffffff));
    auto im =
        importText(tmp, texturedTriangle(uri, R"({"wrapS":33071,"wrapT":10497})"), "my model.gltf");
    ASSERT_EQ(im->scene.textures.size(), 1u);
    const ir::Texture &tex = *im->scene.textures[0];
    EXPECT_EQ(tex.name, "my_model_tex0");
    ASSERT_EQ(tex.width, 2);
    ASSERT_EQ(tex.height, 2);
    EXPECT_EQ(tex.wrapU, ir::Texture::Wrap::ClampToEdge);
    EXPECT_EQ(tex.wrapV, ir::Texture::Wrap::Repeat);
    EXPECT_FALSE(tex.nearest);  // no magFilter: linear
    auto texel = [&](int x, int y, int c) {
        return tex.rgba[static_cast<size_t>((y * 2 + x) * 4 + c)];
    };
    EXPECT_FLOAT_EQ(texel(0, 0, 0), 1.0f);  // top-left red
    EXPECT_FLOAT_EQ(texel(0, 0, 1), 0.0f);
    EXPECT_NEAR(texel(1, 0, 0), 0.2158605, 1e-6);  // sRGB 128 decoded
    EXPECT_FLOAT_EQ(texel(0, 1, 2), 0.0f);         // bottom-left black
    EXPECT_FLOAT_EQ(texel(1, 1, 2), 1.0f);         // bottom-right white
    EXPECT_FLOAT_EQ(texel(1, 1, 3), 1.0f);         // opaque
    EXPECT_EQ(onlyMaterial(*im).baseColorTexture.texture, 0);
    ASSERT_EQ(im->scene.meshes.size(), 1u);
    EXPECT_EQ(im->scene.meshes[0]->uvs.size(), 3u);
    EXPECT_EQ(im->diag.count(Severity::Warning), 0);
}

TEST(GltfTexture, SamplerWrapModesAndFilters) {
    TempDir tmp;
    std::string uri = "data:image/bmp;base64," + base64Encode(bmp2x2(0, 0, 0, 0));
    auto im = importText(tmp, texturedTriangle(uri, R"({"wrapS":33648,"wrapT":33071,)"
                                                    R"("magFilter":9728,"minFilter":9987})"));
    ASSERT_EQ(im->scene.textures.size(), 1u);
    const ir::Texture &tex = *im->scene.textures[0];
    EXPECT_EQ(tex.wrapU, ir::Texture::Wrap::MirroredRepeat);
    EXPECT_EQ(tex.wrapV, ir::Texture::Wrap::ClampToEdge);
    EXPECT_TRUE(tex.nearest);
    EXPECT_EQ(im->diag.count(Severity::Warning), 0);

    auto linear = importText(tmp, texturedTriangle(uri, R"({"magFilter":9729,"minFilter":9728})"));
    ASSERT_EQ(linear->scene.textures.size(), 1u);
    EXPECT_FALSE(linear->scene.textures[0]->nearest);
    EXPECT_EQ(linear->scene.textures[0]->wrapU, ir::Texture::Wrap::Repeat);
    EXPECT_EQ(linear->diag.count(Severity::Warning), 0);
}

TEST(GltfTexture, InvalidSamplerValuesWarnWithTheirPath) {
    TempDir tmp;
    std::string uri = "data:image/bmp;base64," + base64Encode(bmp2x2(0, 0, 0, 0));
    auto im = importText(tmp, texturedTriangle(uri, R"({"wrapS":1234,"wrapT":33648,)"
                                                    R"("magFilter":9984,"minFilter":5})"));
    ASSERT_EQ(im->scene.textures.size(), 1u);
    const ir::Texture &tex = *im->scene.textures[0];
    EXPECT_EQ(tex.wrapU, ir::Texture::Wrap::Repeat);
    EXPECT_EQ(tex.wrapV, ir::Texture::Wrap::MirroredRepeat);
    EXPECT_FALSE(tex.nearest);
    EXPECT_EQ(im->diag.countContaining("samplers[0].wrapS: 1234 is not a wrap mode"), 1);
    EXPECT_EQ(im->diag.countContaining("samplers[0].magFilter: 9984"), 1);
    EXPECT_EQ(im->diag.countContaining("samplers[0].minFilter: 5"), 1);
}

TEST(GltfTexture, UndecodableOrMissingImagesCostOnlyTheTexture) {
    TempDir tmp;
    std::string garbage =
        "data:image/png;base64," + base64Encode(std::vector<unsigned char>(64, 0x5a));
    auto bad = importText(tmp, texturedTriangle(garbage, "{}"));
    EXPECT_TRUE(bad->scene.textures.empty());
    EXPECT_EQ(onlyMaterial(*bad).baseColorTexture.texture, -1);
    EXPECT_EQ(bad->diag.countContaining("cannot decode images[0]"), 1);
    EXPECT_EQ(bad->scene.meshes.size(), 1u);

    auto missing = importText(tmp, texturedTriangle("no_such_image.png", "{}"));
    EXPECT_TRUE(missing->scene.textures.empty());
    EXPECT_GE(missing->diag.countContaining("no_such_image.png"), 1);
    EXPECT_EQ(missing->scene.meshes.size(), 1u);
}

TEST(GltfTexture, ImageBufferViewOutsideItsBufferIsNotRead) {
    TempDir tmp;
    std::string text = texturedTriangle("x", "{}");
    text = replaceOnce(text, R"("images":[{"uri":"x"}])",
                       R"("images":[{"bufferView":2,"mimeType":"image/png"}])");
    text = replaceOnce(text, R"(],"accessors")",
                       R"(,{"buffer":0,"byteOffset":1000,"byteLength":64}],"accessors")");
    auto im = importText(tmp, text);
    EXPECT_TRUE(im->scene.textures.empty());
    EXPECT_EQ(im->diag.countContaining("images[0]: its bufferView lies outside its buffer"), 1);
    EXPECT_EQ(im->scene.meshes.size(), 1u);
}

TEST(GltfTexture, TextureTransformIsReadAndMissingUvSetsAreWarnedAbout) {
    TempDir tmp;
    std::string uri = "data:image/bmp;base64," + base64Encode(bmp2x2(0, 0, 0, 0));
    // KHR_texture_transform: offset, rotation and scale kept on the material's reference
    std::string text = texturedTriangle(
        uri, "{}",
        R"({"index":0,"extensions":{"KHR_texture_transform":{"offset":[0.5,-0.25],"rotation":0.75,"scale":[2,3]}}})");
    text.insert(1, R"("extensionsUsed":["KHR_texture_transform","EXT_whatever"],)");
    auto im = importText(tmp, text);
    EXPECT_EQ(im->diag.countContaining("KHR_texture_transform"), 0);
    EXPECT_EQ(im->diag.countContaining("uses extension EXT_whatever"), 1);
    const ir::TextureRef &ref = onlyMaterial(*im).baseColorTexture;
    EXPECT_EQ(ref.texture, 0);
    EXPECT_EQ(ref.texCoord, 0);
    EXPECT_EQ(ref.offsetU, 0.5);
    EXPECT_EQ(ref.offsetV, -0.25);
    EXPECT_EQ(ref.rotation, 0.75);
    EXPECT_EQ(ref.scaleU, 2);
    EXPECT_EQ(ref.scaleV, 3);
    // TEXCOORD_1 is read, but this triangle has none: the texture is left out, with the reason
    auto second = importText(tmp, texturedTriangle(uri, "{}", R"({"index":0,"texCoord":1})"));
    EXPECT_EQ(second->diag.countContaining("no TEXCOORD_1 for the base colour texture"), 1);
    EXPECT_EQ(onlyMaterial(*second).baseColorTexture.texture, -1);
    // Sets beyond 1 are not read
    auto third = importText(tmp, texturedTriangle(uri, "{}", R"({"index":0,"texCoord":2})"));
    EXPECT_EQ(third->diag.countContaining("uses TEXCOORD_2"), 1);
    EXPECT_EQ(onlyMaterial(*third).baseColorTexture.texture, -1);
}

TEST(GltfLights, SpotDirectionalAndPointFromGeneratedFile) {
    TempDir tmp;
    std::string text = triangleGltf("", R"(,"extensionsUsed":["KHR_lights_punctual"],
        "extensions":{"KHR_lights_punctual":{"lights":[
            {"type":"spot","color":[1,0,0],"intensity":10,
             "spot":{"innerConeAngle":0.2,"outerConeAngle":0.5}},
            {"type":"directional","intensity":3},
            {"type":"point","range":5}]}})");
    text = replaceOnce(text, R"("nodes":[{"mesh":0,"name":"tri"}])",
                       R"("nodes":[{"mesh":0},
        {"translation":[1,2,3],"extensions":{"KHR_lights_punctual":{"light":0}}},
        {"rotation":[-0.70710678,0,0,0.70710678],
         "extensions":{"KHR_lights_punctual":{"light":1}}},
        {"children":[4],"scale":[2,2,2]},
        {"translation":[0,1,0],"extensions":{"KHR_lights_punctual":{"light":2}}}])");
    text = replaceOnce(text, R"("scenes":[{"nodes":[0]}])", R"("scenes":[{"nodes":[0,1,2,3]}])");
    writeText(tmp.file("lights.gltf"), text);
    DiagnosticSink diag;
    ImportOptions opts;
    opts.unitScale = 2;
    ir::Scene scene = importGltf(tmp.file("lights.gltf"), diag, opts);
    ASSERT_EQ(scene.lights.size(), 3u);

    const ir::Light &spot = scene.lights[0];
    EXPECT_EQ(spot.kind, ir::Light::Kind::Spot);
    expectNear(spot.position, zUp(Vec3(1, 2, 3)) * 2, 1e-12);
    expectNear(spot.direction, zUp(Vec3(0, 0, -1)), 1e-12);
    expectRgb(spot.color, Rgb(1, 0, 0) * (10 * kExposure / 2), 1e-12);
    EXPECT_NEAR(spot.spotRadius, degrees(0.2), 1e-12);
    EXPECT_NEAR(spot.spotFalloff, degrees(0.5), 1e-12);
    EXPECT_EQ(spot.spotTightness, 0);
    EXPECT_EQ(spot.fadeDistance, 2);  // one metre in world units
    EXPECT_EQ(spot.fadePower, 2);

    // Rotated -90 degrees about glTF X, the directional light shines down (world -Z) from
    // outside the scene's bounds
    const ir::Light &sun = scene.lights[1];
    EXPECT_EQ(sun.kind, ir::Light::Kind::Directional);
    expectNear(sun.direction, Vec3(0, 0, -1), 1e-8);
    expectRgb(sun.color, Rgb(3 * kExposure), 1e-12);
    EXPECT_EQ(sun.fadePower, 0);
    // Triangle (0,0,0), (1,0,0), (0,1,0) in glTF: world bounds (0,0,0)..(2,0,2) at scale 2
    Vec3 centre(1, 0, 1);
    double diag2 = std::sqrt(8.0);
    expectNear(sun.position, centre + Vec3(0, 0, 1) * (10 * diag2 + 1), 1e-6);

    // Point light under a scaled parent: position scaled, default colour and intensity
    const ir::Light &point = scene.lights[2];
    EXPECT_EQ(point.kind, ir::Light::Kind::Point);
    expectNear(point.position, zUp(Vec3(0, 2, 0)) * 2, 1e-12);
    expectRgb(point.color, Rgb(kExposure / 2), 1e-12);
    EXPECT_EQ(diag.countContaining("range"), 1);
}

TEST(GltfLights, LightsPunctualLampHasFivePointLights) {
    REQUIRE_GLTF_SAMPLE("LightsPunctualLamp/LightsPunctualLamp.gltf");
    DiagnosticSink diag;
    ir::Scene scene = importGltf(sample("LightsPunctualLamp/LightsPunctualLamp.gltf"), diag);
    ASSERT_EQ(scene.lights.size(), 5u);
    // In node order: lights 0..4; light 1 has no colour (white)
    const double intensity[5] = {15, 1.5, 80, 80, 180};
    const Rgb color[5] = {Rgb(1, 0.6318749785423279, 0.23909975588321689), Rgb(1),
                          Rgb(0.21223080158233645, 0.5906190276145935, 0.5583405494689941),
                          Rgb(0.21223080158233645, 0.5906190276145935, 0.5583405494689941),
                          Rgb(1, 0.6278365254402161, 0.5012403726577759)};
    for (size_t i = 0; i < 5; ++i) {
        SCOPED_TRACE(i);
        const ir::Light &l = scene.lights[i];
        EXPECT_EQ(l.kind, ir::Light::Kind::Point);
        expectRgb(l.color, color[i] * (intensity[i] * kExposure / 2), 1e-9);
        EXPECT_EQ(l.fadeDistance, 1);
        EXPECT_EQ(l.fadePower, 2);
    }
    expectNear(scene.lights[0].position,
               zUp(Vec3(0.04622355476021767, 0.9077973365783693, 0.006696629337966442)), 1e-9);

    // The BLEND glass lets light through (alpha from the base colour texture's mean)
    bool blendFound = false;
    for (const Instance &i : instances(scene))
        if (scene.materials[static_cast<size_t>(i.material)].transmit > 0) blendFound = true;
    EXPECT_TRUE(blendFound);
    // The transmissive shade has filter; base colour textures decoded, clamped
    bool filterFound = false;
    for (const ir::Material &m : scene.materials) filterFound |= m.filter > 0;
    EXPECT_TRUE(filterFound);
    // Base colour (2) and emissive (1) textures decoded as colour, normal (2), metallic-
    // roughness (1) and transmission (1) textures as linear data, read per texel; all clamped
    EXPECT_EQ(scene.textures.size(), 7u);
    for (const auto &t : scene.textures) EXPECT_EQ(t->wrapU, ir::Texture::Wrap::ClampToEdge);
    EXPECT_EQ(diag.count(Severity::Warning), 0);
}

TEST(GltfMaterial, EmissiveStrengthScalesEmission) {
    REQUIRE_GLTF_SAMPLE("EmissiveStrengthTest.glb");
    DiagnosticSink diag;
    ir::Scene scene = importGltf(sample("EmissiveStrengthTest.glb"), diag);
    std::vector<double> red;
    for (const Instance &i : instances(scene)) {
        const ir::Material &m = scene.materials[static_cast<size_t>(i.material)];
        if (m.finish.emission.isBlack()) continue;
        Rgb e = m.color * m.finish.emission;  // what POV-Ray emits
        EXPECT_NEAR(e.g / e.r, 5, 1e-9);
        EXPECT_NEAR(e.b / e.r, 9, 1e-9);
        red.push_back(e.r);
    }
    std::sort(red.begin(), red.end());
    ASSERT_EQ(red.size(), 5u);
    const double strength[5] = {1, 2, 4, 8, 16};
    for (size_t k = 0; k < 5; ++k) EXPECT_NEAR(red[k], 0.1 * strength[k], 1e-9);
}

TEST(GltfMaterial, TransmissionRoughnessTakesMetalnessFromTheTexture) {
    REQUIRE_GLTF_SAMPLE("TransmissionRoughnessTest.glb");
    DiagnosticSink diag;
    ir::Scene scene = importGltf(sample("TransmissionRoughnessTest.glb"), diag);
    std::set<double> iors;
    for (const Instance &i : instances(scene)) {
        const ir::Material &m = scene.materials[static_cast<size_t>(i.material)];
        if (m.filter > 0) iors.insert(std::round(m.interior.ior * 100) / 100);
    }
    // metallicFactor stays at its default 1; the texture's metalness (0) lets light through.
    // Each glass has KHR_materials_volume, so its ior bends the rays.
    EXPECT_EQ(iors, (std::set<double>{1.0, 1.33, 1.5, 1.76, 2.42}));

    // Without volume (thicknessFactor renamed, same length) the same glasses are thin-walled
    std::vector<unsigned char> bytes = readBytes(sample("TransmissionRoughnessTest.glb"));
    std::string text(bytes.begin(), bytes.end());
    size_t at = 0;
    int renamed = 0;
    while ((at = text.find("\"thicknessFactor\"", at)) != std::string::npos) {
        text[at + 15] = 'X';
        ++renamed;
    }
    EXPECT_EQ(renamed, 5);
    TempDir tmp;
    writeText(tmp.file("thin.glb"), text);
    ir::Scene thin = importGltf(tmp.file("thin.glb"), diag);
    int glass = 0;
    for (const ir::Material &m : thin.materials)
        if (m.filter > 0) {
            ++glass;
            EXPECT_EQ(m.interior.ior, 1);
        }
    EXPECT_GE(glass, 5);
}

}  // namespace
}  // namespace rt::gltf::test
