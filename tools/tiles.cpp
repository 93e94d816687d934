// SPDX-License-Identifier: MIT
// Tiles of a picture: layout, fingerprints, tile files and their assembly.
#include "tools/tiles.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/ir/facet_mode.h"
#include "core/ir/ir_dump.h"

namespace rt::cli {

namespace {

namespace fs = std::filesystem;

/// FNV-1a, 64 bits: tells renders apart by accident, not against an adversary (a tile file is
/// trusted as much as the scene it was rendered from).
class Hasher {
  public:
    void bytes(const void *data, size_t n) {
        const auto *p = static_cast<const unsigned char *>(data);
        for (size_t i = 0; i < n; ++i) h_ = (h_ ^ p[i]) * 0x100000001b3ULL;
    }
    /// A length-prefixed piece, so that ("ab", "c") and ("a", "bc") differ.
    void piece(const void *data, size_t n) {
        uint64_t len = n;
        bytes(&len, sizeof len);
        bytes(data, n);
    }
    void text(const std::string &s) { piece(s.data(), s.size()); }
    template <typename T>
    void vector(const std::vector<T> &v) {
        piece(v.data(), v.size() * sizeof(T));
    }
    /// The file's bytes; throws std::runtime_error when it cannot be read.
    void file(const std::string &path) {
        std::ifstream in(path, std::ios::binary);
        if (!in) throw std::runtime_error("cannot read '" + path + "' to fingerprint it");
        std::vector<char> buf(1 << 16);
        uint64_t total = 0;
        while (in.read(buf.data(), buf.size()) || in.gcount() > 0) {
            bytes(buf.data(), size_t(in.gcount()));
            total += uint64_t(in.gcount());
        }
        bytes(&total, sizeof total);
    }
    std::string hex() const {
        char buf[17];
        std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h_));
        return buf;
    }

  private:
    uint64_t h_ = 0xcbf29ce484222325ULL;
};

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

/// Hash of the running scadray binary: tiles from two builds (other compiler, other flags,
/// other code) need not agree to the bit, so they do not merge.
const std::string &binaryFingerprint() {
    static const std::string hash = [] {
        Hasher h;
        std::error_code ec;
        fs::path exe = fs::read_symlink("/proc/self/exe", ec);
        if (ec) return std::string("unknown");
        h.file(exe.string());
        return h.hex();
    }();
    return hash;
}

std::vector<std::string> lines(const std::string &text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

/// The lines of `a` not in `b`, joined by ", " ("seed=0").
std::string onlyIn(const std::string &a, const std::string &b) {
    std::vector<std::string> la = lines(a), lb = lines(b);
    std::string out;
    for (const std::string &l : la)
        if (std::find(lb.begin(), lb.end(), l) == lb.end()) out += (out.empty() ? "" : ", ") + l;
    return out.empty() ? "(none)" : out;
}

/// "1, 3 and 4".
std::string listNumbers(const std::vector<int> &v) {
    std::string s;
    for (size_t i = 0; i < v.size(); ++i)
        s += (i == 0 ? "" : i + 1 == v.size() ? " and " : ", ") + std::to_string(v[i]);
    return s;
}

}  // namespace

TileSpec parseTile(const std::string &text) {
    TileSpec t;
    int k = 0, n = 0;
    char slash = 0, extra = 0;
    std::istringstream in(text);
    auto bad = [&] {
        return std::invalid_argument(
            "--tile takes K/N, tile K (1 to N) of N horizontal bands, not '" + text + "'");
    };
    if (!(in >> k >> slash >> n) || slash != '/' || (in >> extra)) throw bad();
    if (n < 1 || k < 1 || k > n) throw bad();
    t.index = k;
    t.count = n;
    return t;
}

std::string sceneFingerprint(const std::string &path, const ir::Scene &scene) {
    Hasher h;
    h.file(path);
    // The scene as read covers included files, -D values, facets and the automatic camera;
    // the dump writes meshes and textures by size only, so their data is hashed too
    h.text(ir::dump(scene));
    for (const ir::MeshPtr &m : scene.meshes) {
        h.vector(m->positions);
        h.vector(m->normals);
        h.vector(m->uvs);
        h.vector(m->uvs1);
        h.vector(m->tangents);
        h.vector(m->colors);
        h.vector(m->triangles);
    }
    for (const ir::TexturePtr &t : scene.textures) h.vector(t->rgba);
    if (scene.settings.environment.image) h.vector(scene.settings.environment.image->rgba);
    return h.hex();
}

