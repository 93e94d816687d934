// SPDX-License-Identifier: MIT
#include "core/system/large_stack.h"

#include <system_error>

namespace rt {

StackThread::StackThread(size_t stackBytes, std::function<void()> fn)
    : task_(std::make_unique<Task>(Task{std::move(fn), nullptr})) {
    bool started = false;
    pthread_attr_t attr;
    if (pthread_attr_init(&attr) == 0) {
        started = pthread_attr_setstacksize(&attr, stackBytes) == 0 &&
                  pthread_create(&thread_, &attr, &StackThread::run, task_.get()) == 0;
        pthread_attr_destroy(&attr);
    }
    // Without the large stack, a thread with the default one; without any thread, an error as
    // std::thread gives (running `fn` later in join() would stall callers that wait for it)
    if (!started) {
        int rc = pthread_create(&thread_, nullptr, &StackThread::run, task_.get());
        if (rc != 0) throw std::system_error(rc, std::generic_category(), "cannot start a thread");
    }
}

StackThread::~StackThread() {
    try {
        join();
    } catch (...) {
    }
}

void *StackThread::run(void *p) {
    auto *t = static_cast<Task *>(p);
    try {
        t->fn();
    } catch (...) {
        t->error = std::current_exception();
    }
    return nullptr;
}

void StackThread::join() {
    if (joined_) return;
    joined_ = true;
    pthread_join(thread_, nullptr);
    if (task_->error) std::rethrow_exception(task_->error);
}

void runWithStack(size_t stackBytes, const std::function<void()> &fn) {
    StackThread(stackBytes, fn).join();
}

}  // namespace rt
