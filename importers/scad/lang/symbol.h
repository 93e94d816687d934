// SPDX-License-Identifier: MIT
// Interned identifier names: compared and hashed as pointers during evaluation.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

namespace rt::scad {

/// An identifier interned in a process-wide table (names are never freed; a program has few).
class Symbol {
  public:
    Symbol() = default;
    static Symbol intern(std::string_view name);

    bool empty() const { return name_ == nullptr; }
    const std::string &str() const;
    /// `$fn`, `$t`, ...: dynamically scoped. `$children` is not: OpenSCAD 2021.01 scopes it
    /// lexically (context.cc is_config_variable).
    bool isDollar() const { return dollar_; }
    bool operator==(const Symbol &o) const { return name_ == o.name_; }
    bool operator!=(const Symbol &o) const { return name_ != o.name_; }
    size_t hash() const { return std::hash<const void *>()(name_); }

  private:
    Symbol(const std::string *name, bool dollar) : name_(name), dollar_(dollar) {}
    const std::string *name_ = nullptr;
    bool dollar_ = false;
};

struct SymbolHash {
    size_t operator()(const Symbol &s) const { return s.hash(); }
};

}  // namespace rt::scad
