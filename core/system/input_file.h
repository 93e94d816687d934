// SPDX-License-Identifier: MIT
// The one way scadray opens a file on behalf of an input (a scene, a library, an image, a
// report's pictures): regular files only, never blocking, never past a size cap.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace rt {

/// Why a file named by an input cannot be read. The message names the file (control
/// characters escaped) and the reason; callers add a location where they have one.
class InputFileError : public std::runtime_error {
  public:
    enum class Reason {
        Missing,     ///< nothing of that name (readers that warn and go on, as OpenSCAD does)
        NotRegular,  ///< a FIFO, device, socket or folder
        TooLarge,    ///< past the reader's size cap
        Unreadable,  ///< permissions, I/O errors
    };
    InputFileError(Reason reason, const std::string &message)
        : std::runtime_error(message), reason_(reason) {}
    Reason reason() const { return reason_; }

  private:
    Reason reason_;
};

/// Reads the whole of `path`, which must be a regular file (or a link to one) of at most
/// `maxBytes`. A FIFO, device, socket or folder is refused without blocking or reading from it:
/// the file is opened non-blocking and the open descriptor is examined, so nothing can swap the
/// file between the check and the read. A file growing while it is read is cut at the size it
/// had when opened. Throws InputFileError.
std::string readInputFile(const std::string &path, uint64_t maxBytes);

/// The checks of readInputFile without reading, for libraries that open a file by name
/// (OpenImageIO, FreeType). Returns the file's size. Throws InputFileError.
uint64_t checkInputFile(const std::string &path, uint64_t maxBytes);

/// True when `inner` lies in `folder` or below it, both already canonical (symbolic links
/// resolved, as std::filesystem::weakly_canonical makes them).
bool isInsideFolder(const std::filesystem::path &inner, const std::filesystem::path &folder);

/// readInputFile of `name` inside `folder`, as a file that names its companions may read them
/// (a check's figures their pictures): `name` resolved with its links must lie in `folder` or
/// below it, so neither an absolute path, `..` nor a link leads out. Throws InputFileError
/// (NotRegular for one that leads out).
std::string readInputFileIn(const std::string &folder, const std::string &name, uint64_t maxBytes);

/// Remembers `path` (its device, inode and change time; nothing when it cannot be examined) as a
/// file this run reads, so that no output of the same run replaces it. readInputFile and
/// checkInputFile do it themselves; readers that open files another way call it. Thread-safe.
void noteInputFile(const std::string &path);

/// Throws std::runtime_error when `target` is (by device, inode and change time, so any other
/// name or link to it counts too) a file this run has read as input: an output never replaces an
/// input
/// (`compare a.png b.png --heat-map a.png`, `check -o` into a model's own folder).
void refuseOverwritingInput(const std::string &target);

/// Forgets every file noted so far. The notes hold for one process's run of a command; a
/// program that runs several commands in one process (a library user, a test) calls this
/// between them, since the inode of a deleted input may be reused by a new file.
void forgetInputFiles();

/// `text` safe to print on a terminal: control characters (C0 but tab, DEL, and C1 as their
/// UTF-8 encoding), which could clear the screen, set a window title or recolour it, become
/// `\xNN`; newlines are kept when `keepNewlines`, else escaped too. Other bytes pass unchanged.
std::string printable(const std::string &text, bool keepNewlines = false);

/// Throws std::runtime_error naming `path` unless it is a regular file (or a link to one):
/// a folder, a FIFO, a device such as /dev/zero or a socket could block or never end.
void requireRegularFile(const std::string &path);

}  // namespace rt
