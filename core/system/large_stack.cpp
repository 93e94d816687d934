// SPDX-License-Identifier: MIT
#include "core/system/large_stack.h"

namespace rt {

StackThread::StackThread(size_t stackBytes, std::function<void()> fn)
    : task_(std::make_unique<Task>(Task{std::move(fn), nullptr})) {
    pthread_attr_t attr;
    if (pthread_attr_init(&attr) != 0) return;
    started_ = pthread_attr_setstacksize(&attr, stackBytes) == 0 &&
               pthread_create(&thread_, &attr, &StackThread::run, task_.get()) == 0;
    pthread_attr_destroy(&attr);
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
    if (started_) pthread_join(thread_, nullptr);
    else run(task_.get());
    if (task_->error) std::rethrow_exception(task_->error);
}

void runWithStack(size_t stackBytes, const std::function<void()> &fn) {
    StackThread(stackBytes, fn).join();
}

}  // namespace rt
