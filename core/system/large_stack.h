// SPDX-License-Identifier: MIT
// Threads with large stacks, for the recursive walks over scene trees (IR checks, CSG compile,
// per-ray CSG evaluation, the SDL writer): a tree is at most ir::kMaxTreeDepth deep, and these
// stacks hold such a tree's walks with room to spare. Only touched pages are committed.
#pragma once

#include <pthread.h>

#include <cstddef>
#include <exception>
#include <functional>
#include <memory>

namespace rt {

/// Stack of the thread a command (or a .scad evaluation) runs on.
constexpr size_t kLargeStackBytes = size_t{512} << 20;
/// Stack of each render worker: per-ray CSG evaluation recurses once per CSG level.
constexpr size_t kWorkerStackBytes = size_t{64} << 20;

/// A thread with a chosen stack size (the default size where that cannot be had), running `fn`
/// once; std::system_error when no thread can be started, as std::thread. join() waits and
/// rethrows what `fn` threw.
class StackThread {
  public:
    StackThread(size_t stackBytes, std::function<void()> fn);
    ~StackThread();  ///< joins, dropping an exception join() did not rethrow
    StackThread(const StackThread &) = delete;
    StackThread &operator=(const StackThread &) = delete;
    void join();

  private:
    struct Task {
        std::function<void()> fn;
        std::exception_ptr error;
    };
    static void *run(void *task);
    std::unique_ptr<Task> task_;
    pthread_t thread_{};
    bool joined_ = false;
};

/// Runs `fn` on a new thread with a `stackBytes` stack, waits, and rethrows what it threw.
void runWithStack(size_t stackBytes, const std::function<void()> &fn);

}  // namespace rt
