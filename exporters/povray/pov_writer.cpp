// SPDX-License-Identifier: MIT
// IR -> POV-Ray SDL.
#include "exporters/povray/pov_writer.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/image/image_io.h"
#include "core/materials/pbr_material.h"
#include "core/materials/texture_sampler.h"
#include "core/math/degree_trig.h"
#include "core/meshing/facets.h"
#include "core/meshing/revolved_mesh.h"
#include "core/system/temp_file.h"
#include "exporters/povray/pov_format.h"
#include "exporters/povray/pov_texture.h"

namespace rt::pov {

namespace {

namespace fs = std::filesystem;

std::string where(const SourceLoc &loc) {
    if (!loc.isValid()) return "";
    return fs::path(*loc.file).filename().string() + ":" + std::to_string(loc.line) + ":" +
           std::to_string(loc.col);
}

std::string materialName(int index) { return "Material_" + std::to_string(index); }

/// POV-Ray's lathe revolves points <r, y> about its y axis; `rotate x*90` turns y into +Z,
/// scadray's axis. A closed outline repeats its first point.
std::string lathe(const ir::ProfileOutline &o) {
    std::string s = "lathe { linear_spline " + std::to_string(o.size() + 1);
    for (size_t i = 0; i <= o.size(); ++i) {
        const ir::ProfilePoint &p = o[i % o.size()];
        s += ", <" + num(p.r) + ", " + num(p.z) + ">";
    }
    return s + " rotate x*90 }";
}

/// The even-odd region of outline k and those nested in it: POV-Ray's lathe takes one closed
/// spline (its inside test counts the crossings of every segment, so a second outline would
/// need a visible bridge), hence each outline is a lathe and each hole a difference.
std::string latheRegion(const std::vector<ir::ProfileOutline> &outlines,
                        const std::vector<int> &parents, int k, const std::string &pad) {
    std::string s = lathe(outlines[k]);
    std::string children;
    for (size_t h = 0; h < outlines.size(); ++h)
        if (parents[h] == k)
            children += "\n" + pad + "    " +
                        latheRegion(outlines, parents, static_cast<int>(h), pad + "    ");
    if (children.empty()) return s;
    return "difference {\n" + pad + "    " + s + children + "\n" + pad + "}";
}

/// A prism as POV-Ray's exact `prism` with linear segments. POV-Ray sweeps the outline, given
/// in its x-z plane, along its y axis; the matrix swaps y and z, so the outline lands in our
/// x-y plane and the sweep on +Z (a reflection, which leaves the solid's inside as it is). A
/// constant scale k is a linear_sweep of the scaled points from z0 to z1. A changing scale is
/// a conic_sweep, whose section at height h is the outline scaled by h: heights k0 .. k1 (from
/// 0 for an apex), then height k mapped to z = z0 + (k - k0) (z1 - z0) / (k1 - k0).
std::string prismShape(const ir::PrismPrim &p) {
    bool conic = p.k0 != p.k1;
    double k = conic ? 1 : p.k0;
    double h0 = conic ? std::min(p.k0, p.k1) : p.z0, h1 = conic ? std::max(p.k0, p.k1) : p.z1;
    std::string s = std::string("prism { ") + (conic ? "conic_sweep" : "linear_sweep") +
                    " linear_spline " + num(h0) + ", " + num(h1) + ", " +
                    std::to_string(p.outline.size() + 1);
    // The outline is closed by repeating its first point
    for (size_t i = 0; i <= p.outline.size(); ++i) {
        const ir::Point2 &q = p.outline[i % p.outline.size()];
        s += ", <" + num(k * q.x) + ", " + num(k * q.y) + ">";
    }
    Mat4 m;
    m.m[1][1] = m.m[2][2] = 0;
    m.m[1][2] = 1;
    m.m[2][1] = 1;
    if (conic) {
        double stretch = (p.z1 - p.z0) / (p.k1 - p.k0);
        m.m[2][1] = stretch;
        m.m[2][3] = p.z0 - p.k0 * stretch;
    }
    return s + " " + matrix(m);
}

/// An open solid of revolution for the writer to close: a torus or lathe about +Z, cut to
/// azimuths [0, angle] by planes through the axis when the turn is partial.
std::string revolvedShape(const ir::PrimShape &shape, const std::string &pad) {
    const auto *t = std::get_if<ir::TorusPrim>(&shape);
    const auto *l = std::get_if<ir::LathePrim>(&shape);
    double angle = t ? t->angle : l->angle;
    bool full = angle >= 360;
    std::string inner = full ? pad : pad + "    ";
    std::string solid;
    if (t) {
        // POV-Ray's torus lies in its x-z plane about y; sturm: the accurate quartic solver,
        // which thin tori need
        solid = "torus { " + num(t->major) + ", " + num(t->minor) + " sturm rotate x*90";
        if (!full) solid += " }";
    } else {
        std::vector<int> parents = meshing::profileParents(l->outlines);
        std::vector<std::string> regions;
        for (size_t k = 0; k < l->outlines.size(); ++k)
            if (parents[k] < 0)
                regions.push_back(latheRegion(l->outlines, parents, static_cast<int>(k), inner));
        if (regions.size() == 1) {
            solid = regions[0];
        } else {
            // Disjoint outer outlines: merge, so no face shows inside a transparent solid
            solid = "merge {";
            for (const auto &r : regions) solid += "\n" + inner + "    " + r;
            solid += "\n" + inner + "}";
        }
        // Left open for the texture and the placement
        if (full) solid.pop_back();
    }
    if (full) return solid;
    // The wedge of azimuths [0, angle]: y >= 0 and clockwise of the end direction; past a
    // half turn the union of the two half-spaces (merge, so neither plane shows inside the
    // other), at exactly a half turn the one plane
    Vec3 endNormal(-sinDegrees(angle), cosDegrees(angle), 0);
    std::string start = "plane { <0, -1, 0>, 0 }", end = "plane { " + vec(endNormal) + ", 0 }";
    std::string wedge;
    if (angle == 180)
        wedge = start;
    else if (angle < 180)
        wedge = "intersection { " + start + " " + end + " }";
    else
        wedge = "merge { " + start + " " + end + " }";
    return "intersection {\n" + inner + solid + "\n" + inner + wedge + "\n" + pad;
}

/// A node that CSG treats as its only child: groups, unions and transforms of one child.
bool passesThrough(const ir::Node &n) {
    return n.kind != ir::NodeKind::Primitive && n.children.size() == 1;
}

const ir::Node *firstPrimitive(const ir::Node &n) {
    if (n.kind == ir::NodeKind::Primitive) return &n;
    for (const auto &c : n.children)
        if (const ir::Node *p = firstPrimitive(*c)) return p;
    return nullptr;
}

class Writer {
  public:
    Writer(const ir::Scene &scene, std::string assetPrefix, std::vector<TextureFile> *images)
        : scene_(scene), assetPrefix_(safeFileName(assetPrefix)), images_(images) {}

