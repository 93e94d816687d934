// SPDX-License-Identifier: MIT
// Monte Carlo effects against answers known in closed form. A glossy mirror (and a frosted
// glass surface) looks straight up at a bright half-space: the radiance it returns is the
// lobe's probability of pointing into the bright part, an integral of the density computed
// here by quadrature, independent of the sampler. The render's mean must agree within its own
// standard error, and the test must be sharp enough to tell a 10 % wider lobe apart.
#include <gtest/gtest.h>

#include <cmath>

#include "core/materials/lobe_sampling.h"
#include "core/render/render_scene.h"
#include "core/render/renderer.h"
#include "support/scene_builder.h"

namespace rt {
namespace {

using namespace rt::test;

constexpr double kPi = 3.14159265358979323846;
/// Height of the bright sheet above the mirror. It begins at x = edge, one lobe spread off the
/// centre (edge = kHeight tan(sigma)), where the answer is most sensitive to the spread: a
/// direction is bright when tan(theta) cos(phi) >= edge / kHeight.
constexpr double kHeight = 1;

/// Probability that a lobe direction about +z has tan(theta) cos(phi) >= a: for each theta
/// the fraction of azimuths with cos(phi) >= a / tan(theta).
double brightFraction(const Lobe &lobe, double a) {
    constexpr int kSteps = 20000;
    double h = (kPi / 2) / kSteps, sum = 0;
    for (int i = 0; i < kSteps; ++i) {
        double theta = (i + 0.5) * h;
        double c = a / std::tan(theta);
        double frac = c >= 1 ? 0 : c <= -1 ? 1 : std::acos(c) / kPi;
        sum += lobe.pdfTheta(theta) * frac * h;
    }
    return sum;
}

/// Camera looking straight down (or up, from inside glass) at the origin with a tiny field of
/// view, so every sample meets the surface at the origin.
struct Estimate {
    double mean, standardError;
};

Estimate renderCentre(ir::Scene &s, const Vec3 &eye) {
    s.camera = lookAt(eye, Vec3(0, 0, 0), 1e-4, Vec3(0, 1, 0));
    DiagnosticSink diag;
    auto rs = RenderScene::compile(s, diag);
    RenderOptions o;
    o.width = o.height = 1;
    o.samplesPerPixel = 16;
    o.batches = 100;
    o.threads = 1;
    o.seed = 3;
    RenderResult r = renderImage(*rs, o);
    EXPECT_EQ(r.stats.nonFinite, 0);
    return {r.image.at(0, 0).g, std::sqrt(r.variance.at(0, 0).g)};
}

/// A bright sheet over x >= edge at height kHeight, so thin that rays meet it only through
/// its underside: beyond its edge they escape to the black background.
void addBrightHalfSpace(ir::Scene &s, double edge) {
    ir::Material bright = plainMaterial(Rgb(1), 1, 0);
    s.root->children.push_back(box(Vec3(edge, -1e4, kHeight), Vec3(1e4, 1e4, kHeight * (1 + 1e-9)),
                                   s.addMaterial(bright)));
}

ir::Material blurred(ir::Material m, ir::Finish::Lobe shape, bool frosted, double degrees) {
    (frosted ? m.finish.frosted : m.finish.glossy) = degrees;
    m.finish.blurLobe = shape;
    m.finish.blurSamples = 64;
    return m;
}

Estimate glossyMirror(ir::Finish::Lobe shape, double degrees, double edge) {
    ir::Scene s = emptyScene();
    ir::Material mirror = plainMaterial(Rgb(1));
    mirror.finish.reflectionMin = mirror.finish.reflectionMax = Rgb(1);
    s.root->children.push_back(box(Vec3(-100, -100, -1), Vec3(100, 100, 0),
                                   s.addMaterial(blurred(mirror, shape, false, degrees))));
    addBrightHalfSpace(s, edge);
    return renderCentre(s, Vec3(0, 0, kHeight / 2));
}

Estimate frostedGlass(ir::Finish::Lobe shape, double degrees, double edge) {
    // The camera sits inside a block of glass and looks up through its top face at normal
    // incidence, where the sharp refracted ray goes straight on
    ir::Scene s = emptyScene();
    s.root->children.push_back(
        box(Vec3(-100, -100, -100), Vec3(100, 100, 0),
            s.addMaterial(blurred(glassMaterial(1.5), shape, true, degrees))));
    addBrightHalfSpace(s, edge);
    return renderCentre(s, Vec3(0, 0, -kHeight / 2));
}

struct KnownAnswerCase {
    ir::Finish::Lobe shape;
    bool frosted;
    double degrees;
};

class KnownAnswer : public ::testing::TestWithParam<KnownAnswerCase> {};

TEST_P(KnownAnswer, ConvergesToTheLobesIntegral) {
    const KnownAnswerCase &c = GetParam();
    LobeShape shape = c.shape == ir::Finish::Lobe::Phong ? LobeShape::Phong : LobeShape::Normal;
    double sigma = c.degrees * kPi / 180;
    double edge = kHeight * std::tan(sigma);
    double want = brightFraction(Lobe(shape, sigma), edge / kHeight);
    double wider = brightFraction(Lobe(shape, sigma * 1.1), edge / kHeight);
    Estimate got =
        c.frosted ? frostedGlass(c.shape, c.degrees, edge) : glossyMirror(c.shape, c.degrees, edge);
    // Within 4.5 standard errors (and a hair of quadrature error) of the exact value ...
    EXPECT_NEAR(got.mean, want, 4.5 * got.standardError + 1e-5)
        << "standard error " << got.standardError;
    // ... while a 10 % wider lobe would be many standard errors away: the test has teeth
    EXPECT_GT(std::abs(wider - want), 8 * got.standardError);
}

INSTANTIATE_TEST_SUITE_P(Effects, KnownAnswer,
                         ::testing::Values(KnownAnswerCase{ir::Finish::Lobe::Normal, false, 10},
                                           KnownAnswerCase{ir::Finish::Lobe::Phong, false, 10},
                                           KnownAnswerCase{ir::Finish::Lobe::Normal, false, 30},
                                           KnownAnswerCase{ir::Finish::Lobe::Normal, true, 10},
                                           KnownAnswerCase{ir::Finish::Lobe::Phong, true, 30}),
                         [](const auto &param) {
                             const KnownAnswerCase &c = param.param;
                             return std::string(c.frosted ? "Frosted" : "Glossy") +
                                    (c.shape == ir::Finish::Lobe::Phong ? "Phong" : "Normal") +
                                    std::to_string(static_cast<int>(c.degrees)) + "deg";
                         });

TEST(MonteCarlo, GlossyWhiteFurnaceLosesNoEnergy) {
    // A glossy sphere in a uniformly white world: every reflected ray, folded or not, sees
    // white, so each pixel on the sphere is exactly its reflectivity
    ir::Scene s = emptyScene();
    s.settings.background = Rgb(1);
    ir::Material m = plainMaterial(Rgb(1));
    m.finish.reflectionMin = m.finish.reflectionMax = Rgb(0.7);
    m.finish.glossy = 40;
    s.root->children.push_back(sphere(1, s.addMaterial(m)));
    s.camera = lookAt(Vec3(0, -5, 0), Vec3(0, 0, 0), 30);
    DiagnosticSink diag;
    auto rs = RenderScene::compile(s, diag);
    RenderOptions o;
    o.width = o.height = 21;
    o.samplesPerPixel = 4;
    RenderResult r = renderImage(*rs, o);
    EXPECT_NEAR(r.image.at(10, 10).r, 0.7, 1e-7);  // images hold floats
    EXPECT_NEAR(r.image.at(10, 4).r, 0.7, 1e-7);   // off-centre, where the lobe folds
    EXPECT_GT(r.stats.distributed, 0);
    EXPECT_EQ(r.stats.reflection, 0);
}

ir::Scene softShadowScene() {
    ir::Scene s = emptyScene();
    ir::Material floor = plainMaterial(Rgb(0.8), 0.1, 0.7);
    ir::Material glossy = plainMaterial(Rgb(0.9, 0.5, 0.3), 0.1, 0.3);
    glossy.finish.reflectionMin = glossy.finish.reflectionMax = Rgb(0.5);
    glossy.finish.glossy = 8;
    s.root->children.push_back(box(Vec3(-5, -5, -1), Vec3(5, 5, 0), s.addMaterial(floor)));
    s.root->children.push_back(translated(Vec3(0, 0, 1), sphere(1, s.addMaterial(glossy))));
    ir::Light l = pointLight(Vec3(2, -2, 6));
    l.area = true;
    l.areaLight.axis1 = Vec3(2, 0, 0);
    l.areaLight.axis2 = Vec3(0, 2, 0);
    l.areaLight.n1 = l.areaLight.n2 = 4;
    l.areaLight.jitter = true;
    s.lights.push_back(l);
    s.camera = lookAt(Vec3(0, -8, 4), Vec3(0, 0, 0.5), 45);
    return s;
}

TEST(MonteCarlo, RendersAreTheSameOnAnyThreadCount) {
    ir::Scene s = softShadowScene();
    DiagnosticSink diag;
    auto rs = RenderScene::compile(s, diag);
    RenderOptions o;
    o.width = 40;
    o.height = 30;
    o.samplesPerPixel = 2;
    o.seed = 5;
    o.threads = 1;
    RenderResult one = renderImage(*rs, o);
    o.threads = 2;
    o.tileSize = 7;
    RenderResult two = renderImage(*rs, o);
    for (int y = 0; y < o.height; ++y)
        for (int x = 0; x < o.width; ++x) ASSERT_EQ(one.image.at(x, y), two.image.at(x, y));
    EXPECT_GT(one.stats.distributed, 0);
    // Another seed gives another (noisy) image
    o.seed = 6;
    RenderResult other = renderImage(*rs, o);
    int differ = 0;
    for (int y = 0; y < o.height; ++y)
        for (int x = 0; x < o.width; ++x) differ += !(other.image.at(x, y) == one.image.at(x, y));
    EXPECT_GT(differ, 50);
}

TEST(MonteCarlo, SoftShadowPenumbraConvergesBetweenLitAndDark) {
    // Jittered area light: under the sphere's edge the shadow is partial and its noise falls
    // with samples per pixel as 1/sqrt(n)
    ir::Scene s = softShadowScene();
    DiagnosticSink diag;
    auto rs = RenderScene::compile(s, diag);
    RenderOptions o;
    o.width = 40;
    o.height = 30;
    o.batches = 16;
    o.threads = 2;
    double meanVar[2];
    for (int k = 0; k < 2; ++k) {
        o.samplesPerPixel = k == 0 ? 1 : 16;
        RenderResult r = renderImage(*rs, o);
        double sum = 0;
        int n = 0;
        for (int y = 0; y < o.height; ++y)
            for (int x = 0; x < o.width; ++x)
                if (r.variance.at(x, y).g > 0) sum += r.variance.at(x, y).g, ++n;
        ASSERT_GT(n, 20);
        meanVar[k] = sum / (o.width * o.height);
    }
    // Variance of the mean drops by about 16 (stratification may do better)
    EXPECT_LT(meanVar[1], meanVar[0] / 8);
}

TEST(MonteCarlo, OneRayAreaShadowsBelowASplitKeepTheMean) {
    // A glossy floor reflects a diffuse wall lit by an area light: below the glossy split each
    // path sends one shadow ray, drawn by grid weight. A mirror (the same scene without
    // gloss) evaluates the full grid at the wall. With a tiny spread the two must agree in
    // the mean, while the glossy render sends far fewer shadow rays per reflected hit.
    auto render = [](double glossy) {
        ir::Scene s = emptyScene();
        ir::Material floor = plainMaterial(Rgb(1));
        floor.finish.reflectionMin = floor.finish.reflectionMax = Rgb(1);
        floor.finish.glossy = glossy;
        floor.finish.blurSamples = 4;
        s.root->children.push_back(box(Vec3(-10, -10, -1), Vec3(10, 10, 0), s.addMaterial(floor)));
        s.root->children.push_back(box(Vec3(-10, 4, 0), Vec3(10, 5, 10),
                                       s.addMaterial(plainMaterial(Rgb(0.8), 0.1, 0.8))));
        s.root->children.push_back(
            box(Vec3(-1, 1, 0), Vec3(1, 2, 3), s.addMaterial(plainMaterial(Rgb(0.5), 0.1, 0.8))));
        ir::Light l = pointLight(Vec3(0, -4, 6));
        l.area = true;
        l.areaLight.axis1 = Vec3(4, 0, 0);
        l.areaLight.axis2 = Vec3(0, 0, 4);
        l.areaLight.n1 = l.areaLight.n2 = 5;
        s.lights.push_back(l);
        s.camera = lookAt(Vec3(0, -8, 2), Vec3(0, -1, 0), 30);  // sees only the floor
        DiagnosticSink diag;
        auto rs = RenderScene::compile(s, diag);
        RenderOptions o;
        o.width = 24;
        o.height = 16;
        o.samplesPerPixel = 64;
        o.threads = 2;
        return renderImage(*rs, o);
    };
    RenderResult sharp = render(0), glossy = render(1e-6);
    double a = 0, b = 0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 24; ++x) a += sharp.image.at(x, y).g, b += glossy.image.at(x, y).g;
    EXPECT_NEAR(b / a, 1, 0.01);
    // Camera rays that meet the wall or the block directly take the full 5 x 5 grid in both;
    // reflected hits take 25 shadow rays behind the mirror, at most 1 behind the gloss
    int64_t direct = sharp.stats.camera - sharp.stats.reflection;
    EXPECT_LE(glossy.stats.shadow, 25 * direct + glossy.stats.distributed);
    EXPECT_GT(sharp.stats.shadow, 25 * direct + 20 * sharp.stats.reflection);
}

}  // namespace
}  // namespace rt
