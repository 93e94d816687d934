// SPDX-License-Identifier: MIT
// `scadray render --tile K/N` and `scadray merge`: the merged picture is the single
// render's, bit for bit, as PNG and as EXR; merge refuses tiles of other scenes, sizes, seeds or
// options, overlapping tiles, and names the tiles missing from a partial set.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/image/image_io.h"
#include "tools/cli_fixture.h"

namespace rt {
namespace {

namespace fs = std::filesystem;
using test::CliRun;

class TileMerge : public test::CliTest {
  protected:
    TileMerge() : CliTest("scadray_tiles_") {}

    /// Renders `tiles` tiles of `sceneArgs` as tile_K.exr; the list of their paths.
    std::string renderTiles(const std::string &sceneArgs, int tiles,
                            const std::string &prefix = "tile_") {
        std::string list;
        for (int k = 1; k <= tiles; ++k) {
            std::string out = path(prefix + std::to_string(k) + ".exr");
            CliRun r = run("render -q " + sceneArgs + " --tile " + std::to_string(k) + "/" +
                           std::to_string(tiles) + " -o " + out);
            EXPECT_EQ(r.exitCode, 0) << r.err;
            list += " " + out;
        }
        return list;
    }

    /// Single render against the merge of `tiles` tiles: the PNG files byte for byte, the EXR
    /// pixels bit for bit (an EXR header carries the time it was written).
    void expectMergeIsSingleRender(const std::string &sceneArgs, int tiles) {
        SCOPED_TRACE(sceneArgs + ", " + std::to_string(tiles) + " tiles");
        ASSERT_EQ(run("render -q " + sceneArgs + " -o " + path("single.png")).exitCode, 0);
        ASSERT_EQ(run("render -q " + sceneArgs + " -o " + path("single.exr")).exitCode, 0);
        std::string list = renderTiles(sceneArgs, tiles);
        CliRun m = run("merge -q" + list + " -o " + path("merged.png"));
        ASSERT_EQ(m.exitCode, 0) << m.err;
        ASSERT_EQ(run("merge -q" + list + " -o " + path("merged.exr")).exitCode, 0);
        std::string a = slurp(path("single.png")), b = slurp(path("merged.png"));
        EXPECT_FALSE(a.empty());
        EXPECT_TRUE(a == b) << "merged PNG differs from the single render's";
        Image x = readImage(path("single.exr")), y = readImage(path("merged.exr"));
        ASSERT_EQ(x.width(), y.width());
        ASSERT_EQ(x.height(), y.height());
        EXPECT_TRUE(x.data() == y.data()) << "merged EXR pixels differ from the single render's";
    }
};

TEST_F(TileMerge, MergedIsTheSingleRenderBitForBit) {
    // Default sampling of a sharp scene: adaptive to edges
    for (int tiles : {1, 3, 7})
        expectMergeIsSingleRender(scene("default.scad") + " -W 45 -H 31", tiles);
    // Uniform sampling
    expectMergeIsSingleRender(scene("default.scad") + " -W 45 -H 31 -s 4 --seed 5", 3);
    // Monte Carlo scene: sampling adaptive to its noise
    expectMergeIsSingleRender(scene("montecarlo/glossy.scad") + " -W 33 -H 23 --aa-max 16", 7);
}

TEST_F(TileMerge, TileFileSaysWhereItLies) {
    std::string out = path("t.exr");
    ASSERT_EQ(
        run("render -q " + scene("default.scad") + " -W 40 -H 30 --tile 2/3 -o " + out).exitCode,
        0);
    ImageMetadata meta;
    ImageEstimate est = readEstimate(out, false, &meta);
    EXPECT_EQ(est.mean.width(), 40);
    EXPECT_EQ(est.mean.height(), 10);
    EXPECT_FALSE(est.ties.empty());
    EXPECT_EQ(meta.y, 10);
    EXPECT_EQ(meta.fullWidth, 40);
    EXPECT_EQ(meta.fullHeight, 30);
    EXPECT_EQ(meta.attribute("scadray:tile"), "2/3");
    EXPECT_NE(meta.attribute("scadray:options").find("size=40x30"), std::string::npos);
    EXPECT_EQ(meta.attribute("scadray:sceneHash").size(), 16u);
}

TEST_F(TileMerge, RefusesTilesOfAnotherRender) {
    std::string base = scene("default.scad") + " -W 30 -H 20";
    std::string tile1 = path("tile_1.exr");
    renderTiles(base, 2);
    auto mergeWith = [&](const std::string &args) {
        std::string other = path("other.exr");
        fs::remove(other);
        CliRun r = run("render -q " + args + " --tile 2/2 -o " + other);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        CliRun m = run("merge " + tile1 + " " + other + " -o " + path("m.png"));
        EXPECT_EQ(m.exitCode, 1);
        EXPECT_FALSE(fs::exists(path("m.png")));
        return m.err;
    };
    EXPECT_NE(mergeWith(base + " --seed 3").find("different options"), std::string::npos);
    EXPECT_NE(mergeWith(base + " --seed 3").find("seed=3"), std::string::npos);
    EXPECT_NE(mergeWith(base + " -s 4").find("sampling=uniform"), std::string::npos);
    EXPECT_NE(mergeWith(base + " --aa-threshold 0.1").find("aa-threshold"), std::string::npos);
    EXPECT_NE(mergeWith(base + " --facets openscad").find("facets=openscad"), std::string::npos);
    EXPECT_NE(mergeWith(base + " -e studio").find("environment=studio"), std::string::npos);
    EXPECT_NE(mergeWith(scene("default.scad") + " -W 30 -H 22").find("different picture sizes"),
              std::string::npos);
    EXPECT_NE(mergeWith(scene("glass.scad") + " -W 30 -H 20").find("different scenes"),
              std::string::npos);
    // A -D that changes the scene
    std::string scad = path("ball.scad");
    std::ofstream(scad) << "r = 1;\nsphere(r);\n";
    std::string ball = scad + " -W 30 -H 20";
    std::string ballTile = path("ball_1.exr");
    ASSERT_EQ(run("render -q " + ball + " --tile 1/2 -o " + ballTile).exitCode, 0);
    ASSERT_EQ(run("render -q " + ball + " -D r=2 --tile 2/2 -o " + path("ball_2.exr")).exitCode, 0);
    CliRun m = run("merge " + ballTile + " " + path("ball_2.exr") + " -o " + path("m.png"));
    EXPECT_EQ(m.exitCode, 1);
    EXPECT_NE(m.err.find("define=r=2"), std::string::npos) << m.err;
    // The same options, another file of the same name: the scene's hash tells them apart
    std::ofstream(scad) << "r = 1;\ncube(r);\n";
    ASSERT_EQ(run("render -q " + ball + " --tile 2/2 -o " + path("ball_2.exr")).exitCode, 0);
    m = run("merge " + ballTile + " " + path("ball_2.exr") + " -o " + path("m.png"));
    EXPECT_EQ(m.exitCode, 1);
    EXPECT_NE(m.err.find("different scenes"), std::string::npos) << m.err;
}

TEST_F(TileMerge, RefusesOverlappingAndMissingTiles) {
    std::string base = scene("default.scad") + " -W 30 -H 20";
    std::string list = renderTiles(base, 4);
    // The same tile twice
    CliRun m = run("merge" + list + " " + path("tile_2.exr") + " -o " + path("m.png"));
    EXPECT_EQ(m.exitCode, 1);
    EXPECT_NE(m.err.find("overlapping tiles"), std::string::npos) << m.err;
    EXPECT_NE(m.err.find("tile 2/4"), std::string::npos) << m.err;
    // A partial set names the missing tiles
    m = run("merge " + path("tile_1.exr") + " " + path("tile_3.exr") + " -o " + path("m.png"));
    EXPECT_EQ(m.exitCode, 1);
    EXPECT_NE(m.err.find("tiles 2 and 4 of 4 are missing"), std::string::npos) << m.err;
    // Tiles of another tiling of the same render
    renderTiles(base, 3, "three_");
    m = run("merge " + path("tile_1.exr") + " " + path("three_2.exr") + " -o " + path("m.png"));
    EXPECT_EQ(m.exitCode, 1);
    EXPECT_NE(m.err.find("different tilings"), std::string::npos) << m.err;
    // An EXR that is no tile
    ASSERT_EQ(run("render -q " + base + " -o " + path("plain.exr")).exitCode, 0);
    m = run("merge " + path("plain.exr") + " -o " + path("m.png"));
    EXPECT_EQ(m.exitCode, 1);
    EXPECT_NE(m.err.find("not a tile"), std::string::npos) << m.err;
    EXPECT_FALSE(fs::exists(path("m.png")));
    // In any order, the whole set merges
    ASSERT_EQ(run("merge " + path("tile_4.exr") + " " + path("tile_2.exr") + " " +
                  path("tile_1.exr") + " " + path("tile_3.exr") + " -o " + path("m.png"))
                  .exitCode,
              0);
}

TEST_F(TileMerge, BadTileOptionsAreUsageErrors) {
    std::string base = "render -q " + scene("default.scad") + " -W 30 -H 5";
    for (const char *bad : {"0/3", "4/3", "3", "a/b", "1/0", "2/3x", "-1/3"}) {
        CliRun r = run(base + " --tile " + bad + " -o " + path("t.exr"));
        EXPECT_EQ(r.exitCode, 2) << bad;
        EXPECT_NE(r.err.find("--tile"), std::string::npos) << r.err;
    }
    // More tiles than rows
    CliRun r = run(base + " --tile 1/6 -o " + path("t.exr"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("rows high"), std::string::npos) << r.err;
    // A tile is an EXR
    r = run(base + " --tile 1/2 -o " + path("t.png"));
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find(".exr"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("t.exr")));
}

}  // namespace
}  // namespace rt
