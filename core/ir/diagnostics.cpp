// SPDX-License-Identifier: MIT
// Diagnostic formatting with a source excerpt, and the collecting sink.
#include "core/ir/diagnostics.h"

#include "core/system/input_file.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <limits>
#include <mutex>
#include <set>

namespace rt {

const std::string &SourceLoc::fileName() const {
    static const std::string kUnknown = "<unknown>";
    return file ? *file : kUnknown;
}

std::string SourceLoc::toString() const {
    if (!file) return "<unknown>";
    std::string s = *file;
    if (line > 0) {
        s += ":" + std::to_string(line);
        if (col > 0) s += ":" + std::to_string(col);
    }
    return s;
}

namespace {

const char *severityName(Severity s) {
    switch (s) {
        case Severity::Note:
            return "note";
        case Severity::Warning:
            return "warning";
        case Severity::Error:
            return "error";
    }
    return "error";
}

/// Lines excerpted around the column: this many bytes either side.
constexpr int kExcerptContext = 60;
/// Messages and kinds are compared on at most this many bytes.
constexpr size_t kKindKeyBytes = 256;

/// The file is indexed in blocks of this many bytes.
constexpr int64_t kIndexBlock = 4096;

/// Which line each block of one file starts in, built once per file (and again when its size
/// or modification time changes): an excerpt then reads at most two blocks and a window of its
/// line, never the file from its start, so a million warnings on one long line cost a million
/// small reads. The index takes 8 bytes per block: 0.2% of the file, whatever its lines.
class LineIndex {
  public:
    /// The bytes [first, last] (1-based columns, clipped to the line) of line `line`, and the
    /// line's length; false when the file is not a readable regular file or has no such line.
    bool window(const std::string &path, int line, int64_t first, int64_t last, std::string &text,
                int64_t &lineLength) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!refresh(path) || line < 1 || line > lines_) return false;
        int64_t begin = lineStart(line);
        int64_t end = line == lines_ ? contentEnd_ : lineStart(line + 1) - 1;
        if (begin < 0 || end < begin) return false;
        // Without the '\r' of a CRLF file
        if (end > begin && read(end - 1, 1) == "\r") --end;
        lineLength = end - begin;
        int64_t from = begin + first - 1, to = std::min(begin + last, end);
        text = from < to ? read(from, to - from) : std::string();
        return true;
    }

  private:
    bool refresh(const std::string &path) {
        struct stat st {};
        // Never open a FIFO or a device: it could block or never end
        if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return false;
        if (path == path_ && st.st_size == size_ && st.st_mtim.tv_sec == mtime_.tv_sec &&
            st.st_mtim.tv_nsec == mtime_.tv_nsec && in_.is_open())
            return true;
        path_.clear();
        blockLine_.clear();
        in_.close();
        in_.clear();
        in_.open(path, std::ios::binary);
        if (!in_) return false;
        std::string block(static_cast<size_t>(kIndexBlock), '\0');
        int64_t offset = 0, line = 1;
        char lastByte = '\0';
        for (;;) {
            in_.read(&block[0], kIndexBlock);
            std::streamsize n = in_.gcount();
            if (n <= 0) break;
            blockLine_.push_back(line);
            line += std::count(block.begin(), block.begin() + n, '\n');
            lastByte = block[static_cast<size_t>(n - 1)];
            offset += n;
        }
        // A final line break ends the last line rather than starting one
        contentEnd_ = lastByte == '\n' ? offset - 1 : offset;
        lines_ = lastByte == '\n' ? line - 1 : line;
        path_ = path;
        size_ = offset;
        mtime_ = st.st_mtim;
        return true;
    }
    /// Offset of the first byte of line `line` (2..lines_); -1 when the file changed under us.
    int64_t lineStart(int64_t line) {
        if (line <= 1) return 0;
        // The last block that starts before line `line` starts: the line starts in it
        auto it = std::lower_bound(blockLine_.begin(), blockLine_.end(), line);
        size_t k = static_cast<size_t>(it - blockLine_.begin()) - 1;
        int64_t base = static_cast<int64_t>(k) * kIndexBlock;
        std::string block = read(base, kIndexBlock);
        int64_t need = line - blockLine_[k];
        for (size_t i = 0; i < block.size(); ++i)
            if (block[i] == '\n' && --need == 0) return base + static_cast<int64_t>(i) + 1;
        return -1;
    }
    std::string read(int64_t offset, int64_t count) {
        std::string out(static_cast<size_t>(std::max<int64_t>(count, 0)), '\0');
        in_.clear();
        in_.seekg(offset);
        in_.read(&out[0], static_cast<std::streamsize>(out.size()));
        out.resize(static_cast<size_t>(std::max<std::streamsize>(in_.gcount(), 0)));
        return out;
    }

    std::mutex mutex_;
    std::string path_;
    std::ifstream in_;
    std::vector<int64_t> blockLine_;  ///< the line number at the start of each block
    int64_t size_ = 0, contentEnd_ = 0, lines_ = 0;
    struct timespec mtime_ {};
};

LineIndex &lineIndex() {
    static LineIndex index;
    return index;
}

std::mutex unquotableMutex;
std::set<std::string> &unquotable() {
    static std::set<std::string> paths;
    return paths;
}

