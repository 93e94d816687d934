// SPDX-License-Identifier: MIT
// Evaluation frames (OpenSCAD contexts): lexical variable scopes, and the dynamic stack that
// `$` variables are looked up in.
#pragma once

#include <algorithm>
#include <memory>
#include <unordered_map>
#include <utility>
#include <vector>

#include "importers/scad/lang/ast.h"
#include "importers/scad/lang/value.h"

namespace rt::scad {

struct LoadedFile;
struct Frame;
using FramePtr = std::shared_ptr<Frame>;

/// What `children()` inside a user module body refers to: the call's child statements and
/// the frame they are evaluated in (the caller's side, with the child block's assignments).
struct ModuleCallInfo {
    const ModuleInstantiation *inst = nullptr;
    FramePtr childFrame;
};

class DynamicStack;

/// One scope of variables. `parent` is the lexical parent; definitions (`defs`) and used
/// libraries (`file`) are searched along the same chain.
struct Frame : std::enable_shared_from_this<Frame> {
    FramePtr parent;
    const Scope *defs = nullptr;           ///< module/function definitions visible here
    LoadedFile *file = nullptr;            ///< set on a file's top-level frame
    const ModuleCallInfo *call = nullptr;  ///< set on a user module's body frame

    explicit Frame(FramePtr p) : parent(std::move(p)) {}
    const Value *findLocal(Symbol name) const;
    void set(Symbol name, Value v);
    size_t size() const { return vars_.size(); }
    const std::vector<std::pair<Symbol, Value>> &vars() const { return vars_; }
    /// Drops every variable (breaking closure reference cycles once evaluation is over).
    void clear() {
        vars_.clear();
        index_.reset();
    }

  private:
    friend class DynamicStack;
    /// Linear search is fastest for the few variables most frames hold; large frames (a
    /// library's top level) get a hash index.
    static constexpr size_t kIndexThreshold = 12;
    std::vector<std::pair<Symbol, Value>> vars_;
    std::unique_ptr<std::unordered_map<Symbol, size_t, SymbolHash>> index_;
    DynamicStack *stack_ = nullptr;  ///< set while the frame is on a dynamic stack
    size_t stackIndex_ = 0;
    int pushCount_ = 0;
};

inline FramePtr makeFrame(const FramePtr &parent) { return std::make_shared<Frame>(parent); }

/// Frames alive in evaluation order; `$name` resolves to the newest frame defining it
/// (OpenSCAD's ctx_stack), regardless of lexical nesting. Each `$` name keeps the stack
/// positions that bind it (shallow binding), so a lookup does not walk deep recursions.
class DynamicStack {
  public:
    void push(Frame *f);
    void pop();
    const Value *lookup(Symbol name) const;
    size_t depth() const { return frames_.size(); }

  private:
    friend struct Frame;
    void bind(Symbol name, size_t index);
    std::vector<Frame *> frames_;
    std::unordered_map<Symbol, std::vector<size_t>, SymbolHash> bindings_;
};

/// Keeps a frame on the dynamic stack for the lifetime of the guard.
class FrameGuard {
  public:
    FrameGuard(DynamicStack &s, Frame *f) : stack_(s) { stack_.push(f); }
    ~FrameGuard() { stack_.pop(); }
    FrameGuard(const FrameGuard &) = delete;
    FrameGuard &operator=(const FrameGuard &) = delete;

  private:
    DynamicStack &stack_;
};

}  // namespace rt::scad
