// SPDX-License-Identifier: MIT
// The command line's geometry budget (--max-geometry): on by default, named in the error that
// stops a model asking for too much geometry work, raised or lifted (0) by the option.
#include <gtest/gtest.h>

#include <string>

#include "importers/scad/scad_importer.h"
#include "tools/cli_fixture.h"

namespace rt {
namespace {

class WorkBudget : public test::CliTest {
  protected:
    WorkBudget() : CliTest("scadray_budget_") {}
    test::CliRun run(const std::string &args) const { return CliTest::run(args + " </dev/null"); }
};

TEST_F(WorkBudget, DefaultBudgetStopsTheRunawayOffsetWithALocatedError) {
    std::string in = write("offset.scad", "linear_extrude(1) offset(r=1e9, $fn=1e6) square(1);\n");
    test::CliRun r = run("render -q -W 32 -H 24 -o " + path("o.png") + " " + in);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("offset.scad:1:19: error: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("geometry budget of " + std::to_string(scad::kDefaultMaxGeometry) +
                         " (--max-geometry N raises it"),
              std::string::npos)
        << r.err;
}

TEST_F(WorkBudget, TheOptionRaisesTheBudget) {
    // A sphere of 40 x 20 fragments has 802 faces; its shadow examines about 640,000 pairs
    std::string in = write("shadow.scad", "linear_extrude(1) projection() sphere(5, $fn=40);\n");
    for (const char *cmd : {"dump", "render -q -W 32 -H 24 -o "}) {
        SCOPED_TRACE(cmd);
        std::string out = std::string(cmd).find("render") == 0 ? path("o.png") + " " : "";
        test::CliRun low = run(std::string(cmd) + out + " --max-geometry 100000 " + in);
        EXPECT_EQ(low.exitCode, 1) << low.err;
        EXPECT_NE(low.err.find("shadow.scad:1:19: error: projection(): about 6.4e+05 face pairs"),
                  std::string::npos)
            << low.err;
        EXPECT_NE(low.err.find("--max-geometry"), std::string::npos) << low.err;
        EXPECT_EQ(run(std::string(cmd) + out + " --max-geometry 1000000 " + in).exitCode, 0);
        EXPECT_EQ(run(std::string(cmd) + out + " --max-geometry 0 " + in).exitCode, 0);
        EXPECT_EQ(run(std::string(cmd) + out + " " + in).exitCode, 0);
    }
}

TEST_F(WorkBudget, TheOptionTakesOnlyCountsAndShowsItsRange) {
    std::string in = write("s.scad", "cube(1);\n");
    test::CliRun bad = run("dump --max-geometry -1 " + in);
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.err.find("--max-geometry"), std::string::npos) << bad.err;
    EXPECT_EQ(run("dump --max-geometry 1e9 " + in).exitCode, 2);
    test::CliRun help = run("render --help");
    EXPECT_NE(help.out.find("--max-geometry INT:>= 0=" + std::to_string(scad::kDefaultMaxGeometry)),
              std::string::npos)
        << help.out;
}

}  // namespace
}  // namespace rt
