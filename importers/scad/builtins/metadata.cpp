// SPDX-License-Identifier: MIT
// scadray's metadata modules (camera, point_light, area_light, material, background,
// render_settings), the $vp* viewport camera and per-primitive material resolution.
#include <cmath>
#include <cstring>
#include <functional>

#include "core/ir/ir_validate.h"
#include "core/ir/scene_defaults.h"
#include "importers/scad/builtins/colors.h"
#include "importers/scad/builtins/families.h"
#include "importers/scad/builtins/module_support.h"

namespace rt::scad {

namespace {

/// Sky vectors closer than this (relative sine) to the view direction cannot orient a camera.
constexpr double kParallelSine = 1e-9;

/// Reads validated arguments of one metadata call, warning and keeping the default when an
/// argument has the wrong type, is not finite or is out of range.
class MetaArgs {
  public:
    MetaArgs(Evaluator &ev, const BoundArgs &a, const char *module)
        : ev_(ev), a_(a), module_(module) {}

    bool given(size_t i) const { return a_.given[i] && !a_[i].isUndef(); }

    double number(size_t i, double dflt, const std::function<bool(double)> &valid = nullptr,
                  const char *requirement = nullptr) {
        if (!given(i)) return dflt;
        const Value &v = a_[i];
        if (!v.isNumber() || !std::isfinite(v.toNumber())) return bad(i, dflt, "a finite number");
        if (valid && !valid(v.toNumber())) return bad(i, dflt, requirement);
        return v.toNumber();
    }

    bool boolean(size_t i, bool dflt) {
        if (!given(i)) return dflt;
        if (!a_[i].isBool()) return bad(i, dflt, "true or false");
        return a_[i].boolValue();
    }