std::string pixelOptions(const RenderOptions &ro, const SceneArgs &scene, bool noPlan) {
    std::string s = "size=" + std::to_string(ro.width) + "x" + std::to_string(ro.height) + "\n";
    if (!ro.adaptive) {
        s += "sampling=uniform\nsamples=" + std::to_string(ro.samplesPerPixel) + "\n";
    } else {
        s += std::string("sampling=") + (ro.adaptiveNoise ? "adaptive-noise" : "adaptive-edges") +
             "\n";
        s += "aa-max=" + std::to_string(ro.adaptiveMax) + "\n";
        if (!ro.adaptiveNoise) s += "aa-threshold=" + number(ro.adaptiveThreshold) + "\n";
        s += "aa-tolerance=" + number(ro.adaptiveTolerance) + "\n";
    }
    if (ro.batches != 1) s += "batches=" + std::to_string(ro.batches) + "\n";
    if (ro.jitterSingleSample) s += "jitter-single-sample\n";
    if (ro.sampleClamp > 0) s += "sample-clamp=" + number(ro.sampleClamp) + "\n";
    s += "seed=" + std::to_string(ro.seed) + "\n";
    s += "facets=" + (scene.facets.empty() ? std::string("auto") : scene.facets) + "\n";
    for (const std::string &d : scene.defines) s += "define=" + d + "\n";
    for (const std::string &l : scene.libraries) s += "library=" + l + "\n";
    if (!scene.environment.empty()) s += "environment=" + scene.environment + "\n";
    if (scene.environmentRotate != 0) s += "env-rotate=" + number(scene.environmentRotate) + "\n";
    s += std::string("plan=") + (noPlan ? "off" : "on") + "\n";
    return s;
}

void writeTile(const RenderResult &r, const std::string &path, TileHeader header) {
    Hasher h;
    h.text(binaryFingerprint());
    h.text(header.sceneHash);
    h.text(header.options);
    header.fingerprint = h.hex();
    ImageEstimate est;
    est.mean = r.image;
    est.variance = r.variance;
    est.ties = r.ties;
    est.batches = r.variance.empty() ? 0 : 1;
    ImageMetadata meta;
    meta.x = 0;
    meta.y = header.rowBegin;
    meta.fullWidth = header.width;
    meta.fullHeight = header.height;
    meta.attributes = {{"scadray:tile", header.tile.text()},
                       {"scadray:scene", header.scene},
                       {"scadray:sceneHash", header.sceneHash},
                       {"scadray:options", header.options},
                       {"scadray:binary", binaryFingerprint()},
                       {"scadray:fingerprint", header.fingerprint},
                       {"scadray:samples", std::to_string(header.samples)}};
    writeEstimate(est, path, meta);
}

TileHeader readTile(const std::string &path, ImageEstimate &pixels) {
    ImageMetadata meta;
    pixels = readEstimate(path, false, &meta);
    std::string tile = meta.attribute("scadray:tile");
    if (tile.empty())
        throw std::runtime_error(
            "'" + path +
            "' is not a tile of `scadray render --tile K/N` (its header has no "
            "scadray:tile)");
    TileHeader h;
    try {
        h.tile = parseTile(tile);
    } catch (const std::invalid_argument &) {
        throw std::runtime_error("'" + path + "' has a malformed scadray:tile '" + tile + "'");
    }
    h.scene = meta.attribute("scadray:scene");
    h.sceneHash = meta.attribute("scadray:sceneHash");
    h.options = meta.attribute("scadray:options");
    h.fingerprint = meta.attribute("scadray:fingerprint");
    std::string samples = meta.attribute("scadray:samples");
    h.samples = samples.empty() ? 0 : std::stoll(samples);
    h.rowBegin = meta.y;
    h.rows = pixels.mean.height();
    h.width = meta.fullWidth;
    h.height = meta.fullHeight;
    if (h.fingerprint.empty() || meta.x != 0 || pixels.mean.width() != h.width)
        throw std::runtime_error(
            "'" + path +
            "' is not a tile of `scadray render --tile K/N` (no fingerprint, or not "
            "whole rows of the picture)");
    return h;
}

