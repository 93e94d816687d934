// SPDX-License-Identifier: MIT
// Temporary files beside their target, and the interrupt handler that removes them.
#include "core/system/temp_file.h"

#include "core/system/input_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace rt {

namespace fs = std::filesystem;

namespace {

/// Longest temporary path an interrupt can remove (longer ones are still removed normally).
constexpr size_t kMaxSlotPath = 4096;

/// Live temporaries, readable from a signal handler: a slot's path is written before the slot
/// is marked used, and the handler reads only used slots.
struct Slot {
    std::atomic<bool> used{false};
    std::atomic<bool> claimed{false};
    char path[kMaxSlotPath] = {};
};
/// Constant-initialised (zero, in .bss): no start-up code touches its 64 KiB
constinit Slot slots[kMaxLiveTempFiles];

int claimSlot(const std::string &path) {
    if (path.size() >= kMaxSlotPath) return -1;
    for (int i = 0; i < kMaxLiveTempFiles; ++i) {
        bool expected = false;
        if (!slots[i].claimed.compare_exchange_strong(expected, true)) continue;
        std::memcpy(slots[i].path, path.c_str(), path.size() + 1);
        slots[i].used.store(true, std::memory_order_release);
        return i;
    }
    return -1;
}

void releaseSlot(int i) {
    if (i < 0) return;
    slots[i].used.store(false, std::memory_order_release);
    slots[i].claimed.store(false, std::memory_order_release);
}

/// Process groups of running children; 0 = free.
constinit std::atomic<int> childGroups[kMaxLiveTempFiles];

extern "C" void removeTempsAndDie(int sig) {
    // Only async-signal-safe calls: kill, unlink, signal, raise
    for (auto &g : childGroups)
        if (int pgid = g.load(std::memory_order_acquire); pgid > 0) ::kill(-pgid, SIGKILL);
    for (auto &s : slots)
        if (s.used.load(std::memory_order_acquire)) ::unlink(s.path);
    std::signal(sig, SIG_DFL);
    std::raise(sig);
}

/// The permissions of a new file under the process's umask (mkstemp creates 0600).
mode_t newFileMode() {
    static const mode_t mode = [] {
        mode_t mask = ::umask(022);
        ::umask(mask);
        return static_cast<mode_t>(0666 & ~mask);
    }();
    return mode;
}

}  // namespace

TempFile::TempFile(const std::string &target, const std::string &suffix) : target_(target) {
    refuseOverwritingInput(target);
    fs::path t(target);
    fs::path dir = t.has_parent_path() ? t.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        throw std::runtime_error("output folder '" + dir.string() + "' does not exist");
    std::string name = (dir / (".scadray-XXXXXX" + suffix)).string();
    std::vector<char> buf(name.begin(), name.end());
    buf.push_back('\0');
    newFileMode();  // read the umask before any temporary exists
    int fd = ::mkstemps(buf.data(), static_cast<int>(suffix.size()));
    if (fd < 0)
        throw std::runtime_error("cannot write '" + target +
                                 "': cannot create a temporary file in '" + dir.string() +
                                 "': " + std::strerror(errno));
    path_ = buf.data();
    slot_ = claimSlot(path_);
    ::fchmod(fd, newFileMode());
    ::close(fd);
}

TempFile::~TempFile() {
    if (!done_) ::unlink(path_.c_str());
    releaseSlot(slot_);
}

void TempFile::commit() {
    std::string problem;
    // Checked again at the end: an input read while this file was written counts too
    try {
        refuseOverwritingInput(target_);
    } catch (const std::runtime_error &e) {
        problem = e.what();
    }
    std::error_code ec;
    if (problem.empty()) fs::rename(path_, target_, ec);
    if (ec) problem = "cannot write '" + target_ + "': " + ec.message();
    if (!problem.empty()) {
        ::unlink(path_.c_str());
        done_ = true;
        releaseSlot(slot_);
        slot_ = -1;
        throw std::runtime_error(problem);
    }
    done_ = true;
    // Released after the rename: an interrupt in between unlinks a name that is gone
    releaseSlot(slot_);
    slot_ = -1;
}

TempDir::TempDir(const std::string &parent) {
    std::string name = (fs::path(parent.empty() ? "." : parent) / ".scadray-XXXXXX").string();
    std::vector<char> buf(name.begin(), name.end());
    buf.push_back('\0');
    if (!::mkdtemp(buf.data()))
        throw std::runtime_error("cannot create a temporary folder in '" + parent +
                                 "': " + std::strerror(errno));
    path_ = buf.data();
}

TempDir::~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
}

ChildGroupGuard::ChildGroupGuard(int pgid) {
    for (int i = 0; i < kMaxLiveTempFiles && slot_ < 0; ++i) {
        int expected = 0;
        if (childGroups[i].compare_exchange_strong(expected, pgid)) slot_ = i;
    }
}

ChildGroupGuard::~ChildGroupGuard() {
    if (slot_ >= 0) childGroups[slot_].store(0, std::memory_order_release);
}

void installInterruptCleanup() {
    newFileMode();
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction old {};
        if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
        struct sigaction sa {};
        sa.sa_handler = removeTempsAndDie;
        sigemptyset(&sa.sa_mask);
        sa.sa_flags = 0;
        ::sigaction(sig, &sa, nullptr);
    }
}

}  // namespace rt