    std::string run(const std::string &sourceName) {
        collectUsed(*scene_.root);
        header(sourceName);
        settings();
        camera();
        lights();
        materials();
        meshes();
        os_ << "// Objects\n";
        topLevel(*scene_.root, Mat4());
        return os_.str();
    }

  private:
    void collectUsed(const ir::Node &n) {
        if (n.kind == ir::NodeKind::Primitive) {
            used_.insert(n.material);
            if (const auto *m = std::get_if<ir::MeshPrim>(&n.shape)) {
                usedMeshes_.insert(m->mesh);
                meshMaterials_.insert({m->mesh, n.material});
                if (vertexColoured(m->mesh, n.material))
                    colouredMeshes_.insert({m->mesh, n.material});
            }
        }
        for (const auto &c : n.children) collectUsed(*c);
    }

    void header(const std::string &sourceName) {
        os_ << "// Exported by scadray from " << commentText(sourceName) << "\n"
            << "// The scene is right-handed with +Z up, as OpenSCAD's. Geometry is written in\n"
            << "// its own coordinates; the camera's negative `right` vector makes POV-Ray's\n"
            << "// look_at construction right-handed too.\n"
            << "// Render: povray "
            << "<this file> +W640 +H480 -A +FN16 File_Gamma=1.0 -D -V -GR\n"
            << "// (or the .ini written beside it).\n"
            << "#version 3.7;\n\n";
    }

    void settings() {
        const ir::Settings &s = scene_.settings;
        os_ << "global_settings {\n"
            << "    assumed_gamma 1.0\n"
            << "    ambient_light " << rgb(s.ambientLight) << "\n"
            << "    max_trace_level " << s.maxTraceLevel << "\n"
            << "    adc_bailout " << num(s.adcBailout) << "\n"
            << "}\n\n"
            << "background { " << rgb(s.background) << " }\n\n";
        skySphere(s.environment);
    }

