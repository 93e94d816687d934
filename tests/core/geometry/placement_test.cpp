// SPDX-License-Identifier: MIT
// A translated leaf adds its offset instead of multiplying by its matrix: the same rays, points,
// normals and error bounds as the matrix gives, bit for bit, but for the sign of a zero.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "core/geometry/primitive.h"
#include "core/geometry/shape.h"
#include "core/math/rng.h"

namespace rt {
namespace {

/// Bit for bit, or both zero where a zero's sign may differ (`zeroSignFree`).
bool same(double a, double b, bool zeroSignFree) {
    if (zeroSignFree && a == 0 && b == 0) return true;
    return std::memcmp(&a, &b, sizeof a) == 0;
}

void expectSame(const Vec3 &fast, const Vec3 &matrix, const Vec3 &offset, const char *what) {
    for (int i = 0; i < 3; ++i)
        EXPECT_TRUE(same(fast[i], matrix[i], offset[i] == 0))
            << what << "[" << i << "]: " << fast[i] << " vs " << matrix[i];
}

/// Error bounds are the same bit for bit. A point or a ray origin may carry a zero of the other
/// sign only on an axis whose offset is zero; a direction or a normal on any axis (the matrix
/// adds its products by 0 to each coordinate, and -0 + +0 is +0).
TEST(Placement, TranslationGivesTheMatrixResultsBitForBit) {
    Rng rng(37);
    auto coordinate = [&](double scale) {
        double u = rng.uniform();
        if (u < 0.1) return 0.0;
        if (u < 0.2) return -0.0;
        return (rng.uniform() * 2 - 1) * scale;
    };
    int translations = 0;
    for (double scale : {1e-6, 1.0, 1e6}) {
        SCOPED_TRACE(scale);
        for (int k = 0; k < 300; ++k) {
            Vec3 offset(coordinate(scale), coordinate(scale), coordinate(scale));
            Transform t = *Transform::fromMatrix(Mat4::translate(offset));
            Placement placement(t);
            if (offset == Vec3(0)) {
                EXPECT_EQ(placement.kind(), Placement::Kind::Identity);
                continue;
            }
            ASSERT_EQ(placement.kind(), Placement::Kind::Translation);
            ++translations;
            Vec3 toWorld = t.matrix().translation(), toObject = t.inverseMatrix().translation();
            double conditioning = transformConditioning(t);
            for (int j = 0; j < 20; ++j) {
                Vec3 p(coordinate(scale), coordinate(scale), coordinate(scale));
                Vec3 d(coordinate(1), coordinate(1), coordinate(1));
                Vec3 err =
                    abs(Vec3(coordinate(scale), coordinate(scale), coordinate(scale))) * 1e-15;
                Vec3 n(coordinate(1), coordinate(1), coordinate(1));
                if (n == Vec3(0)) n.z = 1;

                Ray fast = placement.toObject(Ray(p, d));
                Ray matrix = t.inverseRay(Ray(p, d));
                expectSame(fast.o, matrix.o, toObject, "ray origin");
                expectSame(fast.d, matrix.d, Vec3(0), "ray direction");
                expectSame(placement.pointToObject(p), t.inversePoint(p), toObject, "point");
                expectSame(placement.vectorToWorld(d), t.vector(d), Vec3(0), "vector");
                expectSame(placement.normalToWorld(n), normalize(t.normal(n)), Vec3(0), "normal");

                ObjectSurface os{p, err, n};
                SurfaceInteraction si;
                placement.surfaceToWorld(os, si);
                Vec3 matrixErr;
                Vec3 matrixP = t.point(p, err, &matrixErr);
                expectSame(si.p, matrixP, toWorld, "surface point");
                // The error bound exactly, zero signs included
                expectSame(si.pError, matrixErr * conditioning, Vec3(1), "error bound");
                expectSame(si.n, normalize(t.normal(n)), Vec3(0), "surface normal");
            }
        }
    }
    EXPECT_GT(translations, 800);
}

TEST(Placement, OnlyAnExactIdentityBlockIsATranslation) {
    EXPECT_EQ(Placement(Transform()).kind(), Placement::Kind::Identity);
    EXPECT_EQ(Placement(*Transform::fromMatrix(Mat4::translate(Vec3(1, -2, 0)))).kind(),
              Placement::Kind::Translation);
    for (const Mat4 &m : {Mat4::rotateZ(90), Mat4::rotateX(1e-9), Mat4::scale(Vec3(1, 1, -1)),
                          Mat4::scale(Vec3(1, 1, 1 + 1e-15)), Mat4::mirror(Vec3(1, 0, 0)),
                          Mat4::translate(Vec3(3, 0, 0)) * Mat4::rotateY(180)}) {
        EXPECT_EQ(Placement(*Transform::fromMatrix(m)).kind(), Placement::Kind::General)
            << m.toString();
    }
}

}  // namespace
}  // namespace rt
