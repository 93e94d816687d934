// SPDX-License-Identifier: MIT
// OFF reader ([ST][C][N][4][n]OFF, as CGAL reads it for OpenSCAD): polygons triangulated,
// colours, normals and texture coordinates ignored.
#include <cmath>
#include <filesystem>

#include "core/meshing/triangulate.h"
#include "importers/mesh/mesh_reader.h"
#include "importers/mesh/reader_support.h"

namespace rt::meshio {

namespace {

using detail::Token;

/// At most this many skipped-face warnings per file; the rest are counted in one summary.
constexpr int kMaxFaceWarnings = 10;
/// Larger vertex or face counts are refused outright (the products below must not overflow).
constexpr uint64_t kMaxCount = uint64_t{1} << 40;

/// What the header keyword says about each vertex line.
struct OffHeader {
    bool homogeneous = false;  ///< "4": x y z w, divided by w
    bool dimension = false;    ///< "n": a dimension follows the keyword
};

/// Parses [ST][C][N][4][n]OFF (CGAL's File_header_OFF; the keyword is case-sensitive).
bool parseHeader(std::string_view word, OffHeader &h) {
    if (word.size() < 3 || word.substr(word.size() - 3) != "OFF") return false;
    std::string_view prefix = word.substr(0, word.size() - 3);
    auto take = [&prefix](std::string_view p) {
        if (prefix.substr(0, p.size()) != p) return false;
        prefix.remove_prefix(p.size());
        return true;
    };
    take("ST");
    take("C");
    take("N");
    h.homogeneous = take("4");
    h.dimension = take("n");
    return prefix.empty();
}

class OffParser {
  public:
    OffParser(const std::string &path, const std::string &text,
              std::shared_ptr<const std::string> file, DiagnosticSink &diag)
        : path_(path), scan_(text, std::move(file), '#'), diag_(diag), textBytes_(text.size()) {}

    ir::Mesh parse() {
        ir::Mesh mesh;
        mesh.name = std::filesystem::path(path_).filename().string();
        mesh.loc = SourceLoc(scan_.file(), 0, 0);

        // Header keyword, optional dimension, then the counts (the edge count may be left out)
        Token t;
        if (!scan_.next(t)) throw ParseError(scan_.endLoc(), "empty file: expected 'OFF'");
        OffHeader header;
        if (!parseHeader(t.text, header))
            throw ParseError(scan_.loc(t), "unexpected '" + std::string(t.text) +
                                               "': expected an OFF header ('OFF', 'COFF', "
                                               "'NOFF', '4OFF', ...)");
        Token extra;
        if (scan_.nextOnLine(extra) && extra.text == "BINARY")
            throw ParseError(scan_.loc(extra), "binary OFF files are not supported");
        bool pendingExtra = !extra.text.empty();
        auto nextWord = [&](Token &w) {
            if (pendingExtra) {
                w = extra;
                pendingExtra = false;
                return true;
            }
            return scan_.next(w);
        };
        if (header.dimension) {
            Token d = required(nextWord, "the dimension");
            uint64_t dim;
            if (!detail::parseCount(d.text, dim) || dim != 3)
                throw ParseError(scan_.loc(d), "dimension '" + std::string(d.text) +
                                                   "': only 3-dimensional nOFF is supported");
        }
        Token vertexTok = required(nextWord, "the vertex count");
        uint64_t vertexCount = count(vertexTok, "vertex count");
        uint64_t faceCount = count(required(nextWord, "the face count"), "face count");
        // Each vertex takes at least 6 bytes ("0 0 0\n") and each face 8 ("3 0 1 2\n"), the
        // last line one less: counts the file cannot hold are refused before allocating
        if (vertexCount > kMaxCount || faceCount > kMaxCount ||
            vertexCount * 6 + faceCount * 8 > textBytes_ + 1)
            throw ParseError(scan_.loc(vertexTok),
                             "the header promises " + std::to_string(vertexCount) +
                                 " vertices and " + std::to_string(faceCount) +
                                 " faces, more than a file of " + std::to_string(textBytes_) +
                                 " bytes can hold");
        Token edges;
        if (!pendingExtra && scan_.nextOnLine(edges)) count(edges, "edge count");
        scan_.skipLine();
        detail::checkIndexRange(vertexCount, scan_.afterLast());

        // One vertex per line: x y z [w] then colours, normals etc., which are ignored
        mesh.positions.reserve(vertexCount);
        for (uint64_t i = 0; i < vertexCount; ++i) {
            Vec3 p;
            Token first = required([this](Token &w) { return scan_.next(w); },
                                   ("vertex " + std::to_string(i)).c_str());
            p.x = coordinate(first);
            p.y = coordinate(onLine("a y coordinate", i));
            p.z = coordinate(onLine("a z coordinate", i));
            if (header.homogeneous) {
                double w = coordinate(onLine("a w coordinate", i));
                if (w == 0)
                    throw ParseError(scan_.afterLast(), "vertex " + std::to_string(i) +
                                                            " has w = 0 (a point at infinity)");
                p = p / w;
                if (!p.isFinite())
                    throw ParseError(scan_.afterLast(),
                                     "vertex " + std::to_string(i) + " is not finite after /w");
            }
            mesh.positions.push_back(p);
            scan_.skipLine();
        }

        // One face per line: n i0 ... i(n-1), then an optional colour
        int skipped = 0;
        std::vector<uint32_t> polygon;
        for (uint64_t i = 0; i < faceCount; ++i) {
            Token n = required([this](Token &w) { return scan_.next(w); },
                               ("face " + std::to_string(i)).c_str());
            uint64_t size = count(n, "face size");
            if (size < 3)
                throw ParseError(scan_.loc(n), "face " + std::to_string(i) + " has " +
                                                   std::to_string(size) +
                                                   " vertices; a face needs at least 3");
            polygon.clear();
            for (uint64_t k = 0; k < size; ++k) {
                Token idx;
                if (!scan_.nextOnLine(idx))
                    throw ParseError(scan_.afterLast(), "face " + std::to_string(i) +
                                                            ": expected " + std::to_string(size) +
                                                            " vertex indices, found " +
                                                            std::to_string(k));
                uint64_t v;
                if (!detail::parseCount(idx.text, v))
                    throw ParseError(scan_.loc(idx),
                                     "bad vertex index '" + std::string(idx.text) + "'");
                if (v >= vertexCount)
                    throw ParseError(scan_.loc(idx), "vertex index " + std::to_string(v) +
                                                         " is out of range (the file has " +
                                                         std::to_string(vertexCount) +
                                                         " vertices)");
                polygon.push_back(static_cast<uint32_t>(v));
            }
            SourceLoc faceLoc = scan_.loc(n);
            scan_.skipLine();
            if (!addFace(mesh, polygon)) {
                if (++skipped <= kMaxFaceWarnings)
                    diag_.warning(faceLoc, "face " + std::to_string(i) +
                                               " is degenerate (fewer than 3 distinct points or "
                                               "no area); skipped");
            }
        }
        if (skipped > kMaxFaceWarnings)
            diag_.warning(mesh.loc, std::to_string(skipped) + " degenerate faces skipped in all");
        if (scan_.next(t))
            diag_.warning(scan_.loc(t), "text after the " + std::to_string(faceCount) +
                                            " faces the header announces; ignored");
        if (mesh.triangles.empty()) {
            SourceLoc where = scan_.endLoc();
            throw ParseError(where, faceCount == 0 ? "OFF file holds no faces"
                                                   : "OFF file holds only degenerate faces");
        }
        size_t dropped = weldMesh(mesh);
        if (dropped > 0)
            diag_.note(mesh.loc, std::to_string(dropped) +
                                     " degenerate triangle(s) with repeated corners left out");
        return mesh;
    }