    /// The environment as a sky_sphere, looked up by ray direction exactly as scadray does
    /// (core/render/environment.cpp): the gradient as a colour_map over the direction's z
    /// mapped from [-1, 1] to [0, 1]; the image as a spherical image_map whose pole is turned
    /// from +y to +Z, written beside the .pov as linear EXR.
    void skySphere(const ir::Environment &e) {
        if (e.kind == ir::EnvironmentKind::Gradient) {
            os_ << "// Environment: gradient over the ray direction's height\n"
                << "sky_sphere {\n    pigment {\n        gradient z\n        color_map {\n";
            for (const ir::GradientStop &g : e.gradient)
                os_ << "            [" << num((g.z + 1) / 2) << " " << rgb(g.color) << "]\n";
            os_ << "        }\n        scale 2 translate -z\n    }\n}\n\n";
        } else if (e.kind == ir::EnvironmentKind::Image && e.image) {
            std::string file = assetPrefix_ + "_environment.exr";
            if (images_) images_->push_back({file, bakedTexture(*e.image, Rgb(1))});
            os_ << "// Environment: " << commentText(e.imagePath) << "\n"
                << "sky_sphere {\n    pigment {\n        image_map { exr \"" << file
                << "\" map_type 1 interpolate 2 }\n        rotate x*90\n";
            if (e.rotateDegrees != 0) os_ << "        rotate z*" << num(e.rotateDegrees) << "\n";
            os_ << "    }\n}\n\n";
        }
    }

    void camera() {
        if (!scene_.camera) throw std::logic_error("writeSdl needs a complete scene (camera)");
        const ir::Camera &c = *scene_.camera;
        if (c.projection == ir::Projection::Orthographic) {
            // POV-Ray's orthographic film is |right| x |up| in world units
            os_ << comment(c.loc, "camera") << "camera {\n"
                << "    orthographic\n"
                << "    location " << vec(c.location) << "\n"
                << "    look_at " << vec(c.lookAt) << "\n"
                << "    sky " << vec(c.sky) << "\n"
                << "    up <0, " << num(c.orthoHeight) << ", 0>\n"
                << "    right <-" << num(c.orthoHeight) << " * image_width / image_height, 0, 0>\n"
                << "}\n\n";
            return;
        }
        std::string angle = num(c.fov);
        if (c.fovAxis == ir::FovAxis::Vertical)
            angle = "degrees(2 * atan(tan(radians(" + num(c.fov) +
                    " / 2)) * image_width / image_height))";
        os_ << comment(c.loc,
                       c.source == ir::CameraSource::Automatic
                           ? "camera: automatic, framing the model from OpenSCAD's default view"
                           : "camera")
            << "camera {\n"
            << "    perspective\n"
            << "    location " << vec(c.location) << "\n"
            << "    look_at " << vec(c.lookAt) << "\n"
            << "    sky " << vec(c.sky) << "\n"
            << "    up <0, 1, 0>\n"
            << "    right <-image_width / image_height, 0, 0>\n"
            << "    angle " << angle << "\n"
            << "}\n\n";
    }

    void lights() {
        for (const ir::Light &l : scene_.lights) {
            os_ << comment(l.loc, "light") << "light_source {\n"
                << "    " << vec(l.position) << ", " << rgb(l.color) << "\n";
            if (l.kind == ir::Light::Kind::Spot)
                os_ << "    spotlight\n"
                    << "    point_at " << vec(l.position + normalize(l.direction)) << "\n"
                    << "    radius " << num(l.spotRadius) << "\n"
                    << "    falloff " << num(l.spotFalloff) << "\n"
                    << "    tightness " << num(l.spotTightness) << "\n";
            if (l.kind == ir::Light::Kind::Directional)
                os_ << "    parallel\n"
                    << "    point_at " << vec(l.position + normalize(l.direction)) << "\n";
            if (l.fadePower > 0 && l.fadeDistance != 0)
                os_ << "    fade_distance " << num(l.fadeDistance) << "\n"
                    << "    fade_power " << num(l.fadePower) << "\n";
            if (l.shadowless) os_ << "    shadowless\n";
            if (l.area) {
                const ir::Light::Area &a = l.areaLight;
                os_ << "    area_light " << vec(a.axis1) << ", " << vec(a.axis2) << ", " << a.n1
                    << ", " << a.n2 << "\n"
                    << "    adaptive " << a.adaptive << "\n";
                if (a.jitter) os_ << "    jitter  // POV-Ray jitters from its own table\n";
                if (a.circular || a.orient) os_ << "    circular\n";  // orient needs it
                if (a.orient) os_ << "    orient\n";
            }
            os_ << "}\n";
        }
        os_ << "\n";
    }

