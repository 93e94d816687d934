// SPDX-License-Identifier: MIT
// AxisBox finds a translated box's crossings and surfaces inline: the same answers as the
// PrimitiveInstance it stands for, bit for bit.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>

#include "core/csg/csg_shape.h"
#include "core/geometry/axis_box.h"
#include "core/math/rng.h"

namespace rt {
namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expectSameBits(const Vec3 &a, const Vec3 &b, const char *what) {
    for (int i = 0; i < 3; ++i)
        EXPECT_TRUE(sameBits(a[i], b[i])) << what << "[" << i << "]: " << a[i] << " vs " << b[i];
}

std::unique_ptr<PrimitiveInstance> boxInstance(const Vec3 &min, const Vec3 &max, const Mat4 &m) {
    return std::make_unique<PrimitiveInstance>(std::make_unique<Box>(min, max),
                                               *Transform::fromMatrix(m), 0);
}

/// Boxes on a grid of half units (so rays start on their faces, edges and corners and run
/// along them), translated by offsets of three scales or not at all; rays whose direction
/// components are often +0 or -0; windows that begin and end at the crossings themselves.
TEST(AxisBox, GivesThePrimitiveInstancesCrossingsAndSurfacesBitForBit) {
    Rng rng(2026);
    auto grid = [&](double scale) { return std::floor(rng.uniform() * 9 - 4) * 0.5 * scale; };
    auto component = [&] {
        double u = rng.uniform();
        if (u < 0.15) return 0.0;
        if (u < 0.3) return -0.0;
        if (u < 0.4) return u < 0.35 ? 1.0 : -1.0;
        return rng.uniform() * 2 - 1;
    };
    int crossings = 0, exits = 0, parallel = 0, translated = 0, windows = 0;
    for (double scale : {1e-6, 1.0, 1e6}) {
        SCOPED_TRACE(scale);
        for (int k = 0; k < 400; ++k) {
            Vec3 a(grid(scale), grid(scale), grid(scale)), b(grid(scale), grid(scale), grid(scale));
            Vec3 lo = min(a, b), hi = max(a, b);
            for (int i = 0; i < 3; ++i)
                if (lo[i] == hi[i]) hi[i] += 0.5 * scale;
            Vec3 offset =
                k % 4 == 0 ? Vec3(0) : Vec3(grid(scale), grid(scale), rng.uniform() * scale);
            auto inst = boxInstance(lo, hi, Mat4::translate(offset));
            AxisBox box = AxisBox::of(*inst);
            ASSERT_EQ(box.leaf(), inst.get());
            translated += inst->placement().kind() == Placement::Kind::Translation;
            for (int j = 0; j < 100; ++j) {
                // Origins with a coordinate -0 too: where the direction's is 0 as well, the
                // surface point keeps the sign the object-space origin gives it
                auto start = [&] { return rng.uniform() < 0.1 ? -0.0 : grid(scale); };
                Vec3 o(start(), start(), start());
                if (k % 4 != 0) o = o + offset;
                Vec3 d(component(), component(), component());
                if (lengthSquared(d) == 0) d.z = 1;
                d = normalize(d);
                parallel += d.x == 0 || d.y == 0 || d.z == 0;
                Ray ray(o, d);
                Vec3 invDir(1 / d.x, 1 / d.y, 1 / d.z);
                // The whole line, then windows bounded by its crossings
                double ends[] = {-kInfinity, kInfinity, 0, 0};
                Span whole;
                if (inst->lineSpan(ray, &whole)) {
                    ends[2] = whole.in.t;
                    ends[3] = whole.out.t;
                }
                for (double tMin : ends)
                    for (double tMax : ends) {
                        if (!(tMin < tMax)) continue;
                        ++windows;
                        SpanScratch scratch;
                        Crossing expected, got;
                        bool found = inst->firstCrossing(ray, tMin, tMax, &expected, scratch);
                        ASSERT_EQ(box.firstCrossing(ray, invDir, tMin, tMax, &got), found)
                            << "ray " << j << " window " << tMin << " " << tMax;
                        if (!found) continue;
                        ++crossings;
                        exits += got.t == whole.out.t;
                        EXPECT_TRUE(sameBits(got.t, expected.t));
                        EXPECT_EQ(got.face, expected.face);
                        EXPECT_EQ(got.leaf, expected.leaf);
                        EXPECT_EQ(got.tie, expected.tie);
                        SurfaceInteraction s = box.surfaceAt(ray, got),
                                           e = inst->surfaceAt(ray, expected);
                        EXPECT_TRUE(sameBits(s.t, e.t));
                        expectSameBits(s.p, e.p, "point");
                        expectSameBits(s.pError, e.pError, "error bound");
                        expectSameBits(s.n, e.n, "normal");
                        expectSameBits(s.ns, e.ns, "shading normal");
                        EXPECT_EQ(s.leaf, e.leaf);
                        EXPECT_EQ(s.hasUv, e.hasUv);
                    }
            }
        }
    }
    EXPECT_GT(translated, 800);
    EXPECT_GT(parallel, 60000);
    EXPECT_GT(windows, 500000);
    EXPECT_GT(crossings, 50000);
    EXPECT_GT(exits, 15000);
}

TEST(AxisBox, StandsOnlyForBoxesPlacedByTheIdentityOrATranslation) {
    auto identity = boxInstance(Vec3(0), Vec3(1), Mat4());
    EXPECT_EQ(AxisBox::of(*identity).leaf(), identity.get());
    auto shifted = boxInstance(Vec3(0), Vec3(1), Mat4::translate(Vec3(3, -2, 0)));
    EXPECT_EQ(AxisBox::of(*shifted).leaf(), shifted.get());
    for (const Mat4 &m :
         {Mat4::rotateZ(90), Mat4::scale(Vec3(2, 1, 1)), Mat4::mirror(Vec3(1, 0, 0))}) {
        auto placed = boxInstance(Vec3(0), Vec3(1), m);
        EXPECT_EQ(AxisBox::of(*placed).leaf(), nullptr) << m.toString();
    }
    PrimitiveInstance sphere(std::make_unique<Sphere>(1), Transform(), 0);
    EXPECT_EQ(AxisBox::of(sphere).leaf(), nullptr);
    CsgShape csg;
    int a = csg.addLeaf(boxInstance(Vec3(0), Vec3(1), Mat4()));
    int b = csg.addLeaf(boxInstance(Vec3(0.5), Vec3(2), Mat4()));
    csg.addOp(CsgShape::Op::Difference, {a, b});
    EXPECT_EQ(AxisBox::of(csg).leaf(), nullptr);
}

}  // namespace
}  // namespace rt
