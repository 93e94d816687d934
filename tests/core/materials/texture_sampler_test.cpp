// SPDX-License-Identifier: MIT
// Texture addressing as glTF defines it: sampler wrap modes at known coordinates, NEAREST
// against LINEAR, and KHR_texture_transform including its rotation direction.
#include <gtest/gtest.h>

#include <cmath>

#include "core/materials/texture_sampler.h"

namespace rt {
namespace {

constexpr double kPi = 3.14159265358979323846;
using Wrap = ir::Texture::Wrap;

/// 4 x 1 texture whose texel i has red = i (green 0, blue 1, alpha 1 - i / 4).
ir::Texture ramp(Wrap wrapU, bool nearest = false) {
    ir::Texture t;
    t.width = 4;
    t.height = 1;
    for (int i = 0; i < 4; ++i) t.rgba.insert(t.rgba.end(), {float(i), 0, 1, 1 - i / 4.0f});
    t.wrapU = wrapU;
    t.nearest = nearest;
    return t;
}

double red(const ir::Texture &t, double u, double v = 0.5) { return sampleTexture(t, u, v).r; }

TEST(TextureSampler, WrapTexelIndices) {
    EXPECT_EQ(wrapTexel(-1, 4, Wrap::Repeat), 3);
    EXPECT_EQ(wrapTexel(9, 4, Wrap::Repeat), 1);
    EXPECT_EQ(wrapTexel(-7, 4, Wrap::ClampToEdge), 0);
    EXPECT_EQ(wrapTexel(9, 4, Wrap::ClampToEdge), 3);
    // Mirrored repeat reads 0 1 2 3 3 2 1 0 0 1 ...
    int mirrored[] = {0, 1, 2, 3, 3, 2, 1, 0, 0, 1};
    for (int i = 0; i < 10; ++i) EXPECT_EQ(wrapTexel(i, 4, Wrap::MirroredRepeat), mirrored[i]);
    EXPECT_EQ(wrapTexel(-1, 4, Wrap::MirroredRepeat), 0);
    EXPECT_EQ(wrapTexel(-5, 4, Wrap::MirroredRepeat), 3);
}

TEST(TextureSampler, RepeatWrapsBilinearAcrossTheSeam) {
    ir::Texture t = ramp(Wrap::Repeat);
    EXPECT_NEAR(red(t, 0.125), 0, 1e-6);   // centre of texel 0
    EXPECT_NEAR(red(t, 0.875), 3, 1e-6);   // centre of texel 3
    EXPECT_NEAR(red(t, 1.125), 0, 1e-6);   // one period on
    EXPECT_NEAR(red(t, -0.125), 3, 1e-6);  // texel -1 = texel 3
    EXPECT_NEAR(red(t, 0), 1.5, 1e-6);     // halfway between texels 3 and 0
}

TEST(TextureSampler, ClampToEdgeHoldsTheEdgeTexels) {
    ir::Texture t = ramp(Wrap::ClampToEdge);
    EXPECT_NEAR(red(t, 0.125), 0, 1e-6);
    EXPECT_NEAR(red(t, 0), 0, 1e-6);  // no blend with the far edge
    EXPECT_NEAR(red(t, 1), 3, 1e-6);
    EXPECT_NEAR(red(t, -3.7), 0, 1e-6);
    EXPECT_NEAR(red(t, 12.2), 3, 1e-6);
    EXPECT_NEAR(red(t, 0.5), 1.5, 1e-6);  // inside: bilinear as always
}

TEST(TextureSampler, MirroredRepeatReflectsEveryOtherPeriod) {
    ir::Texture t = ramp(Wrap::MirroredRepeat);
    EXPECT_NEAR(red(t, 0.875), 3, 1e-6);
    EXPECT_NEAR(red(t, 1.125), 3, 1e-6);   // texel 4 = texel 3
    EXPECT_NEAR(red(t, 1.375), 2, 1e-6);   // texel 5 = texel 2
    EXPECT_NEAR(red(t, 1.875), 0, 1e-6);   // texel 7 = texel 0
    EXPECT_NEAR(red(t, 2.125), 0, 1e-6);   // texel 8 = texel 0
    EXPECT_NEAR(red(t, -0.125), 0, 1e-6);  // texel -1 = texel 0
    EXPECT_NEAR(red(t, 1.25), 2.5, 1e-6);  // between texels 4 (3) and 5 (2)
}

TEST(TextureSampler, NearestPicksTheTexelUnderThePoint) {
    ir::Texture lin = ramp(Wrap::Repeat), near = ramp(Wrap::Repeat, true);
    EXPECT_NEAR(red(near, 0.3), 1, 1e-6);   // x = 1.2: texel 1
    EXPECT_NEAR(red(lin, 0.3), 0.7, 1e-6);  // 0.7 of texel 1, 0.3 of texel 0
    EXPECT_NEAR(red(near, 0.99), 3, 1e-6);
    EXPECT_NEAR(red(near, -0.01), 3, 1e-6);
    ir::Texture nearClamp = ramp(Wrap::ClampToEdge, true);
    EXPECT_NEAR(red(nearClamp, -0.01), 0, 1e-6);
    ir::Texture nearMirror = ramp(Wrap::MirroredRepeat, true);
    EXPECT_NEAR(red(nearMirror, 1.3), 2, 1e-6);  // x = 5.2: texel 5 = texel 2
    // Alpha is filtered with the colour
    float rgba[4];
    sampleTexture(lin, 0.3, 0.5, rgba);
    EXPECT_NEAR(rgba[3], 1 - 0.7 / 4, 1e-6);
}

TEST(TextureSampler, RowsCountDownFromTheTopPerAxisWrap) {
    // 1 x 4 column whose row j has green = j; v clamps while u repeats
    ir::Texture t;
    t.width = 1;
    t.height = 4;
    for (int j = 0; j < 4; ++j) t.rgba.insert(t.rgba.end(), {0, float(j), 0, 1});
    t.wrapV = Wrap::ClampToEdge;
    EXPECT_NEAR(sampleTexture(t, 0.5, 0.125).g, 0, 1e-6);
    EXPECT_NEAR(sampleTexture(t, 7.5, 0.875).g, 3, 1e-6);
    EXPECT_NEAR(sampleTexture(t, 0.5, 1.5).g, 3, 1e-6);
    EXPECT_NEAR(sampleTexture(t, 0.5, -0.5).g, 0, 1e-6);
    t.wrapV = Wrap::MirroredRepeat;
    EXPECT_NEAR(sampleTexture(t, 0.5, 1.125).g, 3, 1e-6);
    EXPECT_NEAR(sampleTexture(t, 0.5, -0.375).g, 1, 1e-6);
}

TEST(TextureTransform, ScaleRotateOffsetInThatOrder) {
    ir::TextureRef ref;
    ref.scaleU = 2;
    ref.scaleV = 3;
    ref.offsetU = 0.25;
    ref.offsetV = -0.5;
    double u = 0.5, v = 0.5;
    transformTexCoord(ref, &u, &v);
    EXPECT_NEAR(u, 1.25, 1e-12);
    EXPECT_NEAR(v, 1.0, 1e-12);
}

TEST(TextureTransform, RotationTurnsCounterClockwiseInUvSpaceWithVDown) {
    // A quarter turn takes the +u axis to -v: "up" in an image whose v points down
    ir::TextureRef ref;
    ref.rotation = kPi / 2;
    double u = 1, v = 0;
    transformTexCoord(ref, &u, &v);
    EXPECT_NEAR(u, 0, 1e-12);
    EXPECT_NEAR(v, -1, 1e-12);
    u = 0;
    v = 1;
    transformTexCoord(ref, &u, &v);
    EXPECT_NEAR(u, 1, 1e-12);
    EXPECT_NEAR(v, 0, 1e-12);

    // The extension's example: offset (0, 1), rotation pi/2, scale 0.5 "uses only the lower
    // left quadrant of the image": the unit square maps onto [0, 0.5] x [0.5, 1]
    ref.offsetU = 0;
    ref.offsetV = 1;
    ref.scaleU = ref.scaleV = 0.5;
    for (auto [u0, v0] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}, {0.3, 0.7}}) {
        u = u0;
        v = v0;
        transformTexCoord(ref, &u, &v);
        EXPECT_GE(u, -1e-12);
        EXPECT_LE(u, 0.5 + 1e-12);
        EXPECT_GE(v, 0.5 - 1e-12);
        EXPECT_LE(v, 1 + 1e-12);
    }
}

TEST(TextureTransform, AppliesToTheReferencedCoordinateSet) {
    SurfaceInteraction si;
    si.hasUv = si.hasUv1 = true;
    si.u = 0.1;
    si.v = 0.2;
    si.u1 = 0.6;
    si.v1 = 0.7;
    ir::TextureRef ref;
    ref.texCoord = 1;
    ref.offsetU = 0.1;
    double u, v;
    ASSERT_TRUE(textureCoordinates(ref, si, &u, &v));
    EXPECT_NEAR(u, 0.7, 1e-12);
    EXPECT_NEAR(v, 0.7, 1e-12);
    si.hasUv1 = false;
    EXPECT_FALSE(textureCoordinates(ref, si, &u, &v));
}

}  // namespace
}  // namespace rt