    void materials() {
        os_ << "// Materials: pigment explicit; finish terms that have an effect (ambient and "
               "diffuse\n"
               "// always: POV-Ray's defaults differ)\n";
        for (int i : used_) {
            const ir::Material &m = scene_.materials[i];
            const ir::Finish &f = m.finish;
            os_ << comment(m.loc, "") << blurComment(f) << "#declare " << materialName(i)
                << " = texture {\n";
            const ir::Texture *tex = m.baseColorTexture.valid()
                                         ? scene_.textures[m.baseColorTexture.texture].get()
                                         : nullptr;
            if (tex) {
                os_ << "    uv_mapping\n" << texturedPigment(i, m, *tex).body(finish(f));
            } else {
                os_ << "    pigment { rgbft <" << num(m.color.r) << ", " << num(m.color.g) << ", "
                    << num(m.color.b) << ", " << num(m.filter) << ", " << num(m.transmit) << "> }\n"
                    << finish(f);
            }
            os_ << "}\n";
        }
        os_ << "\n";
    }

    /// The finish terms that have an effect. ambient and diffuse always (POV-Ray's defaults,
    /// 0.1 and 0.6, differ from the IR's); the rest only where they change the picture: a
    /// term at POV-Ray's default (emission 0, phong 0, specular 0, no reflection) is left
    /// out, and so are the parameters of a term that is off (phong_size without phong,
    /// roughness without specular, metallic without highlights, brilliance without diffuse).
    static std::string finish(const ir::Finish &f) {
        std::ostringstream os_;  // the writer's name, so the terms read as everywhere else
        os_ << "    finish {\n"
            << "        ambient " << num(f.ambient) << "\n";
        if (!f.emission.isBlack()) os_ << "        emission " << rgb(f.emission) << "\n";
        os_ << "        diffuse " << num(f.diffuse) << "\n";
        if (f.diffuse != 0 && f.brilliance != 1)
            os_ << "        brilliance " << num(f.brilliance) << "\n";
        if (f.phong != 0) os_ << "        phong " << num(f.phong) << "\n";
        if (f.phong != 0 && f.phongSize != 40)
            os_ << "        phong_size " << num(f.phongSize) << "\n";
        if (f.specular != 0) os_ << "        specular " << num(f.specular) << "\n";
        if (f.specular != 0 && f.roughness != 0.05)
            os_ << "        roughness " << num(f.roughness) << "\n";
        if ((f.phong != 0 || f.specular != 0) && f.metallic != 0)
            os_ << "        metallic " << num(f.metallic) << "\n";
        if (f.hasReflection()) {
            os_ << "        reflection {\n"
                << "            " << rgb(f.reflectionMin) << ", " << rgb(f.reflectionMax) << "\n";
            if (f.fresnel) os_ << "            fresnel on\n";
            if (f.reflectionFalloff != 1)
                os_ << "            falloff " << num(f.reflectionFalloff) << "\n";
            if (f.reflectionExponent != 1)
                os_ << "            exponent " << num(f.reflectionExponent) << "\n";
            os_ << "        }\n";
        }
        if (f.conserveEnergy) os_ << "        conserve_energy\n";
        os_ << "    }\n";
        return os_.str();
    }

    /// POV-Ray 3.7 has no blurred reflection or refraction: the nearest equivalent is the sharp
    /// direction the lobe spreads about (its mean), which the texture below keeps.
    static std::string blurComment(const ir::Finish &f) {
        std::string lobe = f.blurLobe == ir::Finish::Lobe::Phong ? "phong" : "normal";
        std::string out;
        if (f.glossy > 0)
            out += "// scadray: glossy reflection spread " + num(f.glossy) + " deg (" + lobe +
                   " lobe) cannot be expressed in POV-Ray 3.7; written as the sharp mirror "
                   "reflection it spreads about\n";
        if (f.frosted > 0)
            out += "// scadray: frosted refraction spread " + num(f.frosted) + " deg (" + lobe +
                   " lobe) cannot be expressed in POV-Ray 3.7; written as the sharp refraction "
                   "it spreads about\n";
        return out;
    }

