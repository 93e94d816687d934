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
#include "importers/scad/ast.h"
#include "importers/scad/clipper2d.h"
#include "importers/scad/environment.h"
#include "importers/scad/parser.h"
#include "importers/scad/scad_importer.h"
#include "importers/scad/revolve.h"
#include "importers/scad/shape2d.h"

namespace rt::scad {

/// Resource bounds that turn runaway programs into located EvalErrors.
/// The defaults stop a runaway program within about 10 s and a few hundred MB.
struct EvalLimits {
    int maxCallDepth = 10000;  ///< nested user function/module calls (OpenSCAD fails near it)
    /// Calls + loop iterations + instantiations; 0 = no cap. A legitimate model may need more
    /// (scadray --max-steps), so the error names the option.
    int64_t maxSteps = kDefaultMaxSteps;
    int64_t maxLiveElements = kDefaultMaxElements;  ///< vector elements alive at once (~24 bytes each)
    int64_t maxLiveStringBytes = 256 << 20;  ///< bytes of string values alive at once
    int64_t maxNodes = 1'500'000;            ///< IR nodes produced (~300 bytes each)
    /// Deepest node of the scene tree: the root is at depth 1. Later stages walk the tree
    /// recursively (on stacks sized for this depth), so a deeper tree is a located error.
    int maxNodeDepth = ir::kMaxTreeDepth;
    /// Nesting of vector values (`[[[...]]]` built by a loop or tail recursion): freeing,
    /// printing or comparing them recurses that deep.
    int maxValueDepth = 100000;
    size_t maxStringLength = 64u << 20;      ///< bytes in one string value
    size_t stackReserveBytes = 1u << 20;     ///< stack kept free below the deepest frame
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

/// A resolved linear_extrude (or the plate OpenSCAD's preview draws for a top-level 2D object).
struct ExtrudeSpec {
    double z0 = 0, z1 = 1;
    Vec2 scale{1, 1};
    double twist = 0;
    int slices = 1;               ///< the mesh path's slice count, once known
    int sliceArg = 0;             ///< `slices` as given (0: computed)
    ir::Fragments fragments;      ///< $fn/$fa/$fs at the call, for the slice count
    int material = -1;            ///< -1: each 2D primitive keeps its own material
    bool previewTransforms = false;  ///< plates: transforms act in 3D, as in the preview
    bool meshPath = false;        ///< twist or non-uniform scale: swept triangle meshes
    /// linear_extrude's group of children: OpenSCAD unions them without its mixing warning
    /// (applyToChildren2D), only ignoring 3D ones
    const ir::Node *silentUnion = nullptr;
    SourceLoc loc;
};

/// A resolved rotate_extrude: the sweep every lifted leaf takes.
struct RevolveSpec {
    double angle = 360;           ///< |angle| in (0, 360], counter-clockwise from +X
    int segments = 1;             ///< OpenSCAD's segment count over the angle
    ir::Fragments fragments;      ///< $fn/$fa/$fs at the call
    int material = -1;            ///< -1: each 2D primitive keeps its own material
    const ir::Node *silentUnion = nullptr;  ///< the call's group of children
    SourceLoc loc;
};

/// OpenSCAD's Value::getVec2: exactly two numbers (builtins_2d.cpp).
bool getVec2(const Value &v, double &x, double &y);

/// Where and how a DXF file is read (import(), the file forms of the extrusions).
struct Dxf2dArgs {
    std::string layer;  ///< empty: all layers
    double originX = 0, originY = 0, scale = 1;
};

class Evaluator;
using BuiltinFunction = Value (*)(Evaluator &, const std::vector<Value> &args,
                                  const SourceLoc &loc);

class Evaluator {
  public:
    Evaluator(DiagnosticSink &diag, EvalLimits limits = {});
    ~Evaluator();
    Evaluator(const Evaluator &) = delete;
    Evaluator &operator=(const Evaluator &) = delete;

    /// Evaluates the main file (with the libraries `loader` parsed for it) into a scene.
    ir::Scene evaluate(const SourceFile &main, SourceLoader &loader);

