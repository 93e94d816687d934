// SPDX-License-Identifier: MIT
// Builtin function tests with exact expected output (values checked against OpenSCAD 2021.01).
#include <gtest/gtest.h>

#include "importers/scad/lang/value.h"
#include "importers/scad/test_support.h"

namespace rt::scad::test {
namespace {

std::string ev(const std::string &expr) { return echoOf("echo(" + expr + ");"); }

TEST(NumberFormat, SixSignificantDigitsLikeOpenScad) {
    EXPECT_EQ(formatNumber(123456789), "1.23457e+8");
    EXPECT_EQ(formatNumber(1234565), "1.23457e+6");  // exact tie rounds away from zero
    EXPECT_EQ(formatNumber(123456), "123456");
    EXPECT_EQ(formatNumber(999999.5), "1e+6");
    EXPECT_EQ(formatNumber(0.00001), "0.00001");
    EXPECT_EQ(formatNumber(0.000001), "1e-6");
    EXPECT_EQ(formatNumber(1.0 / 3), "0.333333");
    EXPECT_EQ(formatNumber(-0.0), "0");
    EXPECT_EQ(formatNumber(12345.65), "12345.6");  // the double is just below the tie
    EXPECT_EQ(formatNumber(1.5e20), "1.5e+20");
    EXPECT_EQ(formatNumber(1.0 / 0.0), "inf");
    EXPECT_EQ(formatNumber(-1.0 / 0.0), "-inf");
    EXPECT_EQ(ev("0/0, 1e21, 100.5, 3.14159265"), "nan, 1e+21, 100.5, 3.14159");
}

TEST(Arithmetic, ModuloAndPowerFollowC) {
    EXPECT_EQ(ev("-7 % 3, 7 % -3, 5.5 % 2, 0 % 0"), "-1, 1, 1.5, nan");
    EXPECT_EQ(ev("2^10, 2^0.5, (-8)^(1/3)"), "1024, 1.41421, nan");
}

TEST(Arithmetic, VectorRules) {
    EXPECT_EQ(ev("[1, 2, 3] + [1, 1], [1, 2] - [1], -[1, [2, 3]]"), "[2, 3], [0], [-1, [-2, -3]]");
    EXPECT_EQ(ev("[1, 2] * [3, 4], [[1, 2], [3, 4]] * [1, 1], [1, 1] * [[1, 2], [3, 4]]"),
              "11, [3, 7], [4, 6]");
    EXPECT_EQ(ev("[[1, 2], [3, 4]] * [[0, 1], [1, 0]], [2, 4] / 2, 2 / [2, 4]"),
              "[[2, 1], [4, 3]], [1, 2], [1, 0.5]");
    EXPECT_EQ(ev("[1, 2] * [3], [1, 2] / [1, 2], \"a\" + \"b\", true + 1"),
              "undef, undef, undef, undef");
}

TEST(Arithmetic, ComparisonsAndEquality) {
    EXPECT_EQ(ev("[1, 2] < [1, 3], [1, 2] < [1, 2, 0], \"a\" < \"b\", false < true"),
              "true, true, true, true");
    EXPECT_EQ(ev("1 < true, \"a\" < 1, [1, 2] == [1, 2], 1 == true, undef == undef"),
              "undef, undef, true, false, true");
    Imported r = importText("x = 1 < \"a\";");
    EXPECT_TRUE(r.hasWarning("undefined operation (number < string)"));
}

TEST(Truthiness, ValuesAsConditions) {
    EXPECT_EQ(ev("!0, !\"\", ![], !undef, ![0], !\"0\", ![0:0]"),
              "true, true, true, true, false, false, false");
}

TEST(MathBuiltins, DegreeTrigonometryIsExactAtSpecialAngles) {
    EXPECT_EQ(echoOf("echo(cos(90) == 0, sin(180) == 0, sin(30) == 0.5, cos(60) == 0.5, "
                     "tan(45) == 1, sin(-90) == -1, cos(720) == 1);"),
              "true, true, true, true, true, true, true");
    EXPECT_EQ(ev("tan(90), tan(270), asin(0.5), acos(-1), atan(1), atan2(1, 1), atan2(0, -1)"),
              "inf, -inf, 30, 180, 45, 45, 180");
}

TEST(MathBuiltins, RoundingAndBasics) {
    EXPECT_EQ(ev("round(2.5), round(-2.5), round(-0.4), ceil(-1.2), floor(-1.2)"),
              "3, -3, 0, -1, -2");
    EXPECT_EQ(ev("abs(-3), sign(-2), sign(0), sign(3), sqrt(16), pow(2, 10)"),
              "3, -1, 0, 1, 4, 1024");
    EXPECT_EQ(ev("exp(0), ln(1), log(1000), log(2, 8), norm([3, 4]), PI"),
              "1, 0, 3, 3, 5, 3.14159");
    EXPECT_EQ(ev("cross([1, 0, 0], [0, 1, 0]), cross([1, 2], [3, 4])"), "[0, 0, 1], -2");
    Imported r = importText("x = sqrt(\"a\"); y = sin(1, 2);");
    EXPECT_TRUE(r.hasWarning("sqrt() parameter could not be converted"));
    EXPECT_TRUE(r.hasWarning("sin() number of parameters does not match"));
}

TEST(MathBuiltins, MinMax) {
    EXPECT_EQ(ev("min(3, 1, 2), max(3, 1, 2), min([3, 1, 2]), max([4, 9]), min([\"b\", \"a\"])"),
              "1, 3, 1, 9, \"a\"");
    EXPECT_EQ(ev("min(), max([]), min(1, \"a\"), max(1)"), "undef, undef, undef, 1");
}

TEST(MathBuiltins, SeededRandsMatchOpenScad) {
    // std::mt19937 + uniform_real_distribution, as OpenSCAD (values from OpenSCAD 2021.01)
    EXPECT_EQ(ev("rands(0, 1, 3, 42)"), "[0.796543, 0.183435, 0.779691]");
    EXPECT_EQ(ev("rands(5, 1, 2, 1), rands(0, 10, 2.7, 1), rands(0, 1, 0)"),
              "[4.98874, 4.73023], [9.97185, 9.32557], []");
    EXPECT_EQ(ev("len(rands(0, 1, 4))"), "4");
}

TEST(StringBuiltins, StrChrOrdLen) {
    EXPECT_EQ(ev("str(\"a\", 1.5, [1, \"b\"], true, undef)"), "\"a1.5[1, \"b\"]trueundef\"");
    EXPECT_EQ(ev("str(123456789), str(0.1 + 0.2)"), "\"1.23457e+8\", \"0.3\"");
    EXPECT_EQ(ev("chr(65), chr([72, 105]), chr(233), ord(\"A\"), ord(\"é\"), ord(\"\")"),
              "\"A\", \"Hi\", \"é\", 65, 233, undef");
    EXPECT_EQ(ev("len([1, 2, 3]), len(\"héllo\"), len(5)"), "3, 5, undef");
    EXPECT_EQ(ev("\"abc\"[1], \"héllo\"[1], [1, 2, 3][1.7], [1, 2, 3][-1], [1, 2].z"),
              "\"b\", \"é\", 2, undef, undef");
}

TEST(ListBuiltins, Concat) {
    EXPECT_EQ(ev("concat([1, 2], [3]), concat(1, [2, [3]], \"s\"), concat()"),
              "[1, 2, 3], [1, 2, [3], \"s\"], []");
}

TEST(ListBuiltins, LookupInterpolatesAndClamps) {
    EXPECT_EQ(ev("lookup(5, [[0, 0], [10, 100]]), lookup(-5, [[0, 0], [10, 100]])"), "50, 0");
    EXPECT_EQ(ev("lookup(15, [[0, 0], [10, 100]]), lookup(2.5, [[3, 30], [1, 10], [2, 20]])"),
              "100, 25");
    EXPECT_EQ(ev("lookup(1, []), lookup(\"a\", [[1, 2]])"), "undef, undef");
}

TEST(ListBuiltins, Search) {
    EXPECT_EQ(ev("search(\"abce\", \"abcdabcd\")"), "[0, 1, 2]");
    EXPECT_EQ(ev("search(\"a\", \"abcdabcd\", 0)"), "[[0, 4]]");
    EXPECT_EQ(ev("search(3, [1, 3, 3]), search(3, [1, 3, 3], 0)"), "[1], [1, 2]");
    EXPECT_EQ(ev("search([1, 7], [1, 3, 5]), search([1, 5], [1, 3, 5, 5], 0)"),
              "[0, []], [[0], [2, 3]]");
    EXPECT_EQ(ev("search(\"a\", [[\"a\", 1], [\"b\", 2]]), search(1, [[0, 1], [1, 2]], 1, 1)"),
              "[0], [0]");
    Imported r = importText("x = search(\"z\", \"abc\");");
    EXPECT_TRUE(r.hasWarning("search term not found: \"z\""));
}

TEST(TypeBuiltins, IsFunctions) {
    EXPECT_EQ(ev("is_num(1), is_num(0/0), is_num(\"1\"), is_list([]), is_list([0:1])"),
              "true, false, false, true, false");
    EXPECT_EQ(ev("is_string(\"\"), is_bool(false), is_bool(0), is_undef(undef), "
                 "is_function(function(x) x)"),
              "true, true, false, true, true");
}

TEST(VersionBuiltins, Report2021) {
    EXPECT_EQ(ev("version(), version_num(), version_num() == 20210100"),
              "[2021, 1, 0], 2.02101e+7, true");
}

TEST(ModuleBuiltins, ParentModule) {
    EXPECT_EQ(echoOf("module m() echo(parent_module(0), parent_module(), $parent_modules);"
                     "module n() m(); n();"),
              "\"m\", \"n\", 2");
    Imported r = importText("x = parent_module(0);");
    EXPECT_TRUE(r.hasWarning("Parent module index (0) greater than the number of modules"));
}

TEST(Ranges, StepsCountsAndDeprecatedOrder) {
    EXPECT_EQ(ev("[for (i = [0:0.1:0.35]) i], [for (i = [3:-1:1]) i], [for (i = [0:-1:3]) i]"),
              "[0, 0.1, 0.2, 0.3], [3, 2, 1], []");
    Imported r = importText("echo([for (i = [3:1]) i]);");
    EXPECT_EQ(r.echoes(), std::vector<std::string>{"[1, 2, 3]"});
    EXPECT_TRUE(r.hasWarning("DEPRECATED: Using ranges of the form [begin:end]"));
    EXPECT_EQ(ev("[0:2:5].begin, [0:2:5][1], [0:2:5].end"), "0, 2, 5");
}

}  // namespace
}  // namespace rt::scad::test

namespace rt::scad::test {
namespace {

TEST(TypeBuiltins, IsUndefOfUnknownVariableDoesNotWarn) {
    Imported r = importText("echo(is_undef(nosuch), is_undef($nosuch));");
    EXPECT_EQ(r.echoes(), std::vector<std::string>{"true, true"});
    EXPECT_TRUE(r.warnings().empty());
}

}  // namespace
}  // namespace rt::scad::test