    /// The environment image's RGB times `factor`, as it is (base colour textures go through
    /// texturePigment, which also bakes wrap modes).
    static Image bakedTexture(const ir::Texture &tex, const Rgb &factor) {
        Image img(tex.width, tex.height);
        for (int y = 0; y < tex.height; ++y)
            for (int x = 0; x < tex.width; ++x) {
                const float *p = &tex.rgba[4 * (size_t(y) * tex.width + x)];
                img.set(x, y, Rgb(p[0], p[1], p[2]) * factor);
            }
        return img;
    }

    /// How a material's base colour texture alpha makes it see-through: glTF's alpha mode,
    /// factor and cutoff from its per-texel description (the renderer cuts or blends each
    /// texel by them); opaque for every other material, whose own transmit then applies.
    static TextureAlpha textureAlpha(const ir::Material &m) {
        TextureAlpha a;
        if (!m.texel.pbr) return a;
        const PbrMaterial &p = *m.texel.pbr;
        switch (p.alphaMode) {
            case PbrMaterial::AlphaMode::Opaque:
                return a;
            case PbrMaterial::AlphaMode::Mask:
                a.mode = TextureAlpha::Mode::Mask;
                break;
            case PbrMaterial::AlphaMode::Blend:
                a.mode = TextureAlpha::Mode::Blend;
                break;
        }
        a.factor = p.alpha;
        a.cutoff = p.alphaCutoff;
        return a;
    }

    /// The uv_mapping pigment of a textured material: colour factor, wrap modes, filter,
    /// KHR_texture_transform and alpha baked as pov_texture.h describes; the images go to
    /// images_. The transform's reach comes from every mesh the material is placed on.
    TexturePigment texturedPigment(int index, const ir::Material &m, const ir::Texture &tex) {
        const ir::TextureRef &ref = m.baseColorTexture;
        UvRange range;
        for (const auto &[mesh, material] : meshMaterials_) {
            if (material != index) continue;
            const ir::Mesh &me = *scene_.meshes[mesh];
            for (const auto &uv : ref.texCoord == 1 ? me.uvs1 : me.uvs) {
                double u = uv[0], v = uv[1];
                transformTexCoord(ref, &u, &v);
                range.add(u, v);
            }
        }
        TextureAlpha alpha = textureAlpha(m);
        double transmit = alpha.mode == TextureAlpha::Mode::Opaque ? m.transmit : 0;
        TexturePigment p = texturePigment(tex, ref, m.color, alpha, range, m.filter, transmit,
                                          assetPrefix_ + "_" + materialName(index));
        if (images_)
            for (TextureFile &f : p.files) images_->push_back(std::move(f));
        return p;
    }

    /// The texture coordinate set mesh2 `mesh` carries (it has one uv_vectors): the one the
    /// base colour textures placed on it read, TEXCOORD_0 when none does or when they
    /// disagree (`note` then says so).
    const std::vector<std::array<float, 2>> &exportedUvs(const ir::Mesh &m,
                                                         std::string *note) const {
        std::set<int> sets;
        for (const auto &[mesh, material] : meshMaterials_) {
            const ir::TextureRef &ref = scene_.materials[material].baseColorTexture;
            if (scene_.meshes[mesh].get() == &m && ref.valid()) sets.insert(ref.texCoord);
        }
        if (sets.size() > 1)
            *note =
                "    // scadray: textures on this mesh read both TEXCOORD_0 and TEXCOORD_1; "
                "mesh2 holds one set: TEXCOORD_0 written\n";
        return sets.size() == 1 && *sets.begin() == 1 && !m.uvs1.empty() ? m.uvs1 : m.uvs;
    }

    /// Whether mesh `mesh` is written with its vertex colours for material `material`: it has
    /// colours and the material no base colour texture (POV-Ray's mesh2 takes one texture per
    /// vertex, so a colour per vertex excludes an image map).
    bool vertexColoured(int mesh, int material) const {
        return !scene_.meshes[mesh]->colors.empty() &&
               !scene_.materials[material].baseColorTexture.valid();
    }

    /// The declared name of mesh `mesh` as material `material` shows it.
    std::string meshName(int mesh, int material) const {
        if (colouredMeshes_.count({mesh, material}))
            return "Mesh_" + std::to_string(mesh) + "_" + materialName(material);
        return "Mesh_" + std::to_string(mesh);
    }

