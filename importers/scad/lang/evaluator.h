// SPDX-License-Identifier: MIT
// Evaluates a parsed OpenSCAD program into an ir::Scene with OpenSCAD 2021.01's scoping.
#pragma once

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "core/ir/diagnostics.h"
#include "core/ir/scene_ir.h"
#include "importers/scad/geometry2d/shape2d.h"
#include "importers/scad/lang/ast.h"
#include "importers/scad/lang/builtin_table.h"
#include "importers/scad/lang/environment.h"
#include "importers/scad/lang/parser.h"
#include "importers/scad/scad_importer.h"

namespace rt::scad {

/// Resource bounds that turn runaway programs into located EvalErrors.
/// The defaults stop a runaway program within about 10 s and a few hundred MB.
struct EvalLimits {
    int maxCallDepth = 10000;  ///< nested user function/module calls (OpenSCAD fails near it)
    /// Calls + loop iterations + instantiations; 0 = no cap. A legitimate model may need more
    /// (scadray --max-steps), so the error names the option.
    int64_t maxSteps = kDefaultMaxSteps;
    int64_t maxLiveElements =
        kDefaultMaxElements;                 ///< vector elements alive at once (~24 bytes each)
    int64_t maxLiveStringBytes = 256 << 20;  ///< bytes of string values alive at once
    int64_t maxNodes = 1'500'000;            ///< IR nodes produced (~300 bytes each)
    /// Deepest node of the scene tree: the root is at depth 1. Later stages walk the tree
    /// recursively (on stacks sized for this depth), so a deeper tree is a located error.
    int maxNodeDepth = ir::kMaxTreeDepth;
    /// Nesting of vector values (`[[[...]]]` built by a loop or tail recursion): freeing,
    /// printing or comparing them recurses that deep.
    int maxValueDepth = 100000;
    size_t maxStringLength = 64u << 20;   ///< bytes in one string value
    size_t stackReserveBytes = 1u << 20;  ///< stack kept free below the deepest frame
    /// Points and faces the geometry operations make or examine (kDefaultMaxGeometry), over
    /// the whole evaluation; 0 = no cap. Each operation charges its estimate, from its
    /// parameters, before doing the work (scadray --max-geometry), so the error names the
    /// option. The fuzz target sets it far lower, so that no input runs long under the
    /// sanitizers.
    int64_t maxGeometryWork = kDefaultMaxGeometry;
};

/// A file taking part in evaluation: the main file or a used library.
struct LoadedFile {
    const SourceFile *src = nullptr;
    std::vector<LoadedFile *> uses;  ///< newest `use` first (later uses win)
    FramePtr frame;                  ///< top-level frame, built on first use
};

/// Appearance requested by color(): outermost valid one wins.
struct ColorState {
    double r = 0, g = 0, b = 0, a = 1;
    SourceLoc loc;
};

/// One material() call's parameters; only what the call gave is marked.
struct MaterialSpec {
    ir::Material material;
    bool hasColor = false;
    double colorAlpha = 1;
    bool hasTransmit = false;
    SourceLoc loc;
};

/// Arguments of a builtin module call bound to its declared parameter names.
struct BoundArgs {
    /// Parameter names, in binding order (string literals of the builtin's table).
    std::vector<std::string_view> names;
    std::vector<Value> values;
    std::vector<SourceLoc> locs;
    std::vector<bool> given;
    SourceLoc callLoc;

    const Value &operator[](size_t i) const { return values[i]; }
    const SourceLoc &loc(size_t i) const { return given[i] ? locs[i] : callLoc; }
};

/// A glTF file's node tree as an import returned it, cloned for later imports.
struct GltfImport {
    ir::NodePtr tree;
    bool fileMaterials = false;  ///< made without a material override
};

/// What instantiation carries down the tree and the builtins share while the scene is built.
struct InstanceState {
    // Appearance and placement while instantiating
    Mat4 worldFromLocal;
    std::optional<ColorState> color;
    std::vector<MaterialSpec> materials;
    int currentMaterial = -1;  ///< material of the current colour/material context, once known
    int backgroundDepth = 0;   ///< inside `%`: left out of the scene
    /// Above 0, warn() prints nothing: a second pass over a subtree (rotate_extrude evaluates
    /// its children's polygons for their extent, then lifts them) warns only once.
    int quiet = 0;
    /// Inside hull(): a singular transform's flat children still give points to the hull.
    int hullDepth = 0;
    bool backgroundSet = false;
    bool renderSettingsSet = false;

    // Files already imported, by canonical path: each is read once and its meshes shared
    std::unordered_map<std::string, int> meshFiles;  ///< STL/OFF path -> index in scene meshes
    std::unordered_map<std::string, GltfImport> gltfFiles;

