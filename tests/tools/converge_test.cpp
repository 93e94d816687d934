// SPDX-License-Identifier: MIT
// `scadray converge`: the log-log slope fit and the SVG plot as units, and the command end to
// end on a small soft-shadow scene (CSV rows, falling error, option errors, no POV-Ray).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "tools/cli_fixture.h"
#include "tools/svg_plot.h"

namespace rt::cli {
namespace {

namespace fs = std::filesystem;
using test::CliRun;

// --- Slope fit -----------------------------------------------------------------------------

TEST(LogLogFit, RecoversAPowerLaw) {
    std::vector<double> x, y;
    for (double t = 0.001; t < 10; t *= 2) {
        x.push_back(t);
        y.push_back(0.3 * std::pow(t, -0.5));
    }
    LogLogFit fit = fitLogLog(x, y);
    ASSERT_TRUE(fit.valid);
    EXPECT_EQ(fit.points, static_cast<int>(x.size()));
    EXPECT_NEAR(fit.slope, -0.5, 1e-12);
    EXPECT_NEAR(fit.intercept, std::log10(0.3), 1e-12);

    // Least squares: symmetric noise about the line leaves the slope alone
    std::vector<double> noisy = y;
    for (size_t i = 0; i < noisy.size(); ++i) noisy[i] *= (i % 2 ? 1.1 : 1 / 1.1);
    EXPECT_NEAR(fitLogLog(x, noisy).slope, -0.5, 0.02);
}

TEST(LogLogFit, SkipsPointsLogAxesCannotShow) {
    std::vector<double> x = {1, 2, 0, 4, 8, -1, 16};
    std::vector<double> y = {1, 0.5, 3, 0.25, 0, 2, 1.0 / 16};
    LogLogFit fit = fitLogLog(x, y);
    ASSERT_TRUE(fit.valid);
    EXPECT_EQ(fit.points, 4);
    EXPECT_NEAR(fit.slope, -1, 1e-12);
    double nan = std::nan("");
    EXPECT_EQ(fitLogLog({1, nan, 4}, {1, 1, 0.5}).points, 2);
}

TEST(LogLogFit, NeedsTwoDistinctTimes) {
    EXPECT_FALSE(fitLogLog({}, {}).valid);
    EXPECT_FALSE(fitLogLog({1}, {1}).valid);
    EXPECT_FALSE(fitLogLog({2, 2, 2}, {1, 0.5, 0.25}).valid) << "all x equal: no slope";
    // All errors zero (a deterministic scene): nothing to fit, and no division by zero
    LogLogFit zero = fitLogLog({1, 2, 4}, {0, 0, 0});
    EXPECT_FALSE(zero.valid);
    EXPECT_EQ(zero.points, 0);
}

// --- SVG plot --------------------------------------------------------------------------------

/// Tags balance and nest, attributes are quoted, text holds no raw '<' and only known entities.
::testing::AssertionResult wellFormedXml(const std::string &doc) {
    std::vector<std::string> open;
    size_t i = 0;
    while (i < doc.size()) {
        if (doc[i] == '&') {
            size_t semi = doc.find(';', i);
            std::string entity = semi == std::string::npos ? "" : doc.substr(i, semi - i + 1);
            if (entity != "&amp;" && entity != "&lt;" && entity != "&gt;" && entity != "&quot;" &&
                entity != "&apos;")
                return ::testing::AssertionFailure() << "bad entity at " << i;
            i = semi + 1;
            continue;
        }
        if (doc[i] != '<') {
            if (doc[i] == '>') return ::testing::AssertionFailure() << "stray '>' at " << i;
            ++i;
            continue;
        }
        // A tag: find its end outside quoted attribute values
        size_t j = i + 1;
        char quote = 0;
        for (; j < doc.size(); ++j) {
            if (quote) {
                if (doc[j] == quote)
                    quote = 0;
                else if (doc[j] == '<')
                    return ::testing::AssertionFailure() << "'<' in attribute";
            } else if (doc[j] == '"' || doc[j] == '\'') {
                quote = doc[j];
            } else if (doc[j] == '>') {
                break;
            }
        }
        if (j >= doc.size()) return ::testing::AssertionFailure() << "unterminated tag at " << i;
        std::string tag = doc.substr(i + 1, j - i - 1);
        if (tag.empty()) return ::testing::AssertionFailure() << "empty tag at " << i;
        if (tag[0] == '/') {
            std::string name = tag.substr(1);
            if (open.empty() || open.back() != name)
                return ::testing::AssertionFailure()
                       << "</" << name << "> closes <" << (open.empty() ? "" : open.back()) << ">";
            open.pop_back();
        } else if (tag.back() != '/') {
            open.push_back(tag.substr(0, tag.find_first_of(" \t\n")));
        }
        i = j + 1;
        if (open.empty() && doc.find('<', i) != std::string::npos)
            return ::testing::AssertionFailure() << "content after the root element";
    }
    if (!open.empty()) return ::testing::AssertionFailure() << "<" << open.back() << "> not closed";
    return ::testing::AssertionSuccess();
}

size_t count(const std::string &text, const std::string &what) {
    size_t n = 0;
    for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
    return n;
}

LogLogPlot samplePlot() {
    LogLogPlot plot;
    plot.title = "a&b <scene>.scad: error against render time";
    plot.legendTitle = "a&b <scene>.scad, 32x24";
    plot.xLabel = "render time (seconds)";
    plot.yLabel = "RMSE";
    std::vector<double> x = {0.0023, 0.0046, 0.0092, 0.0184, 0.7}, y;
    for (double t : x) y.push_back(0.002 * std::pow(t, -0.5));
    plot.addSeries({"scadray", "#1f77b4", x, y, Stroke::Solid, true});
    plot.addSeries(
        {"POV-Ray", "#d62728", x, {0.05, 0.03, 0.02, 0.015, 0.012}, Stroke::Solid, true});
    plot.addLine({"least-squares fit: slope -0.500", "#1f77b4", -0.5, 1, 0.002, Stroke::Dashed});
    plot.addLine({"slope -1/2", "#555555", -0.5, x[0], y[0], Stroke::Dotted});
    plot.addNote("RMSE corrected for the reference's own noise");
    return plot;
}

TEST(LogLogPlot, DecadesCoverTheData) {
    LogLogPlot plot = samplePlot();
    DecadeRange r = plot.range();
    // x from 0.0023 to 0.7, y from 0.0024 to 0.05
    EXPECT_EQ(r.xLo, -3);
    EXPECT_EQ(r.xHi, 0);
    EXPECT_EQ(r.yLo, -3);
    EXPECT_EQ(r.yHi, -1);
    // Exact powers of ten do not add a decade; a single point still gets one
    LogLogPlot exact;
    exact.addSeries({"s", "black", {0.01, 1}, {1000, 10}});
    r = exact.range();
    EXPECT_EQ(r.xLo, -2);
    EXPECT_EQ(r.xHi, 0);
    EXPECT_EQ(r.yLo, 1);
    EXPECT_EQ(r.yHi, 3);
    LogLogPlot one;
    one.addSeries({"s", "black", {0.05}, {0.01}});
    r = one.range();
    EXPECT_EQ(r.xLo, -2);
    EXPECT_EQ(r.xHi, -1);
    EXPECT_EQ(r.yLo, -2);
    EXPECT_EQ(r.yHi, -1);
    // Lines do not widen the axes; points a log axis cannot show are ignored
    exact.addLine({"l", "black", -0.5, 1e-9, 1e9});
    exact.addSeries({"zero", "black", {0.5, 1e-12}, {0, -1}});
    EXPECT_EQ(exact.range().xLo, -2);
    EXPECT_EQ(exact.range().yHi, 3);
}

TEST(LogLogPlot, DecadeLabels) {
    EXPECT_EQ(decadeLabel(0), "1");
    EXPECT_EQ(decadeLabel(2), "100");
    EXPECT_EQ(decadeLabel(-1), "0.1");
    EXPECT_EQ(decadeLabel(-3), "0.001");
    EXPECT_EQ(decadeLabel(-5), "1e-5");
    EXPECT_EQ(decadeLabel(6), "1e6");
}

TEST(LogLogPlot, WritesWellFormedSvg) {
    std::string svg = samplePlot().svg();
    EXPECT_EQ(svg.rfind("<svg", 0), 0u) << svg.substr(0, 80);
    EXPECT_NE(svg.find("xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
    EXPECT_TRUE(wellFormedXml(svg));
    // Both series joined by lines, with a marker per point
    EXPECT_EQ(count(svg, "<polyline"), 2u);
    EXPECT_EQ(count(svg, "<circle"), 10u + 2u) << "5 points per series and 2 legend markers";
    // The fitted line dashed, the reference line dotted
    EXPECT_EQ(count(svg, "class=\"power-line\""), 2u);
    EXPECT_NE(svg.find("stroke-dasharray=\"8 5\""), std::string::npos);
    EXPECT_NE(svg.find("stroke-dasharray=\"1.5 4\""), std::string::npos);
    // Legend: the scene name (escaped), the slope, the note
    EXPECT_NE(svg.find("id=\"legend\""), std::string::npos);
    EXPECT_NE(svg.find("a&amp;b &lt;scene&gt;.scad, 32x24"), std::string::npos);
    EXPECT_NE(svg.find("least-squares fit: slope -0.500"), std::string::npos);
    EXPECT_NE(svg.find("the reference&apos;s own noise"), std::string::npos);
    // A labelled tick at every decade of both axes: 0.001 .. 1 (x), 0.001 .. 0.1 (y)
    for (const char *label : {">0.001<", ">0.01<", ">0.1<", ">1<"})
        EXPECT_GE(count(svg, label), 1u) << label;
    EXPECT_EQ(count(svg, "class=\"tick-label\""), 4u + 3u);
    EXPECT_NE(svg.find("render time (seconds)"), std::string::npos);
}

TEST(LogLogPlot, EmptyPlotIsStillADocument) {
    LogLogPlot plot;
    plot.title = "nothing";
    plot.addSeries({"zero", "black", {1, 2}, {0, 0}});
    plot.addNote("all errors ~0");
    std::string svg = plot.svg();
    EXPECT_TRUE(wellFormedXml(svg));
    EXPECT_EQ(count(svg, "<polyline"), 0u);
    EXPECT_NE(svg.find("all errors ~0"), std::string::npos);
}

TEST(LogLogPlot, WriteIsAtomic) {
    fs::path dir = fs::temp_directory_path() / "scadray_svg_plot_write";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::string path = (dir / "plot.svg").string();
    samplePlot().write(path);
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    EXPECT_EQ(ss.str(), samplePlot().svg());
    int files = 0;
    for ([[maybe_unused]] const auto &e : fs::directory_iterator(dir)) ++files;
    EXPECT_EQ(files, 1) << "no temporary left behind";
    EXPECT_THROW(samplePlot().write((dir / "missing" / "plot.svg").string()), std::runtime_error);
    EXPECT_FALSE(fs::exists(dir / "missing"));
    fs::remove_all(dir);
}

// --- The command end to end -------------------------------------------------------------------

class Converge : public test::CliTest {
  protected:
    Converge() : CliTest("scadray_converge_") {}

    /// `scadray converge` with `args`.
    CliRun run(const std::string &args, const std::string &env = "") const {
        return CliTest::run("converge " + args, env);
    }
    /// A sphere over a floor under a jittered 4x4 area light: soft shadows, so the error of
    /// each sample count is Monte Carlo noise that falls with more samples.
    std::string softShadows() {
        return write("soft.scad",
                     "use <scadray.scad>\n"
                     "camera(location=[0,-9,7], look_at=[0,0,0.5], fov=45);\n"
                     "area_light(position=[0,0,10], axis1=[2,0,0], axis2=[0,2,0], samples=[4,4], "
                     "jitter=true);\n"
                     "translate([-5,-5,-1]) cube([10,10,1]);\n"
                     "translate([0,0,3]) sphere(1.2, $fn=32);\n");
    }
    /// Rows of a CSV file below its header, split at commas (empty fields kept).
    static std::vector<std::vector<std::string>> rows(const std::string &csv, std::string *header) {
        std::vector<std::vector<std::string>> out;
        std::istringstream in(csv);
        std::string line;
        std::getline(in, *header);
        while (std::getline(in, line)) {
            std::vector<std::string> fields;
            size_t start = 0;
            for (size_t comma; (comma = line.find(',', start)) != std::string::npos;
                 start = comma + 1)
                fields.push_back(line.substr(start, comma - start));
            fields.push_back(line.substr(start));
            out.push_back(fields);
        }
        return out;
    }
};

TEST_F(Converge, SoftShadowErrorFallsWithSamples) {
    std::string scene = softShadows();
    fs::path out = dir / "out";
    CliRun r = run("-W 32 -H 24 --max-samples 8 -t 2 --seed 3 -o " + out.string() + " " + scene);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::string header;
    auto table = rows(slurp(out / "soft_converge.csv"), &header);
    EXPECT_EQ(header, "samples,seconds,rmse,rmse_corrected,efficiency,rmse_povray");
    ASSERT_EQ(table.size(), 4u) << "one row per level: 1, 2, 4, 8 spp";
    for (size_t i = 0; i < table.size(); ++i) {
        ASSERT_EQ(table[i].size(), 6u);
        EXPECT_EQ(std::stoi(table[i][0]), 1 << i);
        EXPECT_GT(std::stod(table[i][1]), 0) << "seconds";
        EXPECT_GE(std::stod(table[i][2]), std::stod(table[i][3])) << "corrected <= raw";
        EXPECT_EQ(table[i][5], "") << "no POV-Ray column without --povray";
    }
    double first = std::stod(table.front()[3]), last = std::stod(table.back()[3]);
    EXPECT_GT(first, 0);
    EXPECT_LT(last, first * 0.6) << "8 spp has about 1/sqrt(8) of the error of 1 spp";
    EXPECT_GT(std::stod(table.back()[4]), 0) << "efficiency";

    // The table and the fit on stdout, the plot beside the CSV
    EXPECT_NE(r.out.find("fit: slope"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("rmse_corr"), std::string::npos);
    std::string svg = slurp(out / "soft_converge.svg");
    EXPECT_EQ(svg.rfind("<svg", 0), 0u);
    EXPECT_TRUE(wellFormedXml(svg));
    EXPECT_NE(svg.find("soft.scad"), std::string::npos);
    EXPECT_NE(svg.find("<polyline"), std::string::npos);
    EXPECT_NE(svg.find("slope"), std::string::npos);
    int files = 0;
    for ([[maybe_unused]] const auto &e : fs::directory_iterator(out)) ++files;
    EXPECT_EQ(files, 2) << "the CSV and the SVG, no temporaries";
}

TEST_F(Converge, BudgetStopsDoubling) {
    std::string scene = softShadows();
    fs::path out = dir / "out";
    CliRun r =
        run("-W 32 -H 24 --max-samples 8 -t 1 --budget 1e-9 -o " + out.string() + " " + scene);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::string header;
    EXPECT_EQ(rows(slurp(out / "soft_converge.csv"), &header).size(), 1u);
    EXPECT_NE(r.out.find("stopped after 1 spp"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("no fit: only one level"), std::string::npos) << r.out;
}

TEST_F(Converge, DeterministicSceneSaysSo) {
    // The camera looks away from the only object: every pixel is the background at any count
    std::string scene = write("empty_view.scad",
                              "use <scadray.scad>\n"
                              "camera(location=[0,-10,0], look_at=[0,-20,0]);\n"
                              "background(color=[0.2,0.3,0.4]);\ncube(1);\n");
    fs::path out = dir / "out";
    CliRun r = run("-W 16 -H 12 --max-samples 4 -t 1 -o " + out.string() + " " + scene);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("all errors are ~0"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
    std::string header;
    auto table = rows(slurp(out / "empty_view_converge.csv"), &header);
    ASSERT_EQ(table.size(), 3u);
    for (const auto &row : table) {
        EXPECT_LT(std::stod(row[2]), 1e-6);
        EXPECT_EQ(row[4], "") << "efficiency is unbounded: left empty";
    }
    EXPECT_TRUE(wellFormedXml(slurp(out / "empty_view_converge.svg")));
}

TEST_F(Converge, BadOptionsFailClearlyAndWriteNothing) {
    std::string scene = softShadows();
    fs::path out = dir / "out";
    struct Case {
        std::string args, mention;
    };
    std::vector<Case> cases = {
        {"--max-samples 0", "max-samples"},
        {"--max-samples 100000", "max-samples"},
        {"-W 0", "width"},
        {"--budget -1", "budget"},
        {"--budget 0", "budget"},
        {"--reference-samples 0", "reference-samples"},
        {"--supersample 20", "supersample"},
        {"--frobnicate", "frobnicate"},
    };
    for (const auto &c : cases) {
        SCOPED_TRACE(c.args);
        CliRun r = run(c.args + " -o " + out.string() + " " + scene);
        EXPECT_EQ(r.exitCode, 2);
        EXPECT_NE(r.err.find(c.mention), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(out));
    }
    EXPECT_NE(run("--budget -1 " + scene).err.find("--budget: must be > 0, not -1"),
              std::string::npos);
    // A scene that does not load: a located error, exit 1, nothing written
    std::string bad = write("bad.scad", "cube(1);\nsphere(r=2;\n");
    CliRun r = run("-W 8 -H 6 --max-samples 2 -o " + out.string() + " " + bad);
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("bad.scad:2:"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
}

TEST_F(Converge, PovRayMissingIsANote) {
    std::string scene = softShadows();
    fs::path out = dir / "out";
    CliRun r = run("-W 16 -H 12 --max-samples 2 -t 1 --povray -o " + out.string() + " " + scene,
                   "PATH=/nonexistent");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("POV-Ray not installed; skipped"), std::string::npos) << r.err;
    std::string header;
    auto table = rows(slurp(out / "soft_converge.csv"), &header);
    ASSERT_EQ(table.size(), 2u);
    EXPECT_EQ(table[0][5], "");
}

TEST_F(Converge, AgainstPovRay) {
    if (std::system("command -v povray >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "POV-Ray (povray) is not installed";
    std::string scene = softShadows();
    fs::path out = dir / "out";
    CliRun r = run("-W 32 -H 24 --max-samples 4 -t 2 --povray --supersample 2 -o " + out.string() +
                   " " + scene);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::string header;
    auto table = rows(slurp(out / "soft_converge.csv"), &header);
    ASSERT_EQ(table.size(), 3u);
    for (const auto &row : table) EXPECT_GT(std::stod(row[5]), 0) << "rmse_povray";
    EXPECT_NE(r.out.find("POV-Ray:"), std::string::npos) << r.out;
    std::string svg = slurp(out / "soft_converge.svg");
    EXPECT_EQ(count(svg, "<polyline"), 2u) << "the POV-Ray series in a second colour";
    EXPECT_NE(svg.find("#d62728"), std::string::npos);
}

}  // namespace
}  // namespace rt::cli