    /// Each mesh once, as mesh2; objects place it. A closed mesh gets an inside_vector, so
    /// POV-Ray knows its inside (by parity) and it can take part in CSG. A mesh with vertex
    /// colours (glTF COLOR_0) is declared once more per material it is shown with, with a
    /// texture per distinct colour: POV-Ray blends the three vertex textures of a triangle
    /// with its barycentric weights, which for textures differing only in a plain pigment is
    /// the linearly interpolated colour scadray shades with.
    void meshes() {
        if (usedMeshes_.empty()) return;
        os_ << "// Meshes\n";
        std::set<int> plain;  // meshes shown without vertex colours by some material
        for (const auto &pair : meshMaterials_)
            if (!colouredMeshes_.count(pair)) plain.insert(pair.first);
        for (int i : plain) {
            const ir::Mesh &m = *scene_.meshes[i];
            std::string note;
            if (!m.colors.empty())
                note =
                    "// scadray: the vertex colours of this mesh are left out where a material "
                    "with a base colour texture shows it (POV-Ray's mesh2 takes either)\n";
            mesh2(m, "Mesh_" + std::to_string(i), nullptr, note);
        }
        for (const auto &[i, mat] : colouredMeshes_)
            mesh2(*scene_.meshes[i], meshName(i, mat), &scene_.materials[mat], "");
        os_ << "\n";
    }

    /// One mesh2 declaration; with `coloured`, a texture_list of that material's colour times
    /// each distinct vertex colour (its finish kept) and a texture index per face corner.
    void mesh2(const ir::Mesh &m, const std::string &name, const ir::Material *coloured,
               const std::string &note) {
        std::vector<std::array<uint32_t, 3>> faces;
        for (const auto &t : m.triangles) {
            const Vec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
            if (lengthSquared(cross(b - a, c - a)) > 0) faces.push_back(t);  // POV drops the rest
        }
        os_ << comment(m.loc, "mesh '" + m.name + "'") << note << "#declare " << name
            << " = mesh2 {\n"
            << "    vertex_vectors {\n        " << m.positions.size();
        for (const Vec3 &p : m.positions) os_ << ",\n        " << vec(p);
        os_ << "\n    }\n";
        if (!m.normals.empty()) {
            os_ << "    normal_vectors {\n        " << m.normals.size();
            for (const Vec3 &n : m.normals) os_ << ",\n        " << vec(n);
            os_ << "\n    }\n";
        }
        std::string uvNote;
        const auto &uvs = exportedUvs(m, &uvNote);
        if (!uvs.empty()) {
            os_ << uvNote << "    uv_vectors {\n        " << uvs.size();
            for (const auto &uv : uvs)
                os_ << ",\n        <" << num(uv[0]) << ", " << num(1.0 - double(uv[1])) << ">";
            os_ << "\n    }\n";
        }
        // Vertex colours: one texture per distinct RGB (alpha is not used, as in the renderer)
        std::vector<uint32_t> textureOf;
        if (coloured) {
            std::map<std::array<float, 3>, uint32_t> index;
            std::vector<std::array<float, 3>> list;
            textureOf.resize(m.colors.size());
            for (size_t v = 0; v < m.colors.size(); ++v) {
                std::array<float, 3> c = {m.colors[v][0], m.colors[v][1], m.colors[v][2]};
                auto [it, isNew] = index.try_emplace(c, static_cast<uint32_t>(list.size()));
                if (isNew) list.push_back(c);
                textureOf[v] = it->second;
            }
            os_ << "    texture_list {\n        " << list.size();
            for (const auto &c : list) {
                Rgb col = coloured->color * Rgb(c[0], c[1], c[2]);
                os_ << ",\n        texture {\n    pigment { rgbft <" << num(col.r) << ", "
                    << num(col.g) << ", " << num(col.b) << ", " << num(coloured->filter) << ", "
                    << num(coloured->transmit) << "> }\n";
                os_ << finish(coloured->finish);
                os_ << "        }";
            }
            os_ << "\n    }\n";
        }
        os_ << "    face_indices {\n        " << faces.size();
        for (const auto &t : faces) {
            os_ << ",\n        <" << t[0] << ", " << t[1] << ", " << t[2] << ">";
            if (coloured)
                os_ << ", " << textureOf[t[0]] << ", " << textureOf[t[1]] << ", "
                    << textureOf[t[2]];
        }
        os_ << "\n    }\n";
        if (ir::analyzeMesh(m).closed())
            os_ << "    inside_vector <0.2718281828, 0.5772156649, 0.7071067811>\n";
        os_ << "}\n";
    }

    static std::string comment(const SourceLoc &loc, const std::string &what) {
        std::string w = where(loc);
        if (w.empty() && what.empty()) return "";
        return "// " + commentText(what + (what.empty() || w.empty() ? "" : ": ") + w) + "\n";
    }

