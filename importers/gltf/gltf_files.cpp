// SPDX-License-Identifier: MIT
// What a glTF file may make the importer read: a scan of its JSON text (nesting depth, buffer
// and image URIs with their line and column) before tinygltf parses it, and the filesystem
// callbacks tinygltf reads through, which open nothing outside the model's folder.

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "core/system/input_file.h"
#include "core/system/utf8.h"
#include "importers/gltf/gltf_internal.h"

namespace rt::gltf::detail {

namespace fs = std::filesystem;

namespace {

/// One open container while scanning: its kind, the member key being read (objects) or the
/// element index (arrays).
struct Container {
    bool object = false;
    bool expectKey = true;  ///< objects: the next string is a key
    std::string key;
    size_t index = 0;
    bool hasUri = false;  ///< objects: a "uri" member was seen
};

int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

/// Reads the JSON string starting at text[at] == '"'; returns the index after its closing
/// quote (text.size() when unterminated) and its decoded value in `out`.
size_t readString(std::string_view text, size_t at, std::string &out) {
    out.clear();
    size_t i = at + 1;
    while (i < text.size() && text[i] != '"') {
        char c = text[i];
        if (c != '\\') {
            out += c;
            ++i;
            continue;
        }
        if (i + 1 >= text.size()) return text.size();
        char e = text[i + 1];
        i += 2;
        switch (e) {
            case 'b':
                out += '\b';
                break;
            case 'f':
                out += '\f';
                break;
            case 'n':
                out += '\n';
                break;
            case 'r':
                out += '\r';
                break;
            case 't':
                out += '\t';
                break;
            case 'u': {
                uint32_t cp = 0;
                for (int k = 0; k < 4 && i < text.size(); ++k, ++i) {
                    int h = hexValue(text[i]);
                    cp = cp * 16 + static_cast<uint32_t>(h < 0 ? 0 : h);
                }
                appendUtf8(out, cp);  // surrogate pairs are left as they are (only compared)
                break;
            }
            default:
                out += e;
                break;  // \" \\ \/ and anything invalid, which nlohmann reports
        }
    }
    return i < text.size() ? i + 1 : i;
}

}  // namespace

JsonScan scanJson(std::string_view text) {
    JsonScan scan;
    std::vector<Container> stack;
    int line = 1;
    size_t lineStart = 0;
    std::string value;
    auto column = [&](size_t at) { return static_cast<int>(at - lineStart + 1); };
    for (size_t i = 0; i < text.size();) {
        char c = text[i];
        if (c == '\n') {
            ++line;
            lineStart = ++i;
            continue;
        }
        if (c == '{' || c == '[') {
            if (stack.size() >= kMaxJsonDepth) {
                scan.tooDeep = true;
                scan.deepLine = line;
                scan.deepColumn = column(i);
                return scan;
            }
            Container next;
            next.object = c == '{';
            stack.push_back(next);
            ++i;
            continue;
        }
        if (c == '}' || c == ']') {
            if (!stack.empty()) {
                const Container &closed = stack.back();
                // buffers[i] closes: remember whether it named a uri
                if (closed.object && stack.size() == 3 && stack[0].object &&
                    stack[0].key == "buffers" && !stack[1].object)
                    scan.buffersWithoutUri += closed.hasUri ? 0 : 1;
                stack.pop_back();
            }
            ++i;
            continue;
        }
        if (c == ',') {
            if (!stack.empty()) {
                Container &top = stack.back();
                if (top.object)
                    top.expectKey = true;
                else
                    ++top.index;
            }
            ++i;
            continue;
        }
        if (c == ':') {
            if (!stack.empty()) stack.back().expectKey = false;
            ++i;
            continue;
        }
        if (c == '"') {
            size_t start = i;
            i = readString(text, i, value);
            if (stack.empty()) continue;
            Container &top = stack.back();
            if (top.object && top.expectKey) {
                top.key = value;
                if (value == "uri") top.hasUri = true;
                continue;
            }
            // A string value: a buffer's or an image's uri?
            if (top.object && top.key == "uri" && stack.size() == 3 && stack[0].object &&
                (stack[0].key == "buffers" || stack[0].key == "images") && !stack[1].object) {
                UriRef ref;
                ref.path = jsonPath(stack[0].key.c_str(), stack[1].index) + ".uri";
                ref.uri = value;
                ref.line = line;
                ref.column = column(start);
                scan.uris.push_back(std::move(ref));
            }
            continue;
        }
        // A number: a buffer's byteLength below 1?
        if ((c == '-' || (c >= '0' && c <= '9')) && !scan.emptyBuffer && !stack.empty()) {
            const Container &top = stack.back();
            size_t end = i + 1;
            while (end < text.size() && std::strchr("0123456789+-.eE", text[end]) != nullptr) ++end;
            if (top.object && !top.expectKey && top.key == "byteLength" && stack.size() == 3 &&
                stack[0].object && stack[0].key == "buffers" && !stack[1].object) {
                std::string number(text.substr(i, end - i));
                char *stop = nullptr;
                double v = std::strtod(number.c_str(), &stop);
                if (stop == number.c_str() + number.size() && v < 1) {
                    NumberRef ref;
                    ref.path = jsonPath("buffers", stack[1].index) + ".byteLength";
                    ref.text = number;
                    ref.line = line;
                    ref.column = column(i);
                    scan.emptyBuffer = std::move(ref);
                }
            }
            i = end;
            continue;
        }
        ++i;
    }
    return scan;
}

std::string urlDecode(const std::string &uri) {
    // As tinygltf decodes a URI before opening it: %XX to the byte, '+' to a space
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+') {
            out += ' ';
        } else if (uri[i] == '%' && i + 2 < uri.size()) {
            int hi = hexValue(uri[i + 1]), lo = hexValue(uri[i + 2]);
            out += static_cast<char>(((hi < 0 ? 0 : hi) << 4) | (lo < 0 ? 0 : lo));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

namespace {

/// True when `uri` starts with a scheme ("file:", "http:"): letters, digits, '+', '-', '.'
/// after a first letter, then ':'.
bool hasScheme(const std::string &uri) {
    size_t colon = uri.find(':');
    if (colon == std::string::npos || colon == 0) return false;
    if (!std::isalpha(static_cast<unsigned char>(uri[0]))) return false;
    for (size_t i = 1; i < colon; ++i) {
        unsigned char c = static_cast<unsigned char>(uri[i]);
        if (!std::isalnum(c) && c != '+' && c != '-' && c != '.') return false;
    }
    return true;
}

}  // namespace

ModelFolder::ModelFolder(const std::string &gltfPath) {
    fs::path parent = fs::path(gltfPath).parent_path();
    std::error_code ec;
    folder_ = fs::weakly_canonical(parent.empty() ? fs::path(".") : parent, ec);
    if (ec) folder_ = fs::absolute(parent.empty() ? fs::path(".") : parent, ec);
}

std::string ModelFolder::check(const std::string &path, fs::path *resolved) const {
    if (path.find('\0') != std::string::npos) return "holds a NUL byte";
    if (path.find('\\') != std::string::npos)
        return "holds a backslash (a URI separates folders with '/')";
    std::error_code ec;
    fs::path p(path);
    if (p.is_relative()) p = fs::current_path(ec) / p;
    fs::path canonical = fs::weakly_canonical(p, ec);
    if (ec) return "cannot be resolved: " + ec.message();
    if (!isInsideFolder(canonical, folder_))
        return "lies outside the model's folder " + folder_.string() +
               " (a glTF file may only use files in its own folder or below it, and data: URIs)";
    if (resolved) *resolved = canonical;
    fs::file_status st = fs::status(canonical, ec);
    if (!fs::exists(st)) return "";  // a missing file is tinygltf's to report
    if (!fs::is_regular_file(st)) return "is not a regular file";
    uintmax_t size = fs::file_size(canonical, ec);
    if (ec) return "cannot be read: " + ec.message();
    if (size > kMaxExternalFileBytes)
        return "is " + std::to_string(size) + " bytes, more than the limit of " +
               std::to_string(kMaxExternalFileBytes) + " for one file";
    return "";
}

std::string ModelFolder::checkUri(const std::string &uri) const {
    if (uri.rfind("data:", 0) == 0) return "";
    std::string decoded = urlDecode(uri);
    if (decoded.empty()) return "is empty";
    if (hasScheme(uri) || hasScheme(decoded))
        return "names a scheme (only relative file references and data: URIs are read)";
    if (decoded.front() == '/') return "is an absolute path (only relative references are read)";
    return check((folder_ / decoded).string(), nullptr);
}

namespace {

/// tinygltf looks a URI up under the model's folder, then under the working directory ("./");
/// only the first is a place a glTF file may name.
bool underBaseDir(const FileAccess &files, const std::string &path) {
    if (files.baseDir.empty()) return true;
    std::string prefix = files.baseDir.back() == '/' ? files.baseDir : files.baseDir + "/";
    return path.compare(0, prefix.size(), prefix) == 0;
}

bool fsFileExists(const std::string &path, void *user) {
    auto *files = static_cast<FileAccess *>(user);
    if (!underBaseDir(*files, path)) return false;
    fs::path resolved;
    std::string problem = files->folder.check(path, &resolved);
    if (!problem.empty()) {
        files->refused.push_back("'" + path + "' " + problem);
        return false;
    }
    std::error_code ec;
    return fs::is_regular_file(resolved, ec);
}

std::string fsExpandFilePath(const std::string &path, void *) {
    return path;  // no '~' or variable expansion: the URI is a relative path as it stands
}

bool fsReadWholeFile(std::vector<unsigned char> *out, std::string *err, const std::string &path,
                     void *user) {
    auto *files = static_cast<FileAccess *>(user);
    fs::path resolved;
    std::string problem = underBaseDir(*files, path) ? files->folder.check(path, &resolved)
                                                     : "is not under the model's folder";
    if (!problem.empty()) {
        files->refused.push_back("'" + path + "' " + problem);
        if (err) *err += problem;
        return false;
    }
    // Through the input reader (regular files only, never blocking): examined first for the
    // budget, then read, each open checking again, so a FIFO swapped in between cannot hang it
    std::string refusal, bytes;
    try {
        uint64_t size = checkInputFile(resolved.string(), kMaxExternalFileBytes);
        uint64_t distinct = files->distinctBytes;
        if (!files->sizes.count(resolved.string())) distinct += size;
        uint64_t budget = std::min(kMaxExternalBytes, 2 * distinct + kExternalRereadSlack);
        if (size > budget - std::min(budget, files->bytesRead))
            refusal =
                "is named too often: reading it again would bring the bytes read for this "
                "model to " +
                std::to_string(files->bytesRead + size) +
                ", more than twice the size of the files it names plus " +
                std::to_string(kExternalRereadSlack);
        else
            bytes = readInputFile(resolved.string(), size);
    } catch (const InputFileError &e) {
        refusal = e.reason() == InputFileError::Reason::NotRegular ? "is not a regular file"
                  : e.reason() == InputFileError::Reason::TooLarge
                      ? "is more than the limit of " + std::to_string(kMaxExternalFileBytes) +
                            " bytes for one file"
                      : e.what();
    }
    if (!refusal.empty()) {
        files->refused.push_back("'" + path + "' " + refusal);
        if (err) *err += refusal;
        return false;
    }
    out->assign(bytes.begin(), bytes.end());
    files->bytesRead += bytes.size();
    if (files->sizes.emplace(resolved.string(), bytes.size()).second)
        files->distinctBytes += bytes.size();
    return true;
}

bool fsWriteWholeFile(std::string *err, const std::string &, const std::vector<unsigned char> &,
                      void *) {
    if (err) *err += "the importer writes no files";
    return false;
}

}  // namespace

tinygltf::FsCallbacks FileAccess::callbacks() {
    tinygltf::FsCallbacks cb{};
    cb.FileExists = fsFileExists;
    cb.ExpandFilePath = fsExpandFilePath;
    cb.ReadWholeFile = fsReadWholeFile;
    cb.WriteWholeFile = fsWriteWholeFile;
    cb.user_data = this;
    return cb;
}

}  // namespace rt::gltf::detail