    // Services used by the builtin function and module implementations
    DiagnosticSink &diag() { return diag_; }
    const EvalLimits &limits() const { return limits_; }
    void warn(const SourceLoc &loc, const std::string &msg) {
        if (quiet_ == 0) diag_.warning(loc, msg);
    }
    Value makeString(std::string s, const SourceLoc &loc);
    /// Throws when a vector of `extra` more elements would exceed the element budget.
    void checkElementBudget(size_t extra, const SourceLoc &loc);
    /// Counts one unit of work (call, iteration, instantiation) against the step budget.
    void step(const SourceLoc &loc) {
        if ((++steps_ & kProgressStepMask) == 0 || steps_ > stepCap_) stepSlow(loc);
    }
    /// Called with the step count every kProgressStepMask + 1 steps while evaluating.
    void setProgress(std::function<void(int64_t steps)> progress) {
        progress_ = std::move(progress);
    }
    /// The animation time `$t` the builtins start with (0 outside an animation).
    void setTime(double t) { time_ = t; }
    uint64_t randomSeed() { return ++randomCounter_; }

    /// The user module names on the call stack, innermost last (parent_module()).
    const std::vector<Symbol> &moduleStack() const { return moduleStack_; }

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
    Value eval(const Expr &e, const FramePtr &f);
    Value evalUnchecked(const Expr &e, const FramePtr &f);
    Value lookupVariable(Symbol name, const Frame *f, const SourceLoc &loc, bool silent = false);
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
    Value callBuiltinFunction(BuiltinFunction fn, const ArgumentList &args, const FramePtr &f,
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
    /// Binds a builtin's arguments; `$` arguments go into `dollarFrame` when given. Only the
    /// first `positional` parameters can be given without a name.
    BoundArgs bindBuiltin(const ModuleInstantiation &inst,
                          std::initializer_list<std::string_view> params, const FramePtr &argFrame,
                          Frame *dollarFrame, size_t positional = SIZE_MAX);
    /// Evaluates a builtin's child block into `out` in a fresh frame under `caller`.
    void instantiateChildren(const ModuleInstantiation &inst, const FramePtr &caller,
                             std::vector<ir::NodePtr> &out, const Scope *scope = nullptr);
    ir::NodePtr newNode(ir::NodeKind kind, const SourceLoc &loc);
    ir::NodePtr childrenGroupOrNull(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr groupOf(ir::NodeKind kind, const SourceLoc &loc, std::vector<ir::NodePtr> children);

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
    /// Warns "DEPRECATED: what" once per source line, or once per run when `oncePerRun`.
    void deprecated(const SourceLoc &loc, const std::string &what, bool oncePerRun);

    // Geometry builtins (builtins_geometry.cpp)
    ir::NodePtr moduleCube(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleSphere(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleCylinder(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleTranslate(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleRotate(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleScale(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleMirror(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleMultmatrix(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleColor(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleUnion(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleDifference(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleIntersection(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleGroup(const ModuleInstantiation &inst, const FramePtr &f);
    /// hull(): the convex hull of the points OpenSCAD generates for the children, as one
    /// polytope primitive.
    ir::NodePtr moduleHull(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleUnsupported(const ModuleInstantiation &inst, const FramePtr &f);
    /// The children of hull() or minkowski(), a source of points only: a singular transform
    /// inside still gives its flat points, as in OpenSCAD.
    ir::NodePtr pointSourceChildren(const ModuleInstantiation &inst, const FramePtr &f);
    /// An empty group for a feature not supported yet, with a warning (none inside `%`).
    ir::NodePtr skipUnsupported(const SourceLoc &loc, const std::string &what);
    ir::NodePtr csgOperation(ir::NodeKind kind, const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr transformNode(const Mat4 &m, const ModuleInstantiation &inst, const FramePtr &f,
                              const FramePtr &argFrame);
    ir::NodePtr primitive(ir::PrimShape shape, const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr emptyPrimitive(const ModuleInstantiation &inst, const std::string &why);
    ir::Fragments currentFragments(const SourceLoc &loc);
    /// sphere()/circle() radius from `r` and `d` (bound first and second): a numeric d wins,
    /// with OpenSCAD's warning when r is given too; undef when neither is a number.
    Value radiusArgument(const BoundArgs &a, const ModuleInstantiation &inst);
    void warnLeafChildren(const ModuleInstantiation &inst);

    // 2D shapes and linear_extrude (builtins_2d.cpp)
    ir::NodePtr moduleSquare(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleCircle(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr modulePolygon(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleLinearExtrude(const ModuleInstantiation &inst, const FramePtr &f);
    /// An empty group standing for a 2D shape in the node tree until an extrusion lifts it.
    ir::NodePtr shape2dNode(Shape2d shape, const ModuleInstantiation &inst);
    const Shape2d *shape2dOf(const ir::Node &n) const;
    /// Bit 1: the subtree holds 2D shapes; bit 2: it holds 3D primitives.
    int contentsOf(const ir::Node &n) const;
    /// OpenSCAD's dimension of a node: that of its first child with geometry (0: none).
    int dimensionOf(const ir::Node &n) const;
    /// n's 2D children; 3D ones are left out, with OpenSCAD's warnings when warnIgnored (and
    /// its mixing warning when warnMixing too).
    std::vector<const ir::Node *> children2d(const ir::Node &n, bool warnMixing,
                                             bool warnIgnored = true);
    /// OpenSCAD's warnings for the 2D parts of a 3D subtree, which 3D operations ignore.
    void warnIgnored2d(const ir::Node &n);
    /// hull() of 2D children (the first child with geometry is 2D): a convex polygon shape.
    ir::NodePtr hull2d(const ir::Node &children, const ModuleInstantiation &inst);
    /// The points whose convex hull is OpenSCAD's hull of the 2D subtree n placed by
    /// `placed`; false (after a warning) when there are more than meshing::kMaxHullPoints.
    bool hullPoints2d(const ir::Node &n, const Affine2 &placed, std::vector<Vec2> &out);
    /// The 3D solid of a 2D subtree swept as `spec` says; null when nothing is left.
    ir::NodePtr lift2d(const ir::Node &n, const ExtrudeSpec &spec, const Affine2 &placed,
                       double pad);
    ir::NodePtr liftShape(const Shape2d &s, const ExtrudeSpec &spec, const Affine2 &placed,
                          double pad);
    ir::NodePtr sweptSolid(const Outline &ccw, const ExtrudeSpec &spec, double pad,
                           int material, const SourceLoc &loc);
    /// Number of 2D outlines under `n` (a circle or square is one).
    size_t outlineCount(const ir::Node &n) const;
    /// Outline points of the 2D shapes under `n` (a circle's fragments), for the geometry
    /// budget.
    double pointCount2d(const ir::Node &n) const;
    void extentOf2d(const ir::Node &n, const Affine2 &placed, Vec2 scale, double &rSqr,
                    double &deltaSqr) const;
    /// Draws the 2D subtrees left outside any extrusion as OpenSCAD's preview does.
    int finish2d(ir::Node &n, bool top);
    ir::NodePtr makeLifted(ir::PrimShape shape, int material, const SourceLoc &loc);

    // rotate_extrude (builtins_revolve.cpp)
    ir::NodePtr moduleRotateExtrude(const ModuleInstantiation &inst, const FramePtr &f);
    /// The x range of every outline point of the 2D subtree n placed by `placed`.
    XRange pointRange2d(const ir::Node &n, const Affine2 &placed);
    /// The 3D solid of a 2D subtree revolved as `spec` says (the subtree's profile is on the
    /// +X side once placed); `subtracted` inside what a difference subtracts.
    ir::NodePtr liftRevolve(const ir::Node &n, const RevolveSpec &spec, const Affine2 &placed,
                            bool subtracted);
    ir::NodePtr revolveShape(const Shape2d &s, const RevolveSpec &spec, const Affine2 &placed,
                             bool subtracted);

  public:
    /// OpenSCAD's polygon set for the 2D children of `n` (the placeholder tree under a module
    /// call, such as the group of an extrusion's children): GeometryEvaluator's
    /// applyToChildren2D(UNION) in 2021.01, so one child is taken as it is and several are
    /// united by Clipper, 3D children are ignored (with OpenSCAD's warnings), each polygon()
    /// is sanitized even-odd and results are quantised as clipper2d.h says. Empty when
    /// nothing 2D is left. `xRange` gives the x extent of the outlines.
    clipper2d::PolygonSet evaluate2d(const ir::Node &n);

  private:
    // Clipper evaluation of 2D subtrees and offset() (evaluate2d.cpp)
    /// Runs a Clipper operation; a coordinate beyond Clipper's range is a located error.
    template <typename F>
    static auto withClipper(const SourceLoc &loc, F &&f) -> decltype(f()) {
        try {
            return f();
        } catch (const clipper2d::RangeError &e) {
            throw EvalError(loc, e.what());
        }
    }
    ir::NodePtr moduleOffset(const ModuleInstantiation &inst, const FramePtr &f);
    /// A 2D shape node holding an evaluated polygon set (offset(), minkowski(), projection(),
    /// ...); an empty group when the set is empty.
    ir::NodePtr polygonSetNode(clipper2d::PolygonSet set, const ModuleInstantiation &inst);
    /// The polygon set of the 2D subtree n; nullopt for OpenSCAD's null geometry. The
    /// children of `silent` are combined without the mixing warning (applyToChildren2D
    /// called directly).
    std::optional<clipper2d::PolygonSet> polygons2d(const ir::Node &n, const ir::Node *silent);
    /// A polygon set's regions swept as `spec` says (see liftShape).
    ir::NodePtr liftRegions(const std::vector<Region> &regions, const ExtrudeSpec &spec,
                            double pad, int material, const SourceLoc &loc);

    // Mesh modules (builtins_mesh.cpp)
    ir::NodePtr modulePolyhedron(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleImport(const ModuleInstantiation &inst, const FramePtr &f);
    /// import_stl(), import_off(), import_dxf(): 2021.01's deprecated spellings of import().
    ir::NodePtr moduleImportDeprecated(const ModuleInstantiation &inst, const FramePtr &f);
    /// The file an import() names: relative to the folder of the file holding the call, else
    /// (deprecated, with OpenSCAD's warning) relative to the main file's folder.
    std::string resolveImportPath(const std::string &name, const SourceLoc &loc);
    ir::NodePtr importMeshFile(const std::string &path, const ModuleInstantiation &inst,
                               const FramePtr &f);
    ir::NodePtr importGltfFile(const std::string &path, const ModuleInstantiation &inst);
    int addMesh(ir::Mesh mesh);

    // text() (builtins_text.cpp)
    ir::NodePtr moduleText(const ModuleInstantiation &inst, const FramePtr &f);

    // 2D file formats and height maps: import() of .dxf/.svg, surface() (builtins_import2d.cpp)
    ir::NodePtr moduleSurface(const ModuleInstantiation &inst, const FramePtr &f);
    /// import() of a .dxf or .svg file named `name` (`a` bound as moduleImport binds it).
    ir::NodePtr importFile2d(const std::string &ext, const std::string &name, const BoundArgs &a,
                             const ModuleInstantiation &inst);
    /// The layer, origin and scale of a DXF read by `who`, checked as OpenSCAD checks them.
    Dxf2dArgs dxfArgs(const std::string &who, const Value &layer, const Value &origin,
                      const SourceLoc &originLoc, const Value &scale, const SourceLoc &scaleLoc);
    /// A DXF file's polygon (DxfData::toPolygon2d, sanitized even-odd as a polygon() is) as a
    /// 2D placeholder; empty, after OpenSCAD's warning, when the file can't be read.
    ir::NodePtr dxfShapeNode(const std::string &path, const Dxf2dArgs &args,
                             const ModuleInstantiation &inst);
    /// An SVG file's polygon (import_svg: each shape sanitized even-odd, all united).
    ir::NodePtr importSvg(const std::string &path, const BoundArgs &a,
                          const ModuleInstantiation &inst);
    /// The file form of linear_extrude()/rotate_extrude(): the DXF named by `file`.
    ir::NodePtr dxfFileShape(const Value &file, const Dxf2dArgs &args,
                             const ModuleInstantiation &inst);

  public:
    /// dxf_dim() or dxf_cross(), which read their arguments by name (2021.01 dxfdim.cc).
    Value callDxfFunction(bool cross, const ArgumentList &args, const FramePtr &f,
                          const SourceLoc &loc);

  private:

    // resize(), minkowski(), projection() (builtins_3d_ops.cpp)
    ir::NodePtr moduleResize(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleMinkowski(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr moduleProjection(const ModuleInstantiation &inst, const FramePtr &f);

    // Metadata modules (builtins_metadata.cpp)
    ir::NodePtr instantiateMetadata(Symbol name, const ModuleInstantiation &inst,
                                    const FramePtr &f);
    ir::NodePtr metaCamera(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr metaPointLight(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr metaAreaLight(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr metaMaterial(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr metaBackground(const ModuleInstantiation &inst, const FramePtr &f);
    ir::NodePtr metaRenderSettings(const ModuleInstantiation &inst, const FramePtr &f);
    void cameraFromViewportVariables(const SourceFile &main);
    int resolveMaterial(const SourceLoc &primLoc);

    static const std::unordered_map<Symbol, ModuleHandler, SymbolHash> &builtinModules();
    static bool isMetadataModule(Symbol name);

    DiagnosticSink &diag_;
    EvalLimits limits_;
    ir::Scene scene_;
    DynamicStack dyn_;
    FramePtr builtinFrame_;
    LoadedFile mainFile_;
    std::unordered_map<const SourceFile *, LoadedFile> libraries_;
    std::vector<Symbol> moduleStack_;

    // Appearance and placement while instantiating
    Mat4 worldFromLocal_;
    std::optional<ColorState> color_;
    std::vector<MaterialSpec> materials_;
    int currentMaterial_ = -1;  ///< material of the current colour/material context, once known
    int backgroundDepth_ = 0;
    /// Above 0, warn() prints nothing: a second pass over a subtree (rotate_extrude evaluates
    /// its children's polygons for their extent, then lifts them) warns only once.
    int quiet_ = 0;
    /// Inside hull(): a singular transform's flat children still give points to the hull.
    int hullDepth_ = 0;
    bool backgroundSet_ = false;
    bool renderSettingsSet_ = false;

    // Files already imported, by canonical path: each is read once and its meshes shared
    /// A glTF file's node tree as an import returned it, cloned for later imports.
    struct GltfImport {
        ir::NodePtr tree;
        bool fileMaterials = false;  ///< made without a material override
    };
    std::unordered_map<std::string, int> meshFiles_;  ///< STL/OFF path -> index in scene meshes
    std::unordered_map<std::string, GltfImport> gltfFiles_;

    // `!` root modifier
    ir::NodePtr rootNode_;
    bool rootSeen_ = false;

    /// Frames captured by function literals; a closure stored in a frame it (indirectly)
    /// captures forms a reference cycle, broken when the evaluator goes away.
    std::vector<std::weak_ptr<Frame>> capturedFrames_;

    std::unordered_set<std::string> deprecationsShown_;

    std::vector<Shape2d> shapes2d_;  ///< 2D shapes, indexed from their placeholder nodes
    bool plateWarned_ = false;

    int callDepth_ = 0;
    int64_t steps_ = 0;
    int64_t stepCap_;  ///< limits_.maxSteps, or the largest count when there is no cap
    std::function<void(int64_t)> progress_;
    double time_ = 0;
    int64_t nodes_ = 0;
    int64_t geometryWork_ = 0;

  public:
    /// Adds `units` (an estimate, made before the work, of the `noun` it makes or examines:
    /// "points", "faces", ...) to the geometry work; beyond EvalLimits::maxGeometryWork a
    /// located error at `loc` naming `what` and the option that raises the budget.
    void chargeGeometryWork(const SourceLoc &loc, const std::string &what, double units,
                            const char *noun = "points");
    /// The geometry work charged so far.
    int64_t geometryWork() const { return geometryWork_; }

  private:
    uint64_t randomCounter_ = 0;
    const char *stackLow_ = nullptr;
};

/// Faces of OpenSCAD's tessellation of the primitives under `n` (as meshing::openscadPolyhedron
/// makes them), estimated from their parameters without building any: what the geometry
/// budget charges before projection(), minkowski(), hull() and resize() tessellate. The
/// points are of the same order.
double tessellatedFaces(const ir::Node &n, const ir::Scene &scene);

/// Builtin function by name, or null.
BuiltinFunction findBuiltinFunction(Symbol name);

}  // namespace rt::scad