    void line(int indent, const std::string &text) {
        os_ << std::string(4 * indent, ' ') << text << "\n";
    }

    std::string interior(const ir::Interior &in) {
        std::string s = "interior { ior " + num(in.ior);
        if (in.fadeDistance != 0)
            s += " fade_distance " + num(in.fadeDistance) + " fade_power " + num(in.fadePower) +
                 " fade_color " + rgb(in.fadeColor);
        return s + " }";
    }

    /// Top level: the same flattening as render::compile; each solid becomes one object.
    void topLevel(const ir::Node &n, const Mat4 &m) {
        switch (n.kind) {
            case ir::NodeKind::Group:
                for (const auto &c : n.children) topLevel(*c, m);
                return;
            case ir::NodeKind::Transform:
                for (const auto &c : n.children) topLevel(*c, m * n.matrix);
                return;
            default:
                break;
        }
        // One solid, with the interior of its first primitive
        const ir::Node *first = firstPrimitive(n);
        if (!first) return;
        solid(n, m, 0, interior(scene_.materials[first->material].interior), isTransparent(n));
        os_ << "\n";
    }

    bool isTransparent(const ir::Node &n) const {
        if (n.kind == ir::NodeKind::Primitive) return scene_.materials[n.material].isTransparent();
        for (const auto &c : n.children)
            if (isTransparent(*c)) return true;
        return false;
    }

    /// Writes a solid whose transform relative to its parent is `m`. `objectInterior` is set
    /// only on the top-level object, whose children share it. Unions of a transparent object
    /// are `merge` (no internal surfaces, which transparency would show); those of an opaque
    /// object stay `union`, because POV-Ray's merge also drops coplanar faces of touching
    /// solids, which OpenSCAD models are full of, while internal faces of an opaque solid are
    /// never the first surface a ray meets.
    void solid(const ir::Node &n, const Mat4 &m, int indent, const std::string &objectInterior,
               bool merge) {
        const ir::Node *cur = &n;
        Mat4 cm = m;
        while (passesThrough(*cur)) {
            if (cur->kind == ir::NodeKind::Transform) cm = cm * cur->matrix;
            cur = cur->children.front().get();
        }
        // A transform of several children is a union of them, placed by its matrix
        if (cur->kind == ir::NodeKind::Transform) cm = cm * cur->matrix;
        std::string tail;
        if (!objectInterior.empty())
            tail += "\n" + std::string(4 * (indent + 1), ' ') + objectInterior;
        if (!cm.isIdentity()) tail += "\n" + std::string(4 * (indent + 1), ' ') + transform(cm);
        if (cur->kind == ir::NodeKind::Primitive) {
            std::string shape;
            if (const auto *s = std::get_if<ir::SpherePrim>(&cur->shape))
                shape = "sphere { <0, 0, 0>, " + num(s->radius);
            else if (const auto *b = std::get_if<ir::BoxPrim>(&cur->shape))
                shape = "box { " + vec(b->min) + ", " + vec(b->max);
            else if (const auto *mp = std::get_if<ir::MeshPrim>(&cur->shape))
                shape = "object { " + meshName(mp->mesh, cur->material);
            else if (const auto *p = std::get_if<ir::PolytopePrim>(&cur->shape)) {
                // A convex polytope is exactly the intersection of its faces' half-spaces
                // (POV-Ray's plane is inside on the side opposite its normal), so it stays a
                // solid in CSG with no mesh parity tests
                shape = "intersection {";
                std::string pad(4 * (indent + 1), ' ');
                for (const auto &pl : meshing::polytopePlanes(*p))
                    shape +=
                        "\n" + pad + "plane { " + vec(pl.normal) + ", " + num(pl.offset) + " }";
                shape += "\n" + pad;
            } else if (const auto *pr = std::get_if<ir::PrismPrim>(&cur->shape))
                shape = prismShape(*pr);
            else if (std::holds_alternative<ir::TorusPrim>(cur->shape) ||
                     std::holds_alternative<ir::LathePrim>(cur->shape)) {
                shape = revolvedShape(cur->shape, std::string(4 * (indent + 1), ' '));
            } else {
                const auto &c = std::get<ir::CylinderPrim>(cur->shape);
                shape = "cone { <0, 0, " + num(c.z0) + ">, " + num(c.r1) + ", <0, 0, " + num(c.z1) +
                        ">, " + num(c.r2);
            }
            std::string w = where(cur->loc);
            line(indent, shape + "  texture { " + materialName(cur->material) + " }" + tail + " }" +
                             (w.empty() ? "" : "  // " + commentText(w)));
            return;
        }
        std::string op;
        switch (cur->kind) {
            case ir::NodeKind::Intersection:
                op = "intersection";
                break;
            case ir::NodeKind::Difference:
                op = "difference";
                break;
            default:
                op = merge ? "merge" : "union";
                break;
        }
        std::string w = where(cur->loc);
        line(indent, op + " {" + (w.empty() ? "" : "  // " + commentText(w)));
        for (const auto &c : cur->children) solid(*c, Mat4(), indent + 1, "", merge);
        if (!tail.empty()) os_ << tail.substr(1) << "\n";
        line(indent, "}");
    }