    std::vector<Shape2d> shapes2d;  ///< 2D shapes, indexed from their placeholder nodes
    bool plateWarned = false;
};

class Evaluator {
  public:
    Evaluator(DiagnosticSink &diag, EvalLimits limits = {});
    ~Evaluator();
    Evaluator(const Evaluator &) = delete;
    Evaluator &operator=(const Evaluator &) = delete;

    /// Evaluates the main file (with the libraries `loader` parsed for it) into a scene.
    ir::Scene evaluate(const SourceFile &main, SourceLoader &loader);

    /// Called with the step count every kProgressStepMask + 1 steps while evaluating.
    void setProgress(std::function<void(int64_t steps)> progress) {
        progress_ = std::move(progress);
    }
    /// The animation time `$t` the builtins start with (0 outside an animation).
    void setTime(double t) { time_ = t; }

    // Services for the builtin modules and functions (importers/scad/builtins). They reach the
    // evaluator only through these.

    // Diagnostics
    DiagnosticSink &diag() { return diag_; }
    void warn(const SourceLoc &loc, const std::string &msg) {
        if (state_.quiet == 0) diag_.warning(loc, msg);
    }
    /// Warns "DEPRECATED: what" once per source line, or once per run when `oncePerRun`.
    void deprecated(const SourceLoc &loc, const std::string &what, bool oncePerRun);

    // Budgets
    const EvalLimits &limits() const { return limits_; }
    Value makeString(std::string s, const SourceLoc &loc);
    /// Throws when a vector of `extra` more elements would exceed the element budget.
    void checkElementBudget(size_t extra, const SourceLoc &loc);
    /// Counts one unit of work (call, iteration, instantiation) against the step budget.
    void step(const SourceLoc &loc) {
        if ((++steps_ & kProgressStepMask) == 0 || steps_ > stepCap_) stepSlow(loc);
    }
    /// Adds `units` (an estimate, made before the work, of the `noun` it makes or examines:
    /// "points", "faces", ...) to the geometry work; beyond EvalLimits::maxGeometryWork a
    /// located error at `loc` naming `what` and the option that raises the budget.
    void chargeGeometryWork(const SourceLoc &loc, const std::string &what, double units,
                            const char *noun = "points");
    /// The geometry work charged so far.
    int64_t geometryWork() const { return geometryWork_; }
    /// Counts `n` IR nodes made outside newNode(); beyond EvalLimits::maxNodes a located error.
    void countNodes(int64_t n, const SourceLoc &loc);

    // Values, arguments and children
    Value eval(const Expr &e, const FramePtr &f);
    /// A variable's value seen from `f`; undef, with a warning unless `silent`, when unknown.
    Value lookupVariable(Symbol name, const Frame *f, const SourceLoc &loc, bool silent = false);
    /// Calls a positional builtin function with `args` evaluated in `f`.
    Value callBuiltinFunction(BuiltinFunction fn, const ArgumentList &args, const FramePtr &f,
                              const SourceLoc &loc);
    /// Binds a builtin's arguments; `$` arguments go into `dollarFrame` when given. Only the
    /// first `positional` parameters can be given without a name.
    BoundArgs bindBuiltin(const ModuleInstantiation &inst,
                          std::initializer_list<std::string_view> params, const FramePtr &argFrame,
                          Frame *dollarFrame, size_t positional = SIZE_MAX);
    /// Evaluates a builtin's child block into `out` in a fresh frame under `caller`.
    void instantiateChildren(const ModuleInstantiation &inst, const FramePtr &caller,
                             std::vector<ir::NodePtr> &out, const Scope *scope = nullptr);
    /// The dynamic scope of `$` variables: a FrameGuard on it makes a builtin's `$` arguments
    /// visible to its children.
    DynamicStack &dynamicScope() { return dyn_; }
    /// $fn/$fa/$fs of the dynamic scope, clamped (with OpenSCAD's warnings) as primitives use them.
    ir::Fragments currentFragments(const SourceLoc &loc);
    uint64_t randomSeed() { return ++randomCounter_; }
    /// The user module names on the call stack, innermost last (parent_module()).
    const std::vector<Symbol> &moduleStack() const { return moduleStack_; }

    // The scene being built
    ir::NodePtr newNode(ir::NodeKind kind, const SourceLoc &loc);
    ir::NodePtr groupOf(ir::NodeKind kind, const SourceLoc &loc, std::vector<ir::NodePtr> children);
    ir::Scene &scene() { return scene_; }
    InstanceState &state() { return state_; }
    /// The main file, and its top-level frame once evaluation has started.
    const SourceFile &mainFile() const { return *mainFile_.src; }
    const Frame &mainFrame() const { return *mainFile_.frame; }
    bool hasMainFile() const { return mainFile_.src != nullptr; }

  private:
    using ModuleHandler = ir::NodePtr (Evaluator::*)(const ModuleInstantiation &, const FramePtr &);

