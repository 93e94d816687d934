// SPDX-License-Identifier: MIT
// OpenImageIO stays out of start-up: neither scadray nor a binary linking the core
// needs libOpenImageIO; it comes with the module scadray_oiio.so, loaded for non-PNG images only,
// and a missing module is a clear error naming it, the paths tried and the file.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "tools/cli_fixture.h"

namespace {

namespace fs = std::filesystem;

/// The shared libraries `binary` needs (DT_NEEDED, as readelf prints them).
std::string neededLibraries(const std::string &binary) {
    std::string out;
    std::FILE *p = ::popen(("readelf -d '" + binary + "' 2>/dev/null").c_str(), "r");
    if (!p) return out;
    char line[512];
    while (std::fgets(line, sizeof line, p))
        if (std::string(line).find("(NEEDED)") != std::string::npos) out += line;
    ::pclose(p);
    return out;
}

bool haveReadelf() { return std::system("readelf --version >/dev/null 2>&1") == 0; }

TEST(ImageModule, NeitherScadrayNorRtCoreLinksOpenImageIO) {
    if (!haveReadelf()) GTEST_SKIP() << "readelf (binutils) is not installed";
    // The module does: the check can see a library when it is there
    std::string module = (fs::path(SCADRAY_BINARY).parent_path() / "scadray_oiio.so").string();
    ASSERT_TRUE(fs::exists(module)) << module;
    EXPECT_NE(neededLibraries(module).find("libOpenImageIO"), std::string::npos)
        << neededLibraries(module);
    std::string scadray = neededLibraries(SCADRAY_BINARY);
    EXPECT_NE(scadray.find("libc.so"), std::string::npos) << scadray;
    EXPECT_EQ(scadray.find("libOpenImageIO"), std::string::npos) << scadray;
    // This test binary links rt_core (and rt_exporters)
    std::string self = neededLibraries(fs::read_symlink("/proc/self/exe").string());
    EXPECT_EQ(self.find("libOpenImageIO"), std::string::npos) << self;
}

class ImageModuleCli : public rt::test::CliTest {
  protected:
    ImageModuleCli() : CliTest("scadray_image_module_") {}
    void SetUp() override {
        CliTest::SetUp();
        scene = write("cube.scad", "cube(1);\n");
    }

    /// Exit code and stderr of scadray run with `env` before it.
    std::pair<int, std::string> run(const std::string &env, const std::string &args) const {
        rt::test::CliRun r = CliTest::run(args, env);
        return {r.exitCode, r.err};
    }
    std::string scene;
};

TEST_F(ImageModuleCli, MissingModuleIsAClearErrorAndPngNeedsNone) {
    std::string absent = (dir / "nowhere" / "scadray_oiio.so").string();
    std::string env = "SCADRAY_OIIO_MODULE='" + absent + "'";
    std::string exr = (dir / "x.exr").string();
    auto [code, err] = run(env, "render " + scene + " -W 2 -H 2 -o " + exr);
    EXPECT_EQ(code, 1) << err;
    for (const std::string &part :
         {std::string("scadray_oiio.so"), absent, exr, std::string("SCADRAY_OIIO_MODULE")})
        EXPECT_NE(err.find(part), std::string::npos) << part << " not in: " << err;
    EXPECT_FALSE(fs::exists(exr));
    // PNG in and out without the module
    std::string png = (dir / "x.png").string();
    auto [pngCode, pngErr] = run(env, "render " + scene + " -W 2 -H 2 -o " + png);
    EXPECT_EQ(pngCode, 0) << pngErr;
    auto [cmpCode, cmpErr] = run(env, "compare " + png + " " + png);
    EXPECT_EQ(cmpCode, 0) << cmpErr;
    // With the module where the variable says, EXR works again
    std::string module = (fs::path(SCADRAY_BINARY).parent_path() / "scadray_oiio.so").string();
    auto [okCode, okErr] =
        run("SCADRAY_OIIO_MODULE='" + module + "'", "render " + scene + " -W 2 -H 2 -o " + exr);
    EXPECT_EQ(okCode, 0) << okErr;
    EXPECT_TRUE(fs::exists(exr));
}

TEST_F(ImageModuleCli, AFileThatIsNotTheModuleIsRefused) {
    std::string fake = (dir / "scadray_oiio.so").string();
    std::ofstream(fake) << "not a shared library";
    auto [code, err] = run("SCADRAY_OIIO_MODULE='" + fake + "'",
                           "render " + scene + " -W 2 -H 2 -o " + (dir / "x.tif").string());
    EXPECT_EQ(code, 1) << err;
    EXPECT_NE(err.find(fake), std::string::npos) << err;
}

}  // namespace
