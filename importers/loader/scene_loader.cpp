// SPDX-License-Identifier: MIT
#include "importers/loader/scene_loader.h"

#include <cctype>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "core/image/environment_image.h"
#include "core/ir/scene_defaults.h"
#include "core/meshing/facets.h"
#include "core/system/input_file.h"
#include "importers/gltf/gltf_importer.h"
#include "importers/mesh/mesh_reader.h"

namespace rt {

namespace {

std::string lowerExtension(const std::string &path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (auto &ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    return ext;
}

/// The environment `-e` names; glTF models get the studio sky unless it says otherwise.
ir::Environment loadEnvironment(SceneFormat format, DiagnosticSink &diag, const LoadOptions &opts) {
    std::string name = opts.environment.empty() ? (format == SceneFormat::Gltf ? "studio" : "none")
                                                : opts.environment;
    ir::Environment env;
    if (name == "studio") {
        env = ir::studioEnvironment();
        env.rotateDegrees = opts.environmentRotate;
    } else if (name != "none") {
        try {
            requireRegularFile(name);
        } catch (const std::exception &e) {
            throw std::runtime_error(std::string("environment image (-e) ") + e.what());
        }
        env = loadEnvironmentImage(name, opts.environmentRotate, diag);
    }
    return env;
}

ir::Scene importScad(const std::string &path, DiagnosticSink &diag, const LoadOptions &opts) {
    scad::ImportOptions io;
    io.libraryPaths = opts.libraryPaths;
    io.defines = opts.defines;
    io.maxSteps = opts.maxSteps;
    io.maxElements = opts.maxElements;
    io.maxGeometry = opts.maxGeometry;
    io.time = opts.time;
    io.progress = opts.progress;
    struct DoneAtEnd {
        const std::function<void()> &done;
        ~DoneAtEnd() {
            if (done) done();
        }
    } doneAtEnd{opts.progressDone};
    return scad::importScad(path, diag, io);
}

/// A bare mesh file: one mesh in OpenSCAD's default colour; a file without triangles is an
/// empty scene, as an empty .scad is.
ir::Scene importMesh(const std::string &path, DiagnosticSink &diag) {
    ir::Scene scene;
    auto mesh = std::make_shared<ir::Mesh>(meshio::readMeshFile(path, diag));
    if (!mesh->triangles.empty()) {
        scene.meshes.push_back(mesh);
        scene.root->children.push_back(
            ir::Node::makePrimitive(ir::MeshPrim{0}, scene.addMaterial(ir::Material()), mesh->loc));
    }
    return scene;
}

}  // namespace

std::optional<SceneFormat> sceneFormat(const std::string &path) {
    std::string ext = lowerExtension(path);
    if (ext == ".scad") return SceneFormat::Scad;
    if (ext == ".gltf" || ext == ".glb") return SceneFormat::Gltf;
    if (ext == ".stl" || ext == ".off") return SceneFormat::Mesh;
    return std::nullopt;
}

ir::Scene loadScene(const std::string &path, DiagnosticSink &diag, const LoadOptions &opts) {
    // Checked before anything opens it: a FIFO would block, /dev/zero never end
    requireRegularFile(path);
    std::optional<SceneFormat> format = sceneFormat(path);
    if (!format)
        throw std::runtime_error(path + ": unknown scene type '" + lowerExtension(path) +
                                 "' (scadray reads .scad, .gltf, .glb, .stl and .off)");
    ir::Environment env = loadEnvironment(*format, diag, opts);
    ir::Scene scene;
    switch (*format) {
        case SceneFormat::Scad:
            scene = importScad(path, diag, opts);
            break;
        case SceneFormat::Gltf:
            scene = gltf::importGltf(path, diag);
            break;
        case SceneFormat::Mesh:
            scene = importMesh(path, diag);
            break;
    }
    scene.settings.environment = std::move(env);
    // Facets first: the automatic camera frames the solids as they will be drawn
    meshing::applyFacets(scene, opts.facets, diag);
    ir::CompleteOptions co;
    co.framing = *format == SceneFormat::Scad ? ir::Framing::OpenScad : ir::Framing::Viewer;
    co.aspect = opts.aspect;
    ir::completeScene(scene, diag, co);
    return scene;
}

}  // namespace rt