bool isUnquotable(const std::string &path) {
    std::lock_guard<std::mutex> lock(unquotableMutex);
    return unquotable().count(path) > 0;
}

}  // namespace

void markUnquotable(const std::string &path) {
    std::lock_guard<std::mutex> lock(unquotableMutex);
    unquotable().insert(path);
}

std::string formatDiagnostic(const Diagnostic &d, bool withExcerpt) {
    // A diagnostic about the scene as a whole has no location to print
    // File names and messages quote input (names, echo() text): control characters are
    // escaped so that a file cannot drive the terminal (clear it, retitle it, recolour it)
    std::string out = (d.loc.file ? printable(d.loc.toString()) + ": " : std::string()) +
                      severityName(d.severity) + ": " + printable(d.message, true);
    if (!withExcerpt || !d.loc.isValid() || isUnquotable(*d.loc.file)) return out;
    int col = std::max(d.loc.col, 1);
    // Long lines (minified JSON) are shown as a window around the column
    int first = std::max(1, col - kExcerptContext);
    std::string window;
    int64_t lineLength = 0;
    if (!lineIndex().window(*d.loc.file, d.loc.line, first, int64_t{col} + kExcerptContext, window,
                            lineLength) ||
        lineLength == 0)
        return out;
    int64_t last = first - 1 + static_cast<int64_t>(window.size());
    std::string lead = first > 1 ? "..." : "";
    std::string tail = last < lineLength ? "..." : "";
    out += "\n    " + lead + printable(window) + tail + "\n    " + std::string(lead.size(), ' ');
    // Keep tabs so the caret lines up under the offending text, as shown (escapes included)
    size_t before =
        static_cast<size_t>(std::clamp(col - first, 0, static_cast<int>(window.size())));
    for (char c : printable(window.substr(0, before))) out += c == '\t' ? '\t' : ' ';
    out += "^";
    return out;
}

std::string DiagnosticSink::kindOf(const std::string &message) {
    std::string key;
    for (size_t i = 0; i < message.size() && key.size() < kKindKeyBytes; ++i) {
        bool digit = std::isdigit(static_cast<unsigned char>(message[i])) != 0;
        if (!digit)
            key += message[i];
        else if (key.empty() || key.back() != '#')
            key += '#';
    }
    return key;
}

DiagnosticSink::Kind &DiagnosticSink::kindFor(const std::string &message) {
    std::string key = kindOf(message);
    auto it = kindIndex_.find(key);
    if (it != kindIndex_.end()) return kinds_[it->second];
    if (kinds_.size() >= kMaxWarningKinds) return overflowKind_;
    kindIndex_.emplace(key, kinds_.size());
    kinds_.push_back({std::move(key), {}, 0});
    return kinds_.back();
}

void DiagnosticSink::report(Severity s, const SourceLoc &loc, std::string message) {
    ++counts_[static_cast<int>(s)];
    Kind *kind = nullptr;
    if (s == Severity::Warning) {
        kind = &kindFor(message);
        if (kind->count++ == 0) kind->first = {s, loc, message};
        if (kind->count > kWarningsShownPerKind) {
            ++suppressed_;
            return;
        }
    }
    Diagnostic d{s, loc, std::move(message)};
    if (diags_.size() < kMaxKeptDiagnostics) {
        diags_.push_back(d);
        if (kind) ++kind->kept;
    }
    if (listener_) listener_(d);
}

int DiagnosticSink::count(Severity s) const {
    int64_t n = counts_[static_cast<int>(s)];
    return static_cast<int>(std::min<int64_t>(n, std::numeric_limits<int>::max()));
}

int DiagnosticSink::countContaining(const std::string &text) const {
    int64_t n = 0;
    for (const auto &d : diags_) n += d.message.find(text) != std::string::npos;
    // Those not kept are counted by their kind's first message
    auto repeats = [&](const Kind &k) {
        if (k.count > k.kept && k.first.message.find(text) != std::string::npos)
            n += k.count - k.kept;
    };
    for (const auto &k : kinds_) repeats(k);
    repeats(overflowKind_);
    return static_cast<int>(std::min<int64_t>(n, std::numeric_limits<int>::max()));
}

std::vector<std::string> DiagnosticSink::summary() const {
    std::vector<std::string> lines;
    auto line = [&](const Kind &k, const char *like) {
        if (k.count <= kWarningsShownPerKind) return;
        const Diagnostic &d = k.first;
        std::string msg = d.message.size() > kKindKeyBytes
                              ? d.message.substr(0, kKindKeyBytes) + "..."
                              : d.message;
        lines.push_back(std::to_string(k.count - kWarningsShownPerKind) + " more warnings " + like +
                        (d.loc.file ? d.loc.toString() + ": " : std::string()) + msg);
    };
    for (const auto &k : kinds_) line(k, "like: ");
    line(overflowKind_, "of other kinds, the first: ");
    return lines;
}

std::string readInputFileAt(const std::string &path, const SourceLoc &loc, uint64_t maxBytes) {
    try {
        return readInputFile(path, maxBytes);
    } catch (const InputFileError &e) {
        throw ParseError(loc, e.what());
    }
}

}  // namespace rt
