// SPDX-License-Identifier: MIT
// Canonical IR text writer.
#include "core/ir/ir_dump.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace rt::ir {

std::string formatNumber(double v) {
    if (v == 0) return "0";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

namespace {

std::string vec(const Vec3 &v) {
    return "[" + formatNumber(v.x) + ", " + formatNumber(v.y) + ", " + formatNumber(v.z) + "]";
}
std::string rgb(const Rgb &c) {
    return "[" + formatNumber(c.r) + ", " + formatNumber(c.g) + ", " + formatNumber(c.b) + "]";
}
std::string boolean(bool b) { return b ? "true" : "false"; }

std::string where(const SourceLoc &loc) {
    if (!loc.isValid()) return "";
    return "  # " + std::filesystem::path(*loc.file).filename().string() + ":" +
           std::to_string(loc.line) + ":" + std::to_string(loc.col);
}

std::string matrix(const Mat4 &m) {
    std::string s = "[";
    for (int i = 0; i < 3; ++i) {
        s += i ? ", [" : "[";
        for (int j = 0; j < 4; ++j) s += (j ? ", " : "") + formatNumber(m.m[i][j]);
        s += "]";
    }
    return s + "]";
}

/// A profile outline as [[r, z] ...].
std::string outline(const ProfileOutline &o) {
    std::string s = "[";
    for (size_t i = 0; i < o.size(); ++i)
        s += (i ? " [" : "[") + formatNumber(o[i].r) + ", " + formatNumber(o[i].z) + "]";
    return s + "]";
}

void dumpNode(const Node &n, int indent, std::ostringstream &os) {
    os << std::string(2 * indent, ' ');
    switch (n.kind) {
        case NodeKind::Transform:
            os << "transform " << matrix(n.matrix);
            break;
        case NodeKind::Primitive:
            if (const auto *s = std::get_if<SpherePrim>(&n.shape))
                os << "sphere r " << formatNumber(s->radius);
            else if (const auto *b = std::get_if<BoxPrim>(&n.shape))
                os << "box min " << vec(b->min) << " max " << vec(b->max);
            else if (const auto *m = std::get_if<MeshPrim>(&n.shape))
                os << "mesh " << m->mesh;
            else if (const auto *p = std::get_if<PolytopePrim>(&n.shape)) {
                os << "polytope vertices [";
                for (size_t i = 0; i < p->vertices.size(); ++i)
                    os << (i ? " " : "") << vec(p->vertices[i]);
                os << "] faces [";
                for (size_t i = 0; i < p->faces.size(); ++i) {
                    os << (i ? " [" : "[");
                    for (size_t j = 0; j < p->faces[i].size(); ++j)
                        os << (j ? " " : "") << p->faces[i][j];
                    os << "]";
                }
                os << "]";
            } else if (const auto *t = std::get_if<TorusPrim>(&n.shape)) {
                os << "torus major " << formatNumber(t->major) << " minor "
                   << formatNumber(t->minor) << " angle " << formatNumber(t->angle) << " fragments "
                   << t->fragments << " outline " << outline(t->facetOutline);
            } else if (const auto *l = std::get_if<LathePrim>(&n.shape)) {
                os << "lathe angle " << formatNumber(l->angle) << " fragments " << l->fragments
                   << " outlines [";
                for (size_t i = 0; i < l->outlines.size(); ++i)
                    os << (i ? " " : "") << outline(l->outlines[i]);
                os << "]";
            } else if (const auto *pr = std::get_if<PrismPrim>(&n.shape)) {
                os << "prism z0 " << formatNumber(pr->z0) << " z1 " << formatNumber(pr->z1)
                   << " k0 " << formatNumber(pr->k0) << " k1 " << formatNumber(pr->k1) << " mesh "
                   << pr->mesh << " outline [";
                for (size_t i = 0; i < pr->outline.size(); ++i)
                    os << (i ? " [" : "[") << formatNumber(pr->outline[i].x) << ", "
                       << formatNumber(pr->outline[i].y) << "]";
                os << "]";
            } else {
                const auto &c = std::get<CylinderPrim>(n.shape);
                os << "cylinder z0 " << formatNumber(c.z0) << " z1 " << formatNumber(c.z1) << " r1 "
                   << formatNumber(c.r1) << " r2 " << formatNumber(c.r2);
            }
            os << " material " << n.material << " fn " << formatNumber(n.fragments.fn) << " fa "
               << formatNumber(n.fragments.fa) << " fs " << formatNumber(n.fragments.fs);
            break;
        default:
            os << nodeKindName(n.kind);
            break;
    }
    if (n.highlight) os << " highlight";
    if (!n.label.empty()) os << " label \"" << n.label << "\"";
    os << where(n.loc) << "\n";
    for (const auto &c : n.children) dumpNode(*c, indent + 1, os);
}

const char *cameraSourceName(CameraSource s) {
    switch (s) {
        case CameraSource::Explicit:
            return "explicit";
        case CameraSource::ViewportVariables:
            return "viewport";
        case CameraSource::Automatic:
            return "automatic";
    }
    return "?";
}

}  // namespace

std::string dump(const Node &node, int indent) {
    std::ostringstream os;
    dumpNode(node, indent, os);
    return os.str();
}

std::string dump(const Scene &scene) {
    std::ostringstream os;
    const Settings &s = scene.settings;
    os << "settings background " << rgb(s.background) << " ambient_light " << rgb(s.ambientLight)
       << " max_trace_level " << s.maxTraceLevel << " adc_bailout " << formatNumber(s.adcBailout)
       << "\n";
    if (s.environment.kind == EnvironmentKind::Gradient) {
        os << "environment gradient";
        for (const GradientStop &g : s.environment.gradient)
            os << " " << formatNumber(g.z) << " " << rgb(g.color);
        os << " rotate " << formatNumber(s.environment.rotateDegrees) << "\n";
    } else if (s.environment.kind == EnvironmentKind::Image) {
        os << "environment image " << s.environment.imagePath << " rotate "
           << formatNumber(s.environment.rotateDegrees) << "\n";
    }
    if (scene.camera) {
        const Camera &c = *scene.camera;
        os << "camera " << cameraSourceName(c.source)
           << (c.projection == Projection::Orthographic
                   ? " orthographic height " + formatNumber(c.orthoHeight)
                   : "")
           << " location " << vec(c.location) << " look_at " << vec(c.lookAt) << " sky "
           << vec(c.sky) << " fov " << formatNumber(c.fov)
           << (c.fovAxis == FovAxis::Horizontal ? " horizontal" : " vertical") << where(c.loc)
           << "\n";
    }
    for (const Light &l : scene.lights)
        os << "light "
           << (l.kind == Light::Kind::Point  ? "point"
               : l.kind == Light::Kind::Spot ? "spot"
                                             : "directional")
           << " position " << vec(l.position)
           << (l.kind != Light::Kind::Point ? " direction " + vec(l.direction) : "")
           << (l.kind == Light::Kind::Spot
                   ? " radius " + formatNumber(l.spotRadius) + " falloff " +
                         formatNumber(l.spotFalloff) + " tightness " + formatNumber(l.spotTightness)
                   : "")
           << " color " << rgb(l.color) << " fade_distance " << formatNumber(l.fadeDistance)
           << " fade_power " << formatNumber(l.fadePower) << " shadowless " << boolean(l.shadowless)
           << (l.area ? " area " + vec(l.areaLight.axis1) + " " + vec(l.areaLight.axis2) + " " +
                            std::to_string(l.areaLight.n1) + "x" + std::to_string(l.areaLight.n2) +
                            " adaptive " + std::to_string(l.areaLight.adaptive) + " jitter " +
                            boolean(l.areaLight.jitter) + " circular " +
                            boolean(l.areaLight.circular) + " orient " + boolean(l.areaLight.orient)
                      : std::string())
           << where(l.loc) << "\n";
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        const Material &m = scene.materials[i];
        const Finish &f = m.finish;
        os << "material " << i << " color " << rgb(m.color) << " filter " << formatNumber(m.filter)
           << " transmit " << formatNumber(m.transmit) << " ambient " << formatNumber(f.ambient)
           << " diffuse " << formatNumber(f.diffuse) << " brilliance " << formatNumber(f.brilliance)
           << " phong " << formatNumber(f.phong) << " phong_size " << formatNumber(f.phongSize)
           << " specular " << formatNumber(f.specular) << " roughness " << formatNumber(f.roughness)
           << " metallic " << formatNumber(f.metallic) << " reflection_min " << rgb(f.reflectionMin)
           << " reflection_max " << rgb(f.reflectionMax) << " reflection_falloff "
           << formatNumber(f.reflectionFalloff) << " reflection_exponent "
           << formatNumber(f.reflectionExponent) << " fresnel " << boolean(f.fresnel)
           << " conserve_energy " << boolean(f.conserveEnergy) << " emission " << rgb(f.emission)
           << (f.glossy > 0 || f.frosted > 0
                   ? " glossy " + formatNumber(f.glossy) + " frosted " + formatNumber(f.frosted) +
                         " blur_samples " + std::to_string(f.blurSamples) + " blur_lobe " +
                         (f.blurLobe == Finish::Lobe::Phong ? "phong" : "normal")
                   : std::string())
           << " ior " << formatNumber(m.interior.ior) << " fade_distance "
           << formatNumber(m.interior.fadeDistance) << " fade_power "
           << formatNumber(m.interior.fadePower) << " fade_color " << rgb(m.interior.fadeColor)
           << (m.baseColorTexture.valid() ? " texture " + std::to_string(m.baseColorTexture.texture)
                                          : "")
           << where(m.loc) << "\n";
    }
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
        const Mesh &m = *scene.meshes[i];
        MeshTopology t = analyzeMesh(m);
        os << "mesh " << i << " \"" << m.name << "\" vertices " << m.positions.size()
           << " triangles " << m.triangles.size() << " normals " << boolean(!m.normals.empty())
           << " uvs " << boolean(!m.uvs.empty()) << " closed " << boolean(t.closed())
           << " oriented " << boolean(t.oriented()) << " bounds " << vec(m.bounds().min) << " "
           << vec(m.bounds().max) << where(m.loc) << "\n";
    }
    for (size_t i = 0; i < scene.textures.size(); ++i)
        os << "texture " << i << " \"" << scene.textures[i]->name << "\" "
           << scene.textures[i]->width << "x" << scene.textures[i]->height << "\n";
    const ImportStats &st = scene.stats;
    os << "dropped background_parts " << st.backgroundParts << " disabled_parts "
       << st.disabledParts << " skipped_modules " << st.skippedModules << "\n";
    dumpNode(*scene.root, 0, os);
    return os.str();
}

}  // namespace rt::ir
