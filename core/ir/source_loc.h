// SPDX-License-Identifier: MIT
// Position in a source file (1-based line and column), carried by every AST and IR node.
#pragma once

#include <memory>
#include <string>

namespace rt {

struct SourceLoc {
    /// Shared so that millions of nodes do not copy the path.
    std::shared_ptr<const std::string> file;
    int line = 0;
    int col = 0;

    SourceLoc() = default;
    SourceLoc(std::shared_ptr<const std::string> f, int l, int c)
        : file(std::move(f)), line(l), col(c) {}

    bool isValid() const { return file && line > 0; }
    const std::string &fileName() const;
    /// "file:line:col", or "<unknown>" when unset.
    std::string toString() const;
};

}  // namespace rt
