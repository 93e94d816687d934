// SPDX-License-Identifier: MIT
// Viewer framing (glTF, STL and OFF files without a camera): the bounding sphere, seen from the
// front-right and above, fills 80-95 % of the picture's smaller side, whatever the model's
// size and place and the picture's shape; .scad framing is unchanged.
#include <gtest/gtest.h>

#include <cmath>

#include "core/ir/scene_defaults.h"
#include "support/scene_builder.h"

namespace rt {
namespace {

using namespace rt::test;

/// Fraction of the picture's smaller side the bounding sphere's outline spans.
double sphereFill(const ir::Camera &c, const Vec3 &centre, double radius, double aspect) {
    double tanV = c.fovAxis == ir::FovAxis::Vertical ? std::tan(radians(c.fov) / 2)
                                                     : std::tan(radians(c.fov) / 2) / aspect;
    double tanSmaller = std::min(tanV, tanV * aspect);
    Vec3 view = centre - c.location;
    double distance = length(view);
    // The sphere's centre lies on the view axis: its outline is a circle of angular radius
    // asin(r / D)
    EXPECT_LT(length(cross(normalize(view), normalize(c.lookAt - c.location))), 1e-9);
    return std::tan(std::asin(radius / distance)) / tanSmaller;
}

TEST(ViewerFraming, FillsMostOfTheSmallerSideAtAnyScale) {
    for (double size : {1e-3, 1.0, 1e3})
        for (const Vec3 &offset : {Vec3(0), Vec3(5, -3, 2), Vec3(-1e4, 2e3, 7e2)})
            for (double aspect : {4.0 / 3, 1.0, 0.5, 0.0}) {
                ir::Scene s;
                int m = s.addMaterial(ir::Material());
                Vec3 lo = offset * size, hi = lo + Vec3(2, 1, 0.5) * size;
                s.root->children.push_back(box(lo, hi, m));
                DiagnosticSink diag;
                ir::CompleteOptions co;
                co.framing = ir::Framing::Viewer;
                co.aspect = aspect;
                ir::completeScene(s, diag, co);
                ASSERT_TRUE(s.camera);
                const ir::Camera &c = *s.camera;
                EXPECT_EQ(c.source, ir::CameraSource::Automatic);
                Vec3 centre = (lo + hi) * 0.5;
                double radius = length(hi - lo) / 2;
                EXPECT_LT(length(c.lookAt - centre), 1e-9 * (1 + length(centre)));
                double fill = sphereFill(c, centre, radius, aspect > 0 ? aspect : 4.0 / 3);
                EXPECT_GE(fill, 0.80) << "size " << size << " aspect " << aspect;
                EXPECT_LE(fill, 0.95) << "size " << size << " aspect " << aspect;
                // From the front (-Y) right (+X) and above, at the documented angles
                Vec3 eye = normalize(c.location - c.lookAt);
                EXPECT_NEAR(degrees(std::asin(eye.z)), ir::kViewerElevation, 1e-9);
                EXPECT_NEAR(degrees(std::atan2(eye.x, -eye.y)), ir::kViewerAzimuth, 1e-9);
            }
}

TEST(ViewerFraming, OpenScadFramingIsTheDefault) {
    ir::Scene s;
    s.root->children.push_back(box(Vec3(0), Vec3(1), s.addMaterial(ir::Material())));
    DiagnosticSink diag;
    ir::completeScene(s, diag);
    EXPECT_DOUBLE_EQ(s.camera->fov, ir::kOpenScadDefaultFov);
}

}  // namespace
}  // namespace rt