    const ir::Scene &scene_;
    std::string assetPrefix_;
    std::vector<TextureFile> *images_;
    std::set<int> used_, usedMeshes_;
    std::set<std::pair<int, int>> meshMaterials_;   ///< (mesh, material) pairs shown
    std::set<std::pair<int, int>> colouredMeshes_;  ///< those shown with vertex colours
    std::ostringstream os_;
};

}  // namespace

std::string writeSdl(const ir::Scene &scene, const std::string &sourceName,
                     std::vector<TextureFile> *textures, const std::string &assetPrefix) {
    return Writer(scene, assetPrefix, textures).run(sourceName);
}

void exportPov(const ir::Scene &scene, const std::string &povPath, const std::string &sourceName,
               IniOptions ini) {
    fs::path pov(povPath);
    std::vector<TextureFile> textures;
    std::string sdl = writeSdl(scene, sourceName, &textures, pov.stem().string());
    ini.povFile = pov.filename().string();
    fs::path dir = pov.has_parent_path() ? pov.parent_path() : fs::path(".");
    std::string iniText = writeIni(ini);
    // Every file is written under a temporary name first and all are renamed at the end, the
    // images before the .pov: a full disk or an error leaves none of them (and never a .pov
    // naming a missing image, nor textures without their .pov)
    std::vector<std::unique_ptr<TempFile>> staged;
    auto stage = [&](const fs::path &target) -> const std::string & {
        staged.push_back(std::make_unique<TempFile>(target.string(), target.extension().string()));
        return staged.back()->path();
    };
    for (const TextureFile &t : textures) {
        WriteOptions wo;
        wo.pngDepth = PngDepth::Bits16;
        wo.linearPng = true;
        // .exr (the environment) keeps values above 1 as float
        writeImage(t.image, stage(dir / t.fileName), wo);
    }
    writeTextFile(stage(pov), sdl);
    writeTextFile(stage(fs::path(pov).replace_extension(".ini")), iniText);
    for (auto &f : staged) f->commit();
}

std::string writeIni(const IniOptions &o) {
    // A newline in a file name would start a new option (Pre_Scene_Command=... runs a shell)
    for (const std::string *name : {&o.povFile, &o.outputFile})
        if (!iniSafe(*name))
            throw std::runtime_error(
                "the file name '" + commentText(*name) +
                "' has a control character, ';' or '\"', which cannot be written "
                "into a POV-Ray .ini file; choose another name");
    std::ostringstream os;
    os << "; scadray: render " << o.povFile << " headless, quietly and deterministically\n"
       << "Input_File_Name=" << iniValue(o.povFile) << "\n"
       << "Output_File_Name=" << iniValue(o.outputFile) << "\n"
       << "Width=" << o.width * o.supersample << "\n"
       << "Height=" << o.height * o.supersample << "\n"
       << "; No adaptive antialiasing: supersample by size and box-downsample instead\n"
       << "Antialias=Off\n"
       << "; 16-bit PNG with linear values, for comparisons\n"
       << "Output_File_Type=N\n"
       << "Bits_Per_Color=16\n"
       << "File_Gamma=1.0\n"
       << "Display=Off\n"
       << "Verbose=Off\n"
       << "Render_Console=Off\n"
       << "Pause_When_Done=Off\n";
    if (o.threads > 0) os << "Work_Threads=" << o.threads << "\n";
    return os.str();
}

void writeTextFile(const std::string &path, const std::string &text) {
    // Beside the target under a short name, renamed on success, removed on an interrupt
    TempFile tmp(path);
    {
        std::ofstream out(tmp.path(), std::ios::binary);
        out << text;
        out.flush();
        if (!out) throw std::runtime_error("cannot write '" + path + "'");
    }
    tmp.commit();
}

}  // namespace rt::pov
