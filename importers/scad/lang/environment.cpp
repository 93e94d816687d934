// SPDX-License-Identifier: MIT
// Frame variable storage and the dynamic `$` variable lookup.
#include "importers/scad/lang/environment.h"

namespace rt::scad {

const Value *Frame::findLocal(Symbol name) const {
    if (index_) {
        auto it = index_->find(name);
        return it == index_->end() ? nullptr : &vars_[it->second].second;
    }
    for (const auto &[n, v] : vars_)
        if (n == name) return &v;
    return nullptr;
}

void Frame::set(Symbol name, Value v) {
    if (index_) {
        auto it = index_->find(name);
        if (it != index_->end()) {
            vars_[it->second].second = std::move(v);
            return;
        }
    } else {
        for (auto &[n, old] : vars_)
            if (n == name) {
                old = std::move(v);
                return;
            }
    }
    vars_.emplace_back(name, std::move(v));
    if (stack_ && name.isDollar()) stack_->bind(name, stackIndex_);
    if (index_) {
        index_->emplace(name, vars_.size() - 1);
    } else if (vars_.size() > kIndexThreshold) {
        index_ = std::make_unique<std::unordered_map<Symbol, size_t, SymbolHash>>();
        for (size_t i = 0; i < vars_.size(); ++i) index_->emplace(vars_[i].first, i);
    }
}

void DynamicStack::push(Frame *f) {
    size_t index = frames_.size();
    frames_.push_back(f);
    f->stack_ = this;
    f->stackIndex_ = index;
    ++f->pushCount_;
    for (const auto &[name, v] : f->vars_)
        if (name.isDollar()) bindings_[name].push_back(index);
}

void DynamicStack::pop() {
    Frame *f = frames_.back();
    size_t index = frames_.size() - 1;
    for (const auto &[name, v] : f->vars_) {
        if (!name.isDollar()) continue;
        auto &positions = bindings_[name];
        if (!positions.empty() && positions.back() == index) positions.pop_back();
    }
    frames_.pop_back();
    if (--f->pushCount_ == 0) {
        f->stack_ = nullptr;
    } else if (f->stackIndex_ == index) {
        // A frame pushed twice (a library's top level) keeps its lower position
        for (size_t i = index; i-- > 0;)
            if (frames_[i] == f) {
                f->stackIndex_ = i;
                break;
            }
    }
}

void DynamicStack::bind(Symbol name, size_t index) {
    // Usually the top frame; keep the positions sorted otherwise
    auto &positions = bindings_[name];
    positions.insert(std::upper_bound(positions.begin(), positions.end(), index), index);
}

const Value *DynamicStack::lookup(Symbol name) const {
    auto it = bindings_.find(name);
    if (it == bindings_.end() || it->second.empty()) return nullptr;
    return frames_[it->second.back()]->findLocal(name);
}

}  // namespace rt::scad
