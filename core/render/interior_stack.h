// SPDX-License-Identifier: MIT
// The solids a ray is inside, innermost last, as POV-Ray's per-ray interior list; it decides
// the relative index of refraction at each surface (docs/design/povray-semantics.md section
// 6.4).
#pragma once

#include <array>

namespace rt {

class Shape;

class InteriorStack {
  public:
    /// POV-Ray's fixed limit is similar; deeper nesting is ignored (counted by the caller).
    static constexpr int kCapacity = 32;

    bool empty() const { return size_ == 0; }
    int size() const { return size_; }
    const Shape *top() const { return size_ ? items_[size_ - 1] : nullptr; }
    bool contains(const Shape *s) const {
        for (int i = 0; i < size_; ++i)
            if (items_[i] == s) return true;
        return false;
    }
    /// False when the stack is full.
    bool push(const Shape *s) {
        if (size_ == kCapacity) return false;
        items_[size_++] = s;
        return true;
    }
    /// Removes s wherever it is; false when absent.
    bool remove(const Shape *s) {
        for (int i = size_ - 1; i >= 0; --i)
            if (items_[i] == s) {
                for (int j = i; j + 1 < size_; ++j) items_[j] = items_[j + 1];
                --size_;
                return true;
            }
        return false;
    }

    InteriorStack() = default;
    /// Copies only the entries in use (usually none or one of the 32): a whole copy is a
    /// `rep movs` of 264 bytes, on every refracted ray.
    InteriorStack(const InteriorStack &o) : size_(o.size_) { copyItems(o); }
    InteriorStack &operator=(const InteriorStack &o) {
        size_ = o.size_;
        copyItems(o);
        return *this;
    }

  private:
    void copyItems(const InteriorStack &o) {
        for (int i = 0; i < size_; ++i) items_[i] = o.items_[i];
    }
    /// Entries from size_ on are never read (and not initialised: zeroing them is what the
    /// copies above save)
    std::array<const Shape *, kCapacity> items_;
    int size_ = 0;
};

}  // namespace rt
