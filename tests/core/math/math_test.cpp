// SPDX-License-Identifier: MIT
// Tests of the double-precision math layer: roots, matrices, degree trig, transforms, bounds.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <vector>

#include "core/math/bounds3.h"
#include "core/math/degree_trig.h"
#include "core/math/float_round.h"
#include "core/math/float_util.h"
#include "core/math/fma_clone.h"
#include "core/math/quadratic.h"
#include "core/math/rng.h"
#include "core/math/transform.h"

namespace rt {
namespace {

// a * b + c as the code is built: the copy for CPUs with FMA (which the loader picks on such a
// CPU, as for the triangle test) is where GCC would fuse it without -ffp-contract=off
SCADRAY_FMA_CLONES
double productPlusSum(double a, double b, double c) { return a * b + c; }

// The product (1 + 2^-30)(1 - 2^-30) = 1 - 2^-60 rounds to 1, so the sum is 0; fused, it would be
// -2^-60. The error bounds and the same picture on every CPU need the rounded product.
TEST(FloatUtil, ProductsAreRoundedBeforeTheSum) {
    EXPECT_EQ(productPlusSum(1 + 0x1p-30, 1 - 0x1p-30, -1), 0.0);
}

TEST(Quadratic, SolvesOrderedRoots) {
    double t0, t1;
    ASSERT_TRUE(solveQuadratic(1, -3, 2, &t0, &t1));
    EXPECT_DOUBLE_EQ(t0, 1);
    EXPECT_DOUBLE_EQ(t1, 2);
    EXPECT_FALSE(solveQuadratic(1, 0, 1, &t0, &t1));
}

TEST(Quadratic, AvoidsCancellationForSmallRoot) {
    // x^2 - 1e8 x + 1 = 0 has roots ~1e-8 and ~1e8; the naive formula loses the small one
    double t0, t1;
    ASSERT_TRUE(solveQuadratic(1, -1e8, 1, &t0, &t1));
    EXPECT_NEAR(t0, 1e-8, 1e-8 * 1e-12);
    EXPECT_NEAR(t1, 1e8, 1e8 * 1e-15);
}

TEST(Quadratic, LinearAndDegenerate) {
    double t0, t1;
    ASSERT_TRUE(solveQuadratic(0, 2, -4, &t0, &t1));
    EXPECT_EQ(t0, 2);
    EXPECT_EQ(t1, 2);
    EXPECT_FALSE(solveQuadratic(0, 0, 1, &t0, &t1));
}

TEST(DegreeTrig, ExactAtSpecialAngles) {
    EXPECT_EQ(cosDegrees(90), 0.0);
    EXPECT_EQ(sinDegrees(180), 0.0);
    EXPECT_EQ(sinDegrees(-90), -1.0);
    EXPECT_EQ(cosDegrees(360 + 60), 0.5);
    EXPECT_EQ(sinDegrees(30), 0.5);
    EXPECT_EQ(sinDegrees(45), std::sqrt(0.5));
    EXPECT_NEAR(sinDegrees(10), std::sin(10 * M_PI / 180), 1e-16);
    EXPECT_TRUE(std::isnan(sinDegrees(NAN)));
}

TEST(Mat4, RotationsAreExactAtRightAngles) {
    Mat4 r = Mat4::rotateX(90);
    Vec3 v = r.transformVector(Vec3(0, 1, 0));
    EXPECT_EQ(v, Vec3(0, 0, 1));
    // OpenSCAD's rotate([x,y,z]) = Rz Ry Rx: x first about world axes
    Mat4 m = Mat4::rotateZ(90) * Mat4::rotateY(0) * Mat4::rotateX(90);
    EXPECT_EQ(m.transformVector(Vec3(0, 1, 0)), Vec3(0, 0, 1));
    EXPECT_EQ(m.transformVector(Vec3(1, 0, 0)), Vec3(0, 1, 0));
    EXPECT_EQ(m.transformVector(Vec3(0, 0, 1)), Vec3(1, 0, 0));
    Mat4 axis = Mat4::rotateAxis(90, Vec3(0, 0, 2));
    EXPECT_EQ(axis.transformVector(Vec3(1, 0, 0)), Vec3(0, 1, 0));
}

TEST(Mat4, MirrorIsHouseholder) {
    Mat4 m = Mat4::mirror(Vec3(1, 1, 0));
    Vec3 v = m.transformVector(Vec3(1, 0, 0));
    EXPECT_NEAR(v.x, 0, 1e-15);
    EXPECT_NEAR(v.y, -1, 1e-15);
    EXPECT_LT(m.det3(), 0);
    EXPECT_TRUE(Mat4::mirror(Vec3(0, 0, 0)).isIdentity());
}

TEST(Mat4, AffineInverseRoundTrips) {
    Mat4 m = Mat4::translate(Vec3(1, -2, 3)) * Mat4::rotateAxis(33, Vec3(1, 2, 3)) *
             Mat4::scale(Vec3(2, 0.5, -3));
    auto inv = m.affineInverse();
    ASSERT_TRUE(inv);
    Mat4 id = m * *inv;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_NEAR(id.m[i][j], i == j ? 1 : 0, 1e-14);
}

TEST(Mat4, SingularityIsRelativeToScale) {
    EXPECT_FALSE(Mat4::scale(Vec3(1, 0, 1)).affineInverse());
    EXPECT_TRUE(Mat4::scale(Vec3(1e-6)).affineInverse());
    EXPECT_TRUE(Mat4::scale(Vec3(1e6)).affineInverse());
    Mat4 nan = Mat4::translate(Vec3(NAN, 0, 0));
    EXPECT_FALSE(nan.affineInverse());
}

TEST(Mat4, ExtremeScalesInvertWithoutOverflow) {
    // det of a 1e150 or 1e300 scale overflows a double; the inverse itself is representable
    for (double s : {1e-300, 1e-150, 1e150, 1e300}) {
        Mat4 m = Mat4::rotateAxis(33, Vec3(1, 2, 3)) * Mat4::scale(Vec3(s, 2 * s, -s));
        auto inv = m.affineInverse();
        ASSERT_TRUE(inv) << s;
        Mat4 id = *inv * m;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) EXPECT_NEAR(id.m[i][j], i == j ? 1 : 0, 1e-14) << s;
    }
    // Rows parallel to within 1e-14 radians are singular at any scale; 1e-6 is not
    for (double s : {1e-200, 1.0, 1e200}) {
        Mat4 nearly = Mat4::identity();
        nearly.m[0][0] = nearly.m[1][0] = s;
        nearly.m[1][1] = 1e-14 * s;
        EXPECT_FALSE(nearly.affineInverse()) << s;
        nearly.m[1][1] = 1e-6 * s;
        EXPECT_TRUE(nearly.affineInverse()) << s;
    }
}

TEST(Transform, NormalsStayPerpendicular) {
    auto t = Transform::fromMatrix(Mat4::scale(Vec3(1, 4, 0.5)) * Mat4::rotateZ(30));
    ASSERT_TRUE(t);
    Vec3 tangent(1, 1, 0), n(1, -1, 0);  // perpendicular in object space
    EXPECT_NEAR(dot(t->vector(tangent), t->normal(n)), 0, 1e-14);
}

TEST(Transform, PointErrorBoundCoversRounding) {
    auto t = Transform::fromMatrix(Mat4::translate(Vec3(1e6, -3e5, 7)) *
                                   Mat4::rotateAxis(17, Vec3(1, 2, 3)));
    ASSERT_TRUE(t);
    Rng rng(7);
    for (int i = 0; i < 1000; ++i) {
        Vec3 p(rng.uniform() * 100 - 50, rng.uniform() * 100 - 50, rng.uniform() * 100 - 50);
        Vec3 err;
        Vec3 q = t->point(p, Vec3(0), &err);
        // Compare with a long-double evaluation
        const auto &m = t->matrix().m;
        for (int k = 0; k < 3; ++k) {
            long double exact = (long double)m[k][0] * p.x + (long double)m[k][1] * p.y +
                                (long double)m[k][2] * p.z + m[k][3];
            EXPECT_LE(std::abs((long double)q[k] - exact), (long double)err[k]);
        }
    }
}

TEST(Transform, BoundsContainTransformedCorners) {
    auto t =
        Transform::fromMatrix(Mat4::rotateAxis(40, Vec3(1, 1, 0)) * Mat4::scale(Vec3(1, 2, 3)));
    Bounds3 b(Vec3(-1, 0, 2), Vec3(1, 3, 5));
    Bounds3 tb = t->bounds(b);
    for (int i = 0; i < 8; ++i) {
        Vec3 c(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z);
        EXPECT_TRUE(tb.contains(t->point(c)));
    }
}

TEST(Bounds3, SlabTestIsNanSafe) {
    Bounds3 b(Vec3(0, 0, 0), Vec3(1, 1, 1));
    // Ray in the plane x = 0 (a face) with d.x = 0: 0 * inf = NaN must not drop the hit
    Ray r(Vec3(0, -1, 0.5), Vec3(0, 1, 0));
    EXPECT_TRUE(b.intersectP(r, 0, kInfinity));
    Ray miss(Vec3(2, -1, 0.5), Vec3(0, 1, 0));
    EXPECT_FALSE(b.intersectP(miss, 0, kInfinity));
    EXPECT_TRUE(Bounds3().isEmpty());
}

TEST(Rng, ReproducibleAndUniform) {
    Rng a = Rng::forSample(12, 3, 99), b = Rng::forSample(12, 3, 99), c = Rng::forSample(13, 3, 99);
    EXPECT_EQ(a.uniformU32(), b.uniformU32());
    EXPECT_NE(Rng::forSample(12, 3, 99).uniformU32(), c.uniformU32());
    Rng r(1);
    double sum = 0;
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        double u = r.uniform();
        ASSERT_GE(u, 0);
        ASSERT_LT(u, 1);
        sum += u;
    }
    EXPECT_NEAR(sum / n, 0.5, 0.005);  // 5 standard errors
}

}  // namespace
}  // namespace rt

