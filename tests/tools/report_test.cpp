// SPDX-License-Identifier: MIT
// `scadray report`: the figures `check` leaves (JSON), the page (order, escaping, plots, the
// self-check), converge's CSV, and `report --from` end to end on hand-made figures (no
// POV-Ray needed; tests/integration/report_browser.sh runs the real thing in a browser).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/image/image_io.h"
#include "tools/check.h"
#include "tools/cli_fixture.h"
#include "tools/report_html.h"

namespace rt::cli {
namespace {

namespace fs = std::filesystem;

class ReportDir : public test::CliTest {
  protected:
    ReportDir() : CliTest("scadray_report_") {}
};

CheckResult passing(const std::string &scene) {
    CheckResult r;
    r.scene = scene;
    r.pass = true;
    r.width = 64;
    r.height = 48;
    r.rmse = 1.5e-4;
    r.maxError = 0.01;
    r.maskedShare = 0.25;
    r.testedShare = 0.75;
    r.tilesTested = 36;
    r.tilesSkipped = 12;
    r.supersample = 3;
    r.povraySeconds = 0.8;
    r.scadraySeconds = 0.2;
    r.refereePicture = "a_reference.png";
    r.scadrayPicture = "a_scadray.png";
    r.diffPicture = "a_diff.png";
    r.text = "PASS: " + scene + "\n";
    return r;
}

TEST_F(ReportDir, CheckFiguresRoundTrip) {
    CheckResult r = passing("scenes/a.scad");
    r.tilesFailed = 3;
    r.pass = false;
    fs::path json = checkJsonPath(dir.string(), r.scene, false);
    EXPECT_EQ(json.filename(), "a_check.json");
    EXPECT_EQ(fs::path(checkJsonPath(dir.string(), r.scene, true)).filename(),
              "a_openscad_check.json");
    std::ofstream(json) << checkResultJson(r);
    CheckResult back = readCheckResult(json.string());
    EXPECT_EQ(back.scene, r.scene);
    EXPECT_FALSE(back.pass);
    EXPECT_TRUE(back.error.empty());
    EXPECT_EQ(back.tilesFailed, 3);
    EXPECT_DOUBLE_EQ(back.rmse, r.rmse);
    EXPECT_DOUBLE_EQ(back.maskedShare, r.maskedShare);
    EXPECT_DOUBLE_EQ(back.testedShare, r.testedShare);
    EXPECT_DOUBLE_EQ(back.refereeSeconds(), 0.8);
    EXPECT_EQ(back.scadrayPicture, "a_scadray.png");
    EXPECT_EQ(back.dir, dir.string());
    EXPECT_EQ(back.text, r.text);
}

TEST_F(ReportDir, ErrorFiguresRoundTrip) {
    CheckResult r;
    r.scene = "b.scad";
    r.error = "b.scad:3:7: error: unknown module 'cub'";
    fs::path json = dir / "b_check.json";
    std::ofstream(json) << checkResultJson(r);
    CheckResult back = readCheckResult(json.string());
    EXPECT_FALSE(back.pass);
    EXPECT_EQ(back.error, r.error);
}

TEST_F(ReportDir, RefusesOtherJsonAndPathsOutOfTheFolder) {
    std::ofstream(dir / "x_check.json") << "{\"scene\": \"x\"}";
    EXPECT_THROW(readCheckResult((dir / "x_check.json").string()), std::runtime_error);
    std::ofstream(dir / "y_check.json") << "not json";
    EXPECT_THROW(readCheckResult((dir / "y_check.json").string()), std::runtime_error);
    std::ofstream(dir / "z_check.json")
        << "{\"scadray_check\": 1, \"scene\": \"z\", \"referee\": \"povray\", \"verdict\": "
           "\"pass\", \"pictures\": {\"scadray\": \"../../etc/passwd\"}}";
    CheckResult z = readCheckResult((dir / "z_check.json").string());
    EXPECT_TRUE(z.scadrayPicture.empty());
    std::ofstream(dir / "w_check.json")
        << "{\"scadray_check\": 1, \"scene\": \"w\", \"rmse\": \"high\"}";
    EXPECT_THROW(readCheckResult((dir / "w_check.json").string()), std::runtime_error);
}

TEST(ReportPage, FailuresFirstThenByName) {
    std::vector<ReportScene> rows(4);
    rows[0].scene = "b.scad";
    rows[0].povray = passing("b.scad");
    rows[1].scene = "a.scad";
    rows[1].povray = passing("a.scad");
    rows[2].scene = "z.scad";
    rows[2].povray = passing("z.scad");
    rows[2].povray->pass = false;
    rows[3].scene = "y.scad";
    rows[3].povray = passing("y.scad");
    rows[3].openscad = CheckResult{};
    rows[3].openscad->error = "openscad failed";
    sortFailuresFirst(rows);
    EXPECT_EQ(rows[0].scene, "y.scad");  // an error in either check
    EXPECT_EQ(rows[1].scene, "z.scad");
    EXPECT_EQ(rows[2].scene, "a.scad");
    EXPECT_EQ(rows[3].scene, "b.scad");

    ReportPage page;
    page.scenes = rows;
    std::string html = reportHtml(page);
    size_t y = html.find("<tr class=\"error\""), z = html.find("<tr class=\"different\""),
           a = html.find("<tr class=\"pass\"");
    ASSERT_NE(y, std::string::npos);
    ASSERT_NE(z, std::string::npos);
    ASSERT_NE(a, std::string::npos);
    EXPECT_LT(y, z);
    EXPECT_LT(z, a);
    EXPECT_NE(html.find("id=\"report-selfcheck\""), std::string::npos);
    // Summary: 2 of 4 passed; speed ratio 0.8 / 0.2 for each measured scene
    EXPECT_NE(html.find("<b>2 / 4</b>passed"), std::string::npos);
    EXPECT_NE(html.find("4.00&times;"), std::string::npos);
}

TEST(ReportPage, EscapesEverythingFromAScene) {
    ReportScene s;
    s.scene = "<img src=x onerror=alert(1)>.scad";
    s.error = "</script><script>alert(2)</script>";
    ReportPage page;
    page.scenes = {s};
    std::string html = reportHtml(page);
    EXPECT_EQ(html.find("<img src=x"), std::string::npos);
    EXPECT_EQ(html.find("<script>alert"), std::string::npos);
    EXPECT_NE(html.find("&lt;img src=x onerror=alert(1)&gt;.scad"), std::string::npos);
}

TEST(ReportPage, ConvergePlotsWithChartJsOrTheSvg) {
    ReportScene s;
    s.scene = "c.scad";
    s.povray = passing("c.scad");
    s.converge = ConvergeCurve{{1, 2, 4}, {0.01, 0.02, 0.04}, {0.1, 0.07, 0.05}, {}, "<svg/>"};
    ReportPage page;
    page.scenes = {s};
    page.chartJs = "window.Chart = function () {}; // </script> inside";
    std::string html = reportHtml(page);
    EXPECT_NE(html.find("<canvas id=\"plot-0\""), std::string::npos);
    EXPECT_NE(html.find("\"spp\":4"), std::string::npos);
    EXPECT_NE(html.find("\"povraySeconds\":0.8"), std::string::npos);
    EXPECT_NE(html.find("<\\/script> inside"), std::string::npos);
    EXPECT_NE(html.find("converge slope"), std::string::npos);

    page.chartJs.clear();
    html = reportHtml(page);
    EXPECT_EQ(html.find("<canvas"), std::string::npos);
    EXPECT_NE(html.find("data:image/svg+xml;base64," + base64("<svg/>")), std::string::npos);
}

TEST(ReportPage, Base64) {
    EXPECT_EQ(base64(""), "");
    EXPECT_EQ(base64("f"), "Zg==");
    EXPECT_EQ(base64("fo"), "Zm8=");
    EXPECT_EQ(base64("foo"), "Zm9v");
    EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
    EXPECT_EQ(base64(std::string("\xff\x00\x10", 3)), "/wAQ");
    EXPECT_EQ(urlPath("a b/c#1.png"), "a%20b/c%231.png");
}

TEST_F(ReportDir, ReadsConvergeCsv) {
    fs::path csv = dir / "c_converge.csv";
    std::ofstream(csv) << "samples,seconds,rmse,rmse_corrected,efficiency,rmse_povray\n"
                          "1,0.01,0.2,0.19,2770,\n2,0.02,0.15,0.14,2551,\n";
    ConvergeCurve c = readConvergeCsv(csv.string());
    ASSERT_EQ(c.samples.size(), 2u);
    EXPECT_EQ(c.samples[1], 2);
    EXPECT_DOUBLE_EQ(c.rmse[0], 0.19);
    EXPECT_TRUE(c.rmsePovray.empty());
    std::ofstream(csv) << "samples,seconds,rmse,rmse_corrected,efficiency,rmse_povray\n1,2\n";
    try {
        readConvergeCsv(csv.string());
        FAIL() << "a short row was accepted";
    } catch (const std::runtime_error &e) {
        EXPECT_NE(std::string(e.what()).find("c_converge.csv:2:"), std::string::npos) << e.what();
    }
}

/// `scadray report --from` on figures written here: rows, order, embedded pictures, exit 1
TEST_F(ReportDir, FromEarlierChecks) {
    fs::path a = dir / "suite" / "a", b = dir / "suite" / "b";
    fs::create_directories(a);
    fs::create_directories(b);
    Image img(4, 3);
    for (const char *name : {"a_reference.png", "a_scadray.png", "a_diff.png"})
        writeImage(img, (a / name).string());
    std::ofstream(a / "a_check.json") << checkResultJson(passing("a.scad"));
    CheckResult bad = passing("b.scad");
    bad.pass = false;
    bad.refereePicture = bad.scadrayPicture = bad.diffPicture = "";
    std::ofstream(b / "b_check.json") << checkResultJson(bad);
    std::ofstream(b / "broken_check.json") << "{";

    fs::path html = dir / "r.html";
    test::CliRun r = run("report -q --from " + (dir / "suite").string() + " -o " + html.string());
    EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
    std::string page = slurp(html);
    size_t err = page.find("data-verdict=\"error\""),
           diff = page.find("data-verdict=\"different\""),
           pass = page.find("data-verdict=\"pass\"");
    ASSERT_NE(err, std::string::npos) << "the unreadable figures are a row";
    ASSERT_NE(diff, std::string::npos);
    ASSERT_NE(pass, std::string::npos);
    EXPECT_LT(err, diff);
    EXPECT_LT(diff, pass);
    EXPECT_NE(page.find("src=\"data:image/png;base64,"), std::string::npos);
    EXPECT_NE(r.out.find("3 scenes: 1 passed, 1 different, 1 errors"), std::string::npos)
        << r.out << r.err;

    // Nothing to report is bad usage
    EXPECT_EQ(run("report -q --from " + (dir / "suite" / "a").string() + "/.. -o " +
                  (dir / "nofolder" / "r.html").string())
                  .exitCode,
              2);
    EXPECT_EQ(run("report -q -o " + html.string()).exitCode, 2);
}

}  // namespace
}  // namespace rt::cli
