// SPDX-License-Identifier: MIT
// Temporary files for atomic writes (write beside the target, then rename), removed when the
// write fails or an interrupt (SIGINT, SIGTERM, SIGHUP) ends the program.
#pragma once

#include <string>

namespace rt {

/// A new, empty temporary file in the folder of `target`, named ".scadray-XXXXXX" plus
/// `suffix` (short whatever the target's name, so any name the file system accepts can be
/// written), with the permissions a new file gets under the umask. While it lives, an
/// interrupt caught by installInterruptCleanup() unlinks it. The destructor removes the file
/// unless commit() renamed it onto the target.
class TempFile {
  public:
    /// Throws std::runtime_error naming `target` when the folder is missing or not writable.
    explicit TempFile(const std::string &target, const std::string &suffix = "");
    ~TempFile();
    TempFile(const TempFile &) = delete;
    TempFile &operator=(const TempFile &) = delete;

    const std::string &path() const { return path_; }
    /// Renames the temporary onto the target; throws std::runtime_error when that fails (the
    /// temporary is then removed).
    void commit();

  private:
    std::string target_, path_;
    int slot_ = -1;
    bool done_ = false;
};

/// A new, empty folder `.scadray-XXXXXX` inside `parent` (mkdtemp: made fresh and private,
/// so nothing in it was put there by anyone else). The destructor removes it with whatever is
/// still in it.
class TempDir {
  public:
    /// Throws std::runtime_error naming `parent` when it is missing or not writable.
    explicit TempDir(const std::string &parent);
    ~TempDir();
    TempDir(const TempDir &) = delete;
    TempDir &operator=(const TempDir &) = delete;

    const std::string &path() const { return path_; }

  private:
    std::string path_;
};

/// While it lives, an interrupt caught by installInterruptCleanup() also kills the process
/// group `pgid` (an external renderer in its own group would otherwise outlive scadray, and
/// the time limit scadray enforces on it).
class ChildGroupGuard {
  public:
    explicit ChildGroupGuard(int pgid);
    ~ChildGroupGuard();
    ChildGroupGuard(const ChildGroupGuard &) = delete;
    ChildGroupGuard &operator=(const ChildGroupGuard &) = delete;

  private:
    int slot_ = -1;
};

/// Installs handlers for SIGINT, SIGTERM and SIGHUP (those not ignored) that unlink every live
/// TempFile, kill every guarded child process group, and then end the program with the signal's
/// default action, so the exit status still says which signal ended it. Call once, early in main().
void installInterruptCleanup();

/// The most temporary files (and child process groups) alive at once that an interrupt
/// removes (more still work; only the first this many are cleaned up by an interrupt).
constexpr int kMaxLiveTempFiles = 16;

}  // namespace rt