  private:
    template <typename Next>
    Token required(Next &&nextWord, const char *what) {
        Token t;
        if (!nextWord(t))
            throw ParseError(scan_.endLoc(),
                             std::string("unexpected end of file: expected ") + what);
        return t;
    }

    Token onLine(const char *what, uint64_t vertex) {
        Token t;
        if (!scan_.nextOnLine(t))
            throw ParseError(scan_.afterLast(), "vertex " + std::to_string(vertex) + ": expected " +
                                                    what + " on this line");
        return t;
    }

    uint64_t count(const Token &t, const char *what) {
        uint64_t n;
        if (!detail::parseCount(t.text, n))
            throw ParseError(scan_.loc(t),
                             std::string("bad ") + what + " '" + std::string(t.text) + "'");
        return n;
    }

    double coordinate(const Token &t) {
        double d;
        if (!detail::parseNumber(t.text, d))
            throw ParseError(scan_.loc(t), "bad number '" + std::string(t.text) + "'");
        if (!std::isfinite(d))
            throw ParseError(scan_.loc(t),
                             "vertex coordinate '" + std::string(t.text) + "' is not finite");
        return d;
    }

    /// Appends the triangles of one face (counter-clockwise seen from outside, as OFF files
    /// are written). False when the face is degenerate.
    bool addFace(ir::Mesh &mesh, std::vector<uint32_t> &polygon) {
        if (polygon.size() == 3) {
            const auto &p = mesh.positions;
            if (p[polygon[0]] == p[polygon[1]] || p[polygon[1]] == p[polygon[2]] ||
                p[polygon[0]] == p[polygon[2]])
                return false;
            mesh.triangles.push_back({polygon[0], polygon[1], polygon[2]});
            return true;
        }
        return meshing::triangulatePolygon(mesh.positions, polygon, mesh.triangles);
    }

    const std::string &path_;
    detail::TextScanner scan_;
    DiagnosticSink &diag_;
    uint64_t textBytes_;
};

}  // namespace

ir::Mesh readOff(const std::string &path, DiagnosticSink &diag) {
    auto file = std::make_shared<const std::string>(path);
    std::string text = detail::readFileBytes(path, file);
    return OffParser(path, text, file, diag).parse();
}

}  // namespace rt::meshio
