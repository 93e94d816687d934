// SPDX-License-Identifier: MIT
// Process-wide identifier interning, safe for concurrent imports.
#include "importers/scad/lang/symbol.h"

#include <memory>
#include <mutex>
#include <unordered_map>

namespace rt::scad {

Symbol Symbol::intern(std::string_view name) {
    static std::mutex mutex;
    static std::unordered_map<std::string_view, std::unique_ptr<std::string>> table;
    std::lock_guard lock(mutex);
    auto it = table.find(name);
    if (it == table.end()) {
        auto owned = std::make_unique<std::string>(name);
        std::string_view key(*owned);
        it = table.emplace(key, std::move(owned)).first;
    }
    const std::string *p = it->second.get();
    return Symbol(p, !p->empty() && (*p)[0] == '$' && *p != "$children");
}

const std::string &Symbol::str() const {
    static const std::string kEmpty;
    return name_ ? *name_ : kEmpty;
}

}  // namespace rt::scad