    struct CallTarget {
        const ParameterList *params = nullptr;
        const Expr *body = nullptr;
        FramePtr parent;                ///< defining (or closure) frame
        LoadedFile *library = nullptr;  ///< set when defined by a used library
        Symbol name;
    };
    struct ModuleLookup {
        const ModuleDef *def = nullptr;
        FramePtr parent;
        LoadedFile *library = nullptr;
    };

    // Expressions (evaluator.cpp)
    Value evalUnchecked(const Expr &e, const FramePtr &f);
    Value evalVector(const VectorExpr &v, const FramePtr &f);
    void evalElement(const Expr &e, const FramePtr &f, std::vector<Value> &out);
    Value evalRange(const RangeExpr &r, const FramePtr &f);
    Value evalIndex(const IndexExpr &e, const FramePtr &f);
    Value evalMember(const MemberExpr &e, const FramePtr &f);
    Value evalCall(const CallExpr &c, const FramePtr &f);
    Value evalPrefix(const PrefixExpr &p, const FramePtr &f);
    void evalEcho(const ArgumentList &args, const FramePtr &f, const SourceLoc &loc);
    void evalAssert(const ArgumentList &args, const FramePtr &f, const SourceLoc &loc);
    void bindLet(const ArgumentList &args, const FramePtr &c);
    std::optional<CallTarget> resolveFunction(const Expr &callee, const FramePtr &f,
                                              Value *calleeValue);
    Value callUser(CallTarget target, const ArgumentList &args, const FramePtr &argFrame,
                   const SourceLoc &loc);
    void bindParameters(const ParameterList &params, const ArgumentList &args,
                        const FramePtr &argFrame, Frame &into, const FramePtr &defaultsFrame,
                        const SourceLoc &callLoc);
    void checkStack(const SourceLoc &loc);
    /// Throws at the first node deeper than limits_.maxNodeDepth.
    void checkNodeDepth(const ir::Node &root) const;
    void stepSlow(const SourceLoc &loc);
    static constexpr int64_t kProgressStepMask = (1 << 16) - 1;

    // Scopes and module instantiation (evaluator.cpp)
    void applyAssignments(const std::vector<Assignment> &as, const FramePtr &f);
    void instantiateScope(const Scope &s, const FramePtr &f, std::vector<ir::NodePtr> &out);
    ir::NodePtr instantiate(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr instantiateUnmodified(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr instantiateUnchecked(const ModuleInstantiation &inst, const FramePtr &f);
    std::optional<ModuleLookup> findModule(Symbol name, const Frame *f);
    FramePtr libraryFrame(LoadedFile &lib);
    ir::NodePtr instantiateUser(const ModuleLookup &m, const ModuleInstantiation &inst,
                                const FramePtr &caller);
    ir::NodePtr childrenGroupOrNull(const ModuleInstantiation &inst, const FramePtr &f);

    // Control modules (evaluator.cpp)
    ir::NodePtr moduleIf(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleFor(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleIntersectionFor(const ModuleInstantiation &inst, const FramePtr &f);
    void forLoop(const ModuleInstantiation &inst, size_t var, const FramePtr &f,
                 std::vector<ir::NodePtr> &out, bool groupPerIteration);
    ir::NodePtr moduleLet(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleEcho(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleAssert(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleChildren(const ModuleInstantiation &inst, const FramePtr &f);
    // Deprecated 2021.01 modules, still working there
    ir::NodePtr moduleAssign(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleChild(const ModuleInstantiation &inst, const FramePtr &f);
    /// The control modules of the language (for, let, echo, children, ...), by name.
    static const std::unordered_map<Symbol, ModuleHandler, SymbolHash> &controlModules();

    DiagnosticSink &diag_;
    EvalLimits limits_;
    ir::Scene scene_;
    DynamicStack dyn_;
    FramePtr builtinFrame_;
    LoadedFile mainFile_;
    std::unordered_map<const SourceFile *, LoadedFile> libraries_;
    std::vector<Symbol> moduleStack_;

    const BuiltinTable &builtins_;
    InstanceState state_;

    // `!` root modifier
    ir::NodePtr rootNode_;
    bool rootSeen_ = false;

    /// Frames captured by function literals; a closure stored in a frame it (indirectly)
    /// captures forms a reference cycle, broken when the evaluator goes away.
    std::vector<std::weak_ptr<Frame>> capturedFrames_;

    std::unordered_set<std::string> deprecationsShown_;

    int callDepth_ = 0;
    int64_t steps_ = 0;
    int64_t stepCap_;  ///< limits_.maxSteps, or the largest count when there is no cap
    std::function<void(int64_t)> progress_;
    double time_ = 0;
    int64_t nodes_ = 0;
    int64_t geometryWork_ = 0;

    uint64_t randomCounter_ = 0;
    const char *stackLow_ = nullptr;
};

}  // namespace rt::scad