Image mergeTiles(const std::vector<std::string> &paths, int64_t *samples) {
    if (paths.empty()) throw std::runtime_error("no tiles to merge");
    std::vector<TileHeader> headers;
    std::vector<ImageEstimate> images(paths.size());
    for (size_t i = 0; i < paths.size(); ++i) headers.push_back(readTile(paths[i], images[i]));
    // Every tile against the first: one render of one scene with the same options (the options
    // first: they say in words what differs, where a scene's hash cannot)
    const TileHeader &first = headers[0];
    const std::string &p0 = paths[0];
    for (size_t i = 1; i < headers.size(); ++i) {
        const TileHeader &t = headers[i];
        const std::string &p = paths[i];
        if (t.width != first.width || t.height != first.height)
            throw std::runtime_error("tiles of different picture sizes: '" + p0 + "' is of " +
                                     std::to_string(first.width) + "x" +
                                     std::to_string(first.height) + ", '" + p + "' of " +
                                     std::to_string(t.width) + "x" + std::to_string(t.height));
        if (t.options != first.options)
            throw std::runtime_error("tiles rendered with different options: '" + p0 + "' with " +
                                     onlyIn(first.options, t.options) + ", '" + p + "' with " +
                                     onlyIn(t.options, first.options));
        if (t.sceneHash != first.sceneHash)
            throw std::runtime_error("tiles of different scenes: '" + p0 + "' is of " +
                                     first.scene + " (" + first.sceneHash + "), '" + p + "' of " +
                                     t.scene + " (" + t.sceneHash + ")");
        if (t.fingerprint != first.fingerprint)
            throw std::runtime_error("tiles rendered by different scadray builds: '" + p0 +
                                     "' and '" + p + "' (pixels need not agree to the bit)");
        if (t.tile.count != first.tile.count)
            throw std::runtime_error("tiles of different tilings: '" + p0 + "' is tile " +
                                     first.tile.text() + ", '" + p + "' tile " + t.tile.text());
    }
    // Each tile once, where the layout puts it
    int n = first.tile.count;
    std::vector<int> owner(n, -1);
    for (size_t i = 0; i < headers.size(); ++i) {
        const TileHeader &t = headers[i];
        int k = t.tile.index - 1;
        if (owner[k] >= 0)
            throw std::runtime_error("overlapping tiles: '" + paths[owner[k]] + "' and '" +
                                     paths[i] + "' are both tile " + t.tile.text());
        owner[k] = static_cast<int>(i);
        auto [begin, end] = tileRows(k, n, t.height);
        if (t.rowBegin != begin || t.rows != end - begin)
            throw std::runtime_error("'" + paths[i] + "' holds rows " + std::to_string(t.rowBegin) +
                                     ".." + std::to_string(t.rowBegin + t.rows - 1) +
                                     ", but tile " + t.tile.text() + " of a picture " +
                                     std::to_string(t.height) + " rows high is rows " +
                                     std::to_string(begin) + ".." + std::to_string(end - 1));
    }
    std::vector<int> missing;
    for (int k = 0; k < n; ++k)
        if (owner[k] < 0) missing.push_back(k + 1);
    if (!missing.empty())
        throw std::runtime_error(
            std::string(missing.size() == 1 ? "tile " : "tiles ") + listNumbers(missing) + " of " +
            std::to_string(n) + " " + (missing.size() == 1 ? "is" : "are") + " missing (" +
            std::to_string(headers.size()) + " of " + std::to_string(n) + " given)");
    // Rows in place
    Image picture(first.width, first.height);
    int64_t total = 0;
    for (size_t i = 0; i < headers.size(); ++i) {
        const std::vector<float> &src = images[i].mean.data();
        std::copy(src.begin(), src.end(),
                  picture.data().begin() + 3 * size_t(headers[i].rowBegin) * size_t(first.width));
        total += headers[i].samples;
    }
    if (samples) *samples = total;
    return picture;
}

}  // namespace rt::cli