    Vec3 vec3(size_t i, Vec3 dflt) {
        if (!given(i)) return dflt;
        double x, y, z;
        if (!a_[i].getVec3(x, y, z) || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
            return bad(i, dflt, "a vector of 3 finite numbers");
        return Vec3(x, y, z);
    }

    /// Anything color() accepts; `alpha` receives the fourth component.
    Rgb color(size_t i, Rgb dflt, double *alpha = nullptr) {
        if (!given(i)) return dflt;
        auto c = colorFromValue(a_[i]);
        if (!c || !std::isfinite(c->r) || !std::isfinite(c->g) || !std::isfinite(c->b) ||
            !std::isfinite(c->a) || c->r < 0 || c->g < 0 || c->b < 0)
            return bad(i, dflt, "a colour name, \"#rrggbb\" or [r, g, b] with non-negative values");
        if (alpha) *alpha = c->a;
        return Rgb(c->r, c->g, c->b);
    }

    /// A number (all channels) or [r, g, b].
    Rgb numberOrRgb(size_t i, Rgb dflt) {
        if (!given(i)) return dflt;
        const Value &v = a_[i];
        if (v.isNumber() && std::isfinite(v.toNumber()) && v.toNumber() >= 0)
            return Rgb(v.toNumber());
        double x, y, z;
        if (v.getVec3(x, y, z) && std::isfinite(x) && std::isfinite(y) && std::isfinite(z) &&
            x >= 0 && y >= 0 && z >= 0)
            return Rgb(x, y, z);
        return bad(i, dflt, "a non-negative number or [r, g, b]");
    }

    template <typename T>
    T bad(size_t i, T dflt, const char *requirement) {
        ev_.warn(a_.loc(i), std::string(module_) + "(): " + std::string(a_.names[i]) + " = " +
                                a_[i].toEchoString() + " is not " + requirement +
                                "; using the default");
        return dflt;
    }

  private:
    Evaluator &ev_;
    const BoundArgs &a_;
    const char *module_;
};

bool nonNegative(double x) { return x >= 0; }

bool positive(double x) { return x > 0; }

bool unit(double x) { return x >= 0 && x <= 1; }

ir::NodePtr metaCamera(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    BoundArgs a = ev.bindBuiltin(inst, {"location", "look_at", "sky", "fov"}, f, nullptr);
    MetaArgs m(ev, a, "camera");
    ir::Camera cam;
    Vec3 location = m.vec3(0, cam.location);
    Vec3 lookAt = m.vec3(1, cam.lookAt);
    Vec3 sky = m.vec3(2, cam.sky);
    cam.fov = m.number(
        3, cam.fov, [](double x) { return x > 0 && x < 180; },
        "between 0 and 180 degrees (exclusive)");
    if (ev.scene().camera) {
        ev.warn(inst.loc, "camera() already given at " + ev.scene().camera->loc.toString() +
                              "; this one is ignored");
        return nullptr;
    }
    // The camera is placed by the transforms around the call
    cam.location = ev.state().worldFromLocal.transformPoint(location);
    cam.lookAt = ev.state().worldFromLocal.transformPoint(lookAt);
    cam.sky = ev.state().worldFromLocal.transformVector(sky);
    Vec3 view = cam.lookAt - cam.location;
    if (!(lengthSquared(view) > 0))
        throw EvalError(inst.loc, "camera(): location and look_at are the same point " +
                                      cam.location.toString());
    if (!(length(cross(view, cam.sky)) > kParallelSine * length(view) * length(cam.sky)))
        throw EvalError(inst.loc, "camera(): sky " + cam.sky.toString() +
                                      " is parallel to the view direction " + view.toString());
    cam.fovAxis = ir::FovAxis::Horizontal;
    cam.source = ir::CameraSource::Explicit;
    cam.loc = inst.loc;
    ev.scene().camera = cam;
    return nullptr;
}

ir::NodePtr metaPointLight(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    BoundArgs a = ev.bindBuiltin(
        inst, {"position", "color", "fade_distance", "fade_power", "shadowless"}, f, nullptr);
    MetaArgs m(ev, a, "point_light");
    ir::Light light;
    Vec3 position = m.vec3(0, Vec3(10, -10, 10));
    light.color = m.color(1, light.color);
    light.fadeDistance = m.number(2, light.fadeDistance, nonNegative, "a number >= 0");
    light.fadePower = m.number(3, light.fadePower, nonNegative, "a number >= 0");
    light.shadowless = m.boolean(4, light.shadowless);
    light.position = ev.state().worldFromLocal.transformPoint(position);
    light.loc = inst.loc;
    ev.scene().lights.push_back(light);
    return nullptr;
}

ir::NodePtr metaAreaLight(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    BoundArgs a = ev.bindBuiltin(inst,
                                 {"position", "axis1", "axis2", "samples", "color", "adaptive",
                                  "jitter", "circular", "orient", "fade_distance", "fade_power"},
                                 f, nullptr);
    MetaArgs m(ev, a, "area_light");
    ir::Light light;
    light.area = true;
    ir::Light::Area &area = light.areaLight;
    Vec3 position = m.vec3(0, Vec3(10, -10, 10));
    Vec3 axis1 = m.vec3(1, area.axis1), axis2 = m.vec3(2, area.axis2);
    area.n1 = area.n2 = 5;
    if (m.given(3)) {
        // samples = [n1, n2]: whole numbers from 1 to kMaxAreaLightGrid
        const Value &v = a[3];
        double n1, n2;
        auto count = [](double x) {
            return x >= 1 && x <= ir::kMaxAreaLightGrid && x == std::floor(x);
        };
        if (v.isVector() && v.toVector().size() == 2 && v.toVector()[0].getFiniteNumber(n1) &&
            v.toVector()[1].getFiniteNumber(n2) && count(n1) && count(n2)) {
            area.n1 = static_cast<int>(n1);
            area.n2 = static_cast<int>(n2);
        } else {
            m.bad(3, 0, "[n1, n2] with whole numbers from 1 to 256");
        }
    }
    light.color = m.color(4, light.color);
    area.adaptive = static_cast<int>(m.number(
        5, area.adaptive, [](double x) { return x >= 0 && x <= 100 && x == std::floor(x); },
        "a whole number from 0 to 100"));
    area.jitter = m.boolean(6, area.jitter);
    area.circular = m.boolean(7, area.circular);
    area.orient = m.boolean(8, area.orient);
    light.fadeDistance = m.number(9, light.fadeDistance, nonNegative, "a number >= 0");
    light.fadePower = m.number(10, light.fadePower, nonNegative, "a number >= 0");
    if ((area.circular || area.orient) && (area.n1 < 2 || area.n2 < 2))
        throw EvalError(inst.loc,
                        "area_light(): circular and orient need samples of at least "
                        "[2, 2]; got [" +
                            std::to_string(area.n1) + ", " + std::to_string(area.n2) + "]");
    if (area.orient && std::abs(length(axis1) - length(axis2)) > 1e-9 * length(axis1))
        ev.warn(a.loc(8),
                "area_light(): orient makes both axes as long as axis1 (POV-Ray does the "
                "same); axis2's length is ignored");
    light.position = ev.state().worldFromLocal.transformPoint(position);
    area.axis1 = ev.state().worldFromLocal.transformVector(axis1);
    area.axis2 = ev.state().worldFromLocal.transformVector(axis2);
    light.loc = inst.loc;
    ev.scene().lights.push_back(light);
    return nullptr;
}

ir::NodePtr metaBackground(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    BoundArgs a = ev.bindBuiltin(inst, {"color"}, f, nullptr);
    MetaArgs m(ev, a, "background");
    Rgb c = m.color(0, ir::Settings().background);
    if (ev.state().backgroundSet) {
        ev.warn(inst.loc, "background() already given; this one is ignored");
        return nullptr;
    }
    ev.state().backgroundSet = true;
    ev.scene().settings.background = c;
    return nullptr;
}

ir::NodePtr metaRenderSettings(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    BoundArgs a =
        ev.bindBuiltin(inst, {"max_trace_level", "adc_bailout", "ambient_light"}, f, nullptr);
    MetaArgs m(ev, a, "render_settings");
    ir::Settings s;
    double level = m.number(
        0, s.maxTraceLevel, [](double x) { return x >= 1 && x <= 256 && x == std::floor(x); },
        "a whole number from 1 to 256");
    double bailout = m.number(1, s.adcBailout, unit, "between 0 and 1");
    Rgb ambient = m.color(2, s.ambientLight);
    if (ev.state().renderSettingsSet) {
        ev.warn(inst.loc, "render_settings() already given; this one is ignored");
        return nullptr;
    }
    ev.state().renderSettingsSet = true;
    ev.scene().settings.maxTraceLevel = static_cast<int>(level);
    ev.scene().settings.adcBailout = bailout;
    ev.scene().settings.ambientLight = ambient;
    return nullptr;
}

ir::NodePtr metaMaterial(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = ev.bindBuiltin(inst,
                                 {"color",
                                  "filter",
                                  "transmit",
                                  "ambient",
                                  "diffuse",
                                  "brilliance",
                                  "phong",
                                  "phong_size",
                                  "specular",
                                  "roughness",
                                  "metallic",
                                  "reflection",
                                  "reflection_falloff",
                                  "reflection_exponent",
                                  "fresnel",
                                  "conserve_energy",
                                  "emission",
                                  "ior",
                                  "fade_distance",
                                  "fade_power",
                                  "fade_color",
                                  "glossy",
                                  "frosted",
                                  "blur_samples",
                                  "blur_lobe"},
                                 f, dollars.get());
    MetaArgs m(ev, a, "material");
    MaterialSpec spec;
    spec.loc = inst.loc;
    ir::Material &mat = spec.material;
    ir::Finish &fin = mat.finish;
    ir::Interior &in = mat.interior;
    if (m.given(0)) {
        double alpha = 1;
        Rgb c = m.color(0, Rgb(-1), &alpha);
        if (c.r >= 0) {
            spec.hasColor = true;
            mat.color = c;
            spec.colorAlpha = alpha;
        }
    }
    mat.filter = m.number(1, mat.filter, unit, "between 0 and 1");
    mat.transmit = m.number(2, mat.transmit, unit, "between 0 and 1");
    spec.hasTransmit = m.given(2);
    fin.ambient = m.number(3, fin.ambient, nonNegative, "a number >= 0");
    fin.diffuse = m.number(4, fin.diffuse, nonNegative, "a number >= 0");
    fin.brilliance = m.number(5, fin.brilliance, nonNegative, "a number >= 0");
    fin.phong = m.number(6, fin.phong, nonNegative, "a number >= 0");
    fin.phongSize = m.number(7, fin.phongSize, positive, "a number > 0");
    fin.specular = m.number(8, fin.specular, nonNegative, "a number >= 0");
    fin.roughness = m.number(9, fin.roughness, positive, "a number > 0");
    fin.metallic = m.number(10, fin.metallic, unit, "between 0 and 1");
    if (m.given(11)) {
        // reflection = r (min = max) or [min, max]
        const Value &r = a[11];
        double lo, hi;
        if (r.isNumber() && std::isfinite(r.toNumber()) && unit(r.toNumber())) {
            fin.reflectionMin = fin.reflectionMax = Rgb(r.toNumber());
        } else if (r.isVector() && r.toVector().size() == 2 &&
                   r.toVector()[0].getFiniteNumber(lo) && r.toVector()[1].getFiniteNumber(hi) &&
                   unit(lo) && unit(hi)) {
            fin.reflectionMin = Rgb(lo);
            fin.reflectionMax = Rgb(hi);
        } else {
            m.bad(11, 0, "a number or [min, max] between 0 and 1");
        }
    }
    fin.reflectionFalloff = m.number(12, fin.reflectionFalloff, positive, "a number > 0");
    fin.reflectionExponent = m.number(13, fin.reflectionExponent, positive, "a number > 0");
    fin.fresnel = m.boolean(14, fin.fresnel);
    fin.conserveEnergy = m.boolean(15, fin.conserveEnergy);
    fin.emission = m.numberOrRgb(16, fin.emission);
    in.ior = m.number(17, in.ior, positive, "a number > 0");
    in.fadeDistance = m.number(18, in.fadeDistance, nonNegative, "a number >= 0");
    in.fadePower = m.number(19, in.fadePower, nonNegative, "a number >= 0");
    in.fadeColor = m.color(20, in.fadeColor);
    auto spread = [](double x) { return x >= 0 && x <= ir::kMaxBlurDegrees; };
    fin.glossy = m.number(21, fin.glossy, spread, "an angle from 0 to 90 degrees");
    fin.frosted = m.number(22, fin.frosted, spread, "an angle from 0 to 90 degrees");
    fin.blurSamples = static_cast<int>(m.number(
        23, fin.blurSamples,
        [](double x) { return x >= 1 && x <= ir::kMaxBlurSamples && x == std::floor(x); },
        "a whole number from 1 to 4096"));
    if (m.given(24)) {
        const Value &lobe = a[24];
        if (lobe.isString() && lobe.toStr() == "normal")
            fin.blurLobe = ir::Finish::Lobe::Normal;
        else if (lobe.isString() && lobe.toStr() == "phong")
            fin.blurLobe = ir::Finish::Lobe::Phong;
        else
            m.bad(24, 0, "\"normal\" or \"phong\"");
    }

    FrameGuard g(ev.dynamicScope(), dollars.get());
    ev.state().materials.push_back(spec);
    ev.state().currentMaterial = -1;
    ir::NodePtr node = ev.newNode(ir::NodeKind::Group, inst.loc);
    node->label = "material";
    ev.instantiateChildren(inst, f, node->children);
    ev.state().materials.pop_back();
    ev.state().currentMaterial = -1;
    return node;
}

ir::NodePtr moduleMetadata(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    const std::string &n = inst.name.str();
    if (n == "material") return metaMaterial(ev, inst, f);
    if (!inst.children.empty()) ev.warn(inst.loc, n + "() takes no children; they are ignored");
    // Like the library's empty modules, these calls produce an empty group
    ir::NodePtr node = ev.newNode(ir::NodeKind::Group, inst.loc);
    node->label = n;
    if (ev.state().backgroundDepth > 0) return node;  // left out of the render with its `%` subtree
    if (n == "camera")
        metaCamera(ev, inst, f);
    else if (n == "point_light")
        metaPointLight(ev, inst, f);
    else if (n == "area_light")
        metaAreaLight(ev, inst, f);
    else if (n == "background")
        metaBackground(ev, inst, f);
    else
        metaRenderSettings(ev, inst, f);
    return node;
}

void cameraFromViewportVariables(Evaluator &ev, const SourceFile &main) {
    // Top-level $vpt/$vpr/$vpd/$vpf of the main file move OpenSCAD's camera; honour them
    const Assignment *first = nullptr;
    for (const auto &a : main.top.assignments) {
        const std::string &n = a.name.str();
        if (n == "$vpt" || n == "$vpr" || n == "$vpd" || n == "$vpf") {
            first = &a;
            break;
        }
    }
    if (!first) return;
    const Frame &top = ev.mainFrame();
    auto vec = [&](const char *name, Vec3 dflt) {
        const Value *v = top.findLocal(Symbol::intern(name));
        double x, y, z;
        if (!v) return dflt;
        if (v->getVec3(x, y, z) && std::isfinite(x) && std::isfinite(y) && std::isfinite(z))
            return Vec3(x, y, z);
        ev.warn(first->loc, std::string(name) + " = " + v->toEchoString() +
                                " is not a vector of 3 finite numbers; using the default");
        return dflt;
    };
    auto num = [&](const char *name, double dflt, bool positiveOnly) {
        const Value *v = top.findLocal(Symbol::intern(name));
        if (!v) return dflt;
        if (v->isNumber() && std::isfinite(v->toNumber()) && (!positiveOnly || v->toNumber() > 0))
            return v->toNumber();
        ev.warn(first->loc, std::string(name) + " = " + v->toEchoString() +
                                " is not a usable number; using the default");
        return dflt;
    };
    Vec3 vpt = vec("$vpt", ir::kOpenScadBuiltinVpt);
    Vec3 vpr = vec("$vpr", ir::kOpenScadBuiltinVpr);
    double vpd = num("$vpd", ir::kOpenScadBuiltinVpd, true);
    double vpf = num("$vpf", ir::kOpenScadDefaultFov, true);
    if (!(vpf < 180)) {
        ev.warn(first->loc, "$vpf must be below 180 degrees; using the default");
        vpf = ir::kOpenScadDefaultFov;
    }
    ir::Camera cam = ir::cameraFromViewport(vpt, vpr, vpd, vpf);
    cam.source = ir::CameraSource::ViewportVariables;
    cam.loc = first->loc;
    ev.scene().camera = cam;
}

}  // namespace

int resolveMaterial(Evaluator &ev, const SourceLoc &primLoc) {
    // Finish, interior, filter and transmit from the innermost material(); pigment from the
    // outermost valid color(), else the innermost material() with a colour, else OpenSCAD's
    // default face colour.
    if (ev.state().currentMaterial >= 0) return ev.state().currentMaterial;
    const MaterialSpec *inner =
        ev.state().materials.empty() ? nullptr : &ev.state().materials.back();
    ir::Material m = inner ? inner->material : ir::Material();
    m.color = ir::kOpenScadDefaultColor;
    m.loc = inner ? inner->loc : primLoc;
    if (ev.state().color) {
        m.color = Rgb(ev.state().color->r, ev.state().color->g, ev.state().color->b);
        if (ev.state().color->a < 1) m.transmit = std::clamp(1 - ev.state().color->a, 0.0, 1.0);
        if (!inner) m.loc = ev.state().color->loc;
    } else {
        for (auto it = ev.state().materials.rbegin(); it != ev.state().materials.rend(); ++it) {
            if (!it->hasColor) continue;
            m.color = it->material.color;
            if (it->colorAlpha < 1 && !inner->hasTransmit)
                m.transmit = std::clamp(1 - it->colorAlpha, 0.0, 1.0);
            break;
        }
    }
    return ev.state().currentMaterial = ev.scene().addMaterial(m);
}

void viewportCameraPass(Evaluator &ev, const SourceFile &main) {
    if (!ev.scene().camera) cameraFromViewportVariables(ev, main);
}

BuiltinFamily metadataBuiltins() {
    static constexpr BuiltinModuleEntry kModules[] = {
        {"camera", moduleMetadata, true},     {"point_light", moduleMetadata, true},
        {"area_light", moduleMetadata, true}, {"material", moduleMetadata, true},
        {"background", moduleMetadata, true}, {"render_settings", moduleMetadata, true},
    };
    return {kModules, {}};
}

}  // namespace rt::scad
