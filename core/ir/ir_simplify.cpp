// SPDX-License-Identifier: MIT
// Pruning of empty CSG operands and singular transforms.
#include "core/ir/ir_simplify.h"

#include "core/math/transform.h"

namespace rt::ir {

namespace {

class Pruner {
  public:
    explicit Pruner(DiagnosticSink &diag) : diag_(diag) {}

    /// Prunes below `node` and returns whether it still has volume.
    bool prune(Node &node) {
        switch (node.kind) {
            case NodeKind::Primitive:
                return true;
            case NodeKind::Transform:
                if (!Transform::fromMatrix(node.matrix)) {
                    diag_.warning(node.loc, node.matrix.isFinite()
                                                ? "transform is singular (a zero scale?); what it "
                                                  "holds has no volume and is left out"
                                                : "transform has non-finite entries; what it "
                                                  "holds is left out");
                    return dropAll(node);
                }
                return keepNonEmpty(node);
            case NodeKind::Group:
            case NodeKind::Union:
                return keepNonEmpty(node);
            case NodeKind::Intersection:
                for (auto &c : node.children)
                    if (!prune(*c)) return dropAll(node);  // an empty operand empties it all
                return !node.children.empty();
            case NodeKind::Difference: {
                if (node.children.empty() || !prune(*node.children.front()))
                    return dropAll(node);  // nothing to subtract from
                auto first = std::move(node.children.front());
                node.children.erase(node.children.begin());
                keepNonEmpty(node);
                node.children.insert(node.children.begin(), std::move(first));
                return true;
            }
        }
        return false;
    }

    int removed = 0;

  private:
    bool keepNonEmpty(Node &node) {
        std::vector<NodePtr> kept;
        for (auto &c : node.children) {
            if (prune(*c))
                kept.push_back(std::move(c));
            else
                ++removed;
        }
        node.children = std::move(kept);
        return !node.children.empty();
    }

    bool dropAll(Node &node) {
        removed += static_cast<int>(node.children.size());
        node.children.clear();
        return false;
    }

    DiagnosticSink &diag_;
};

}  // namespace

int pruneEmpty(Scene &scene, DiagnosticSink &diag) {
    Pruner p(diag);
    p.prune(*scene.root);
    return p.removed;
}

}  // namespace rt::ir
