// SPDX-License-Identifier: MIT
// Regular-file reading with a size cap, and terminal-safe text.
#include "core/system/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <mutex>
#include <set>
#include <stdexcept>
#include <tuple>

namespace rt {

namespace {

/// Every file read as input in this run, by device, inode and change time: the change time
/// tells a file apart from a new one that got the inode of a deleted one.
struct InputRegistry {
    std::mutex mutex;
    std::set<std::tuple<dev_t, ino_t, time_t, long>> files;
};

std::tuple<dev_t, ino_t, time_t, long> fileKey(const struct stat &st) {
    return {st.st_dev, st.st_ino, st.st_ctim.tv_sec, st.st_ctim.tv_nsec};
}

InputRegistry &inputRegistry() {
    static InputRegistry registry;
    return registry;
}

void noteInput(const struct stat &st) {
    InputRegistry &r = inputRegistry();
    std::lock_guard<std::mutex> lock(r.mutex);
    r.files.insert(fileKey(st));
}

/// Closes a descriptor however the function using it ends.
struct FdCloser {
    int fd;
    ~FdCloser() {
        if (fd >= 0) ::close(fd);
    }
};

/// The opened descriptor of `path`, checked to be a regular file of at most `maxBytes`.
int openChecked(const std::string &path, uint64_t maxBytes, uint64_t &size) {
    std::string name = "'" + printable(path) + "'";
    using Reason = InputFileError::Reason;
    if (path.empty()) throw InputFileError(Reason::Missing, "an empty file name was given");
    // Non-blocking, so that opening a FIFO without a writer returns at once; fstat of the open
    // descriptor then decides what it is. O_NOCTTY: a terminal device never becomes ours.
    int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        int err = errno;
        throw InputFileError(err == ENOENT ? Reason::Missing : Reason::Unreadable,
                             "can't open file " + name + ": " +
                                 (err == ENOENT ? "no such file" : std::strerror(err)));
    }
    FdCloser guard{fd};
    struct stat st {};
    if (::fstat(fd, &st) != 0)
        throw InputFileError(Reason::Unreadable,
                             "can't read " + name + ": " + std::strerror(errno));
    if (!S_ISREG(st.st_mode))
        throw InputFileError(
            Reason::NotRegular,
            "can't read " + name + ": not a regular file (" +
                (S_ISDIR(st.st_mode) ? "a directory" : "a FIFO, device or socket") + ")");
    size = static_cast<uint64_t>(st.st_size);
    if (size > maxBytes)
        throw InputFileError(Reason::TooLarge, name + " is too large: " + std::to_string(size) +
                                                   " bytes, more than the limit of " +
                                                   std::to_string(maxBytes));
    noteInput(st);
    guard.fd = -1;
    return fd;
}

}  // namespace

std::string readInputFile(const std::string &path, uint64_t maxBytes) {
    uint64_t size = 0;
    FdCloser fd{openChecked(path, maxBytes, size)};
    std::string data(static_cast<size_t>(size), '\0');
    size_t got = 0;
    while (got < data.size()) {
        ssize_t n = ::read(fd.fd, data.data() + got, data.size() - got);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0)
            throw InputFileError(InputFileError::Reason::Unreadable,
                                 "can't read '" + printable(path) + "': " + std::strerror(errno));
        if (n == 0) break;
        got += static_cast<size_t>(n);
    }
    data.resize(got);
    return data;
}

uint64_t checkInputFile(const std::string &path, uint64_t maxBytes) {
    uint64_t size = 0;
    FdCloser fd{openChecked(path, maxBytes, size)};
    return size;
}

bool isInsideFolder(const std::filesystem::path &inner, const std::filesystem::path &folder) {
    auto f = folder.begin(), i = inner.begin();
    for (; f != folder.end(); ++f, ++i) {
        if (f->empty()) continue;  // a trailing separator
        if (i == inner.end() || *i != *f) return false;
    }
    return true;
}

std::string readInputFileIn(const std::string &folder, const std::string &name, uint64_t maxBytes) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path base = fs::weakly_canonical(folder.empty() ? fs::path(".") : fs::path(folder), ec);
    fs::path file = ec ? fs::path() : fs::weakly_canonical(base / name, ec);
    if (ec || name.empty() || name.find('\0') != std::string::npos || !isInsideFolder(file, base))
        throw InputFileError(InputFileError::Reason::NotRegular,
                             "refusing to read '" + printable(name) + "': it lies outside '" +
                                 printable(folder) + "' (links resolved)");
    return readInputFile(file.string(), maxBytes);
}

void noteInputFile(const std::string &path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) noteInput(st);
}

void refuseOverwritingInput(const std::string &target) {
    struct stat st {};
    if (::stat(target.c_str(), &st) != 0) return;
    InputRegistry &r = inputRegistry();
    std::lock_guard<std::mutex> lock(r.mutex);
    if (r.files.count(fileKey(st)))
        throw std::runtime_error("refusing to write '" + printable(target) +
                                 "': it is a file this command reads; choose another output");
}

void forgetInputFiles() {
    InputRegistry &r = inputRegistry();
    std::lock_guard<std::mutex> lock(r.mutex);
    r.files.clear();
}

std::string printable(const std::string &text, bool keepNewlines) {
    static const char kHex[] = "0123456789abcdef";
    auto escape = [](std::string &out, unsigned char c) {
        out += "\\x";
        out += kHex[c >> 4];
        out += kHex[c & 15];
    };
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size(); ++i) {
        auto c = static_cast<unsigned char>(text[i]);
        if (c == '\n' && keepNewlines) {
            out += '\n';
        } else if ((c < 0x20 && c != '\t') || c == 0x7f) {
            escape(out, c);
        } else if (c == 0xc2 && i + 1 < text.size() &&
                   static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
                   static_cast<unsigned char>(text[i + 1]) <= 0x9f) {
            // A C1 control (U+0080..U+009F) in UTF-8: CSI (U+009B) starts escape sequences too
            escape(out, c);
            escape(out, static_cast<unsigned char>(text[++i]));
        } else {
            out += static_cast<char>(c);
        }
    }
    return out;
}

void requireRegularFile(const std::string &path) {
    if (path.empty()) throw std::invalid_argument("an empty file name was given");
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0)
        throw std::runtime_error(path + ": " +
                                 (errno == ENOENT ? "no such file" : std::strerror(errno)));
    if (S_ISDIR(st.st_mode)) throw std::runtime_error(path + ": is a folder, not a file");
    if (!S_ISREG(st.st_mode))
        throw std::runtime_error(path +
                                 ": is not a regular file (a FIFO, device or socket); "
                                 "scadray reads only regular files");
    // No output of this run may replace it
    noteInputFile(path);
}

}  // namespace rt