namespace rt {
namespace {

// nextUp and nextDown step the bit pattern instead of calling std::nextafter: the same double
// for every input, signed zeros, denormals, the largest finite values and infinities included.
TEST(FloatUtil, NextUpAndNextDownAreNextafter) {
    std::vector<double> values = {0.0,
                                  -0.0,
                                  1.0,
                                  -1.0,
                                  0.1,
                                  -0.1,
                                  1e-310,
                                  -1e-310,
                                  std::numeric_limits<double>::denorm_min(),
                                  -std::numeric_limits<double>::denorm_min(),
                                  std::numeric_limits<double>::min(),
                                  -std::numeric_limits<double>::min(),
                                  std::numeric_limits<double>::max(),
                                  -std::numeric_limits<double>::max(),
                                  kInfinity,
                                  -kInfinity,
                                  2.0,
                                  0.5,
                                  1e300,
                                  -1e-300};
    Rng rng(3);
    for (int i = 0; i < 1000; ++i)
        values.push_back(
            std::ldexp(rng.uniform() - 0.5, static_cast<int>(rng.uniform() * 2000) - 1000));
    for (double v : values) {
        SCOPED_TRACE(v);
        EXPECT_EQ(std::bit_cast<uint64_t>(nextUp(v)),
                  std::bit_cast<uint64_t>(std::nextafter(v, kInfinity)));
        EXPECT_EQ(std::bit_cast<uint64_t>(nextDown(v)),
                  std::bit_cast<uint64_t>(std::nextafter(v, -kInfinity)));
    }
    EXPECT_TRUE(std::isnan(nextUp(std::nan(""))));
    EXPECT_TRUE(std::isnan(nextDown(std::nan(""))));
}

// floatBelow and floatAbove, branch-free, give the float the definition asks for: converted to
// nearest and stepped with std::nextafter where the conversion went the wrong way; the result
// is on the right side of x and no float lies between them. Signed zeros, doubles below the
// smallest float denormal, float denormals, the largest floats, doubles beyond them and the
// infinities included, and doubles one double step either side of floats.
TEST(FloatUtil, FloatBelowAndAboveAreTheNearestFloatsOnEachSide) {
    using FL = std::numeric_limits<float>;
    std::vector<double> values = {0.0,
                                  -0.0,
                                  1e-300,
                                  -1e-300,
                                  1e-46,
                                  -1e-46,
                                  1.0,
                                  -1.0,
                                  0.1,
                                  -0.1,
                                  FL::denorm_min(),
                                  -double(FL::denorm_min()),
                                  FL::min(),
                                  -double(FL::min()),
                                  FL::max(),
                                  -double(FL::max()),
                                  3.5e38,
                                  -3.5e38,
                                  1e300,
                                  -1e300,
                                  kInfinity,
                                  -kInfinity};
    Rng rng(5);
    for (int i = 0; i < 3000; ++i) {
        double v = std::ldexp(rng.uniform() - 0.5, static_cast<int>(rng.uniform() * 300) - 160);
        values.push_back(v);
        // a float and its double neighbours
        double f = static_cast<float>(v);
        values.insert(values.end(), {f, nextUp(f), nextDown(f)});
    }
    for (double x : values) {
        SCOPED_TRACE(x);
        float below = static_cast<float>(x), above = below;
        if (static_cast<double>(below) > x) below = std::nextafter(below, -FL::infinity());
        if (static_cast<double>(above) < x) above = std::nextafter(above, FL::infinity());
        EXPECT_EQ(std::bit_cast<uint32_t>(floatBelow(x)), std::bit_cast<uint32_t>(below));
        EXPECT_EQ(std::bit_cast<uint32_t>(floatAbove(x)), std::bit_cast<uint32_t>(above));
        EXPECT_LE(static_cast<double>(floatBelow(x)), x);
        EXPECT_GE(static_cast<double>(floatAbove(x)), x);
        if (std::isfinite(x)) {
            EXPECT_GT(static_cast<double>(std::nextafter(floatBelow(x), FL::infinity())), x);
            EXPECT_LT(static_cast<double>(std::nextafter(floatAbove(x), -FL::infinity())), x);
        }
    }
#if defined(__SSE2__)
    // The two-lane versions give the same floats in both lanes, whatever the other lane holds
    for (size_t i = 0; i + 1 < values.size(); ++i) {
        double a = values[i], b = values[values.size() - 1 - i];
        SCOPED_TRACE(testing::Message() << a << ", " << b);
        alignas(16) float below[4], above[4];
        _mm_store_ps(below, floatsBelow(_mm_setr_pd(a, b)));
        _mm_store_ps(above, floatsAbove(_mm_setr_pd(a, b)));
        EXPECT_EQ(std::bit_cast<uint32_t>(below[0]), std::bit_cast<uint32_t>(floatBelow(a)));
        EXPECT_EQ(std::bit_cast<uint32_t>(below[1]), std::bit_cast<uint32_t>(floatBelow(b)));
        EXPECT_EQ(std::bit_cast<uint32_t>(above[0]), std::bit_cast<uint32_t>(floatAbove(a)));
        EXPECT_EQ(std::bit_cast<uint32_t>(above[1]), std::bit_cast<uint32_t>(floatAbove(b)));
    }
#endif
}

}  // namespace
}  // namespace rt
