// SPDX-License-Identifier: MIT
// STL reader: binary and ASCII told apart by size and content, vertices welded by position.
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>

#include "importers/mesh/mesh_reader.h"
#include "importers/mesh/reader_support.h"

namespace rt::meshio {

namespace {

using detail::Token;

/// Binary STL layout: an 80-byte header, a 32-bit triangle count, then per triangle a normal
/// and three vertices (12 little-endian floats) and a 16-bit attribute.
constexpr uint64_t kHeaderBytes = 80;
constexpr uint64_t kPrefixBytes = kHeaderBytes + 4;
constexpr uint64_t kTriangleBytes = 50;

uint32_t readLe32(const char *p) {
    uint32_t v;
    std::memcpy(&v, p, sizeof v);
    if constexpr (std::endian::native == std::endian::big)
        v = (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
    return v;
}

float readLeFloat(const char *p) {
    uint32_t bits = readLe32(p);
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

/// True when every byte could belong to an ASCII STL: printable characters, whitespace, or
/// bytes of UTF-8 sequences (names). Binary data is full of NULs and control bytes.
bool looksLikeText(const std::string &data) {
    for (char ch : data) {
        auto c = static_cast<unsigned char>(ch);
        if ((c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\v' && c != '\f') ||
            c == 0x7f)
            return false;
    }
    return true;
}

ir::Mesh newMesh(const std::string &path, const std::shared_ptr<const std::string> &file) {
    ir::Mesh mesh;
    mesh.name = std::filesystem::path(path).filename().string();
    mesh.loc = SourceLoc(file, 0, 0);
    return mesh;
}

/// Appends a triangle of welded vertices unless two of its corners are the same point.
void addTriangle(ir::Mesh &mesh, detail::PositionWelder &welder, const Vec3 (&v)[3],
                 size_t &degenerate) {
    std::array<uint32_t, 3> tri{welder.add(v[0]), welder.add(v[1]), welder.add(v[2])};
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
        ++degenerate;
        return;
    }
    mesh.triangles.push_back(tri);
}

void noteDegenerate(DiagnosticSink &diag, const ir::Mesh &mesh, size_t degenerate) {
    if (degenerate > 0)
        diag.note(mesh.loc, std::to_string(degenerate) +
                                " degenerate triangle(s) with repeated corners left out");
}

ir::Mesh readBinary(const std::string &path, const std::string &data,
                    const std::shared_ptr<const std::string> &file, DiagnosticSink &diag) {
    uint32_t count = readLe32(data.data() + kHeaderBytes);
    ir::Mesh mesh = newMesh(path, file);
    if (count == 0) return mesh;
    detail::PositionWelder welder(mesh.positions);
    welder.reserve(count / 2 + 3);
    mesh.triangles.reserve(count);
    size_t degenerate = 0;
    for (uint64_t i = 0; i < count; ++i) {
        uint64_t offset = kPrefixBytes + i * kTriangleBytes;
        // The facet normal (first 12 bytes) is ignored: the vertex order decides orientation
        const char *p = data.data() + offset + 12;
        Vec3 v[3];
        for (int k = 0; k < 3; ++k) {
            for (int axis = 0; axis < 3; ++axis) {
                float f = readLeFloat(p + 4 * (3 * k + axis));
                if (!std::isfinite(f))
                    throw detail::byteError(file, offset + 12 + 4 * (3 * k + axis),
                                            "triangle " + std::to_string(i) + ", vertex " +
                                                std::to_string(k + 1) + ": coordinate " +
                                                std::to_string(f) + " is not finite");
                v[k][axis] = f;
            }
        }
        addTriangle(mesh, welder, v, degenerate);
        detail::checkIndexRange(mesh.positions.size(), mesh.loc);
    }
    noteDegenerate(diag, mesh, degenerate);
    if (mesh.triangles.empty())
        throw detail::byteError(file, kPrefixBytes, "binary STL holds only degenerate triangles");
    return mesh;
}

/// Recursive-descent reader of `solid name {facet} endsolid name`, possibly repeated.
class AsciiStlParser {
  public:
    AsciiStlParser(const std::string &path, const std::string &text,
                   std::shared_ptr<const std::string> file, DiagnosticSink &diag)
        : path_(path), scan_(text, std::move(file)), diag_(diag) {}

    ir::Mesh parse() {
        ir::Mesh mesh = newMesh(path_, scan_.file());
        detail::PositionWelder welder(mesh.positions);
        size_t degenerate = 0;
        Token t;
        if (!scan_.next(t)) return mesh;  // nothing at all, as OpenSCAD reads it: no triangles
        if (!detail::equalsKeyword(t.text, "solid"))
            throw ParseError(scan_.loc(t), "unexpected '" + std::string(t.text) +
                                               "': expected 'solid' (not an STL file?)");
        skipName();
        Token endsolid;
        for (;;) {
            t = expect("'facet' or 'endsolid'");
            if (detail::equalsKeyword(t.text, "endsolid")) {
                endsolid = t;
                skipName();
                // Several solids may follow each other
                if (!scan_.next(t)) break;
                if (!detail::equalsKeyword(t.text, "solid"))
                    throw unexpected(t, "'solid' or the end of the file");
                skipName();
                continue;
            }
            if (!detail::equalsKeyword(t.text, "facet"))
                throw unexpected(t, "'facet' or 'endsolid'");
            Vec3 v[3];
            facet(v);
            addTriangle(mesh, welder, v, degenerate);
            detail::checkIndexRange(mesh.positions.size(), mesh.loc);
        }
        noteDegenerate(diag_, mesh, degenerate);
        if (mesh.triangles.empty() && degenerate > 0)
            throw ParseError(scan_.loc(endsolid), "STL file holds only degenerate triangles");
        return mesh;
    }

  private:
    /// Skips the optional name after `solid`/`endsolid`: the rest of the line, unless a
    /// keyword follows on the same line (files written on a single line).
    void skipName() {
        Token t;
        while (scan_.nextOnLine(t)) {
            if (detail::equalsKeyword(t.text, "facet") ||
                detail::equalsKeyword(t.text, "endsolid")) {
                pending_ = t;
                hasPending_ = true;
                return;
            }
        }
    }

    bool read(Token &t) {
        if (hasPending_) {
            t = pending_;
            hasPending_ = false;
            return true;
        }
        return scan_.next(t);
    }

    Token expect(const char *what) {
        Token t;
        if (!read(t))
            throw ParseError(scan_.endLoc(),
                             std::string("unexpected end of file: expected ") + what);
        return t;
    }

    ParseError unexpected(const Token &t, const char *what) const {
        return ParseError(scan_.loc(t),
                          "unexpected '" + std::string(t.text) + "': expected " + what);
    }

    void keyword(const char *kw) {
        Token t = expect((std::string("'") + kw + "'").c_str());
        if (!detail::equalsKeyword(t.text, kw))
            throw unexpected(t, (std::string("'") + kw + "'").c_str());
    }

    double number(bool mustBeFinite) {
        Token t = expect("a number");
        double d;
        if (!detail::parseNumber(t.text, d))
            throw ParseError(scan_.loc(t), "bad number '" + std::string(t.text) + "'");
        if (mustBeFinite && !std::isfinite(d))
            throw ParseError(scan_.loc(t),
                             "vertex coordinate '" + std::string(t.text) + "' is not finite");
        return d;
    }

    void facet(Vec3 (&v)[3]) {
        Token t = expect("'normal' or 'outer'");
        if (detail::equalsKeyword(t.text, "normal")) {
            // Ignored (exporters write NaN for degenerate facets): vertex order decides
            for (int i = 0; i < 3; ++i) number(false);
            t = expect("'outer'");
        }
        if (!detail::equalsKeyword(t.text, "outer")) throw unexpected(t, "'outer'");
        keyword("loop");
        for (auto &p : v) {
            keyword("vertex");
            for (int axis = 0; axis < 3; ++axis) p[axis] = number(true);
        }
        keyword("endloop");
        keyword("endfacet");
    }

    const std::string &path_;
    detail::TextScanner scan_;
    DiagnosticSink &diag_;
    Token pending_;
    bool hasPending_ = false;
};

}  // namespace

ir::Mesh readStl(const std::string &path, DiagnosticSink &diag) {
    auto file = std::make_shared<const std::string>(path);
    std::string data = detail::readFileBytes(path, file);
    uint64_t size = data.size();
    // Binary when the size is exactly what the triangle count in the header promises; many
    // binary files start with "solid" too, so the prefix alone decides nothing.
    if (size >= kPrefixBytes) {
        uint64_t expected = kPrefixBytes + kTriangleBytes * readLe32(data.data() + kHeaderBytes);
        if (size == expected) return readBinary(path, data, file, diag);
        if (!looksLikeText(data)) {
            uint32_t count = readLe32(data.data() + kHeaderBytes);
            std::string promise = "the header promises " + std::to_string(count) + " triangles (" +
                                  std::to_string(expected) + " bytes)";
            if (size < expected)
                throw detail::byteError(file, size,
                                        "binary STL is truncated: " + promise +
                                            " but the file ends after " + std::to_string(size) +
                                            " bytes");
            throw detail::byteError(
                file, expected,
                "binary STL triangle count does not match the file size: " + promise +
                    " but the file has " + std::to_string(size) + " bytes");
        }
    } else if (!looksLikeText(data)) {
        throw detail::byteError(file, size,
                                "binary STL is truncated: " + std::to_string(size) +
                                    " bytes, shorter than the 84-byte header and count");
    }
    return AsciiStlParser(path, data, file, diag).parse();
}

}  // namespace rt::meshio
