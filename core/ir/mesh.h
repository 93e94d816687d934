// SPDX-License-Identifier: MIT
// IR triangle meshes and textures, shared between the nodes that place them (instancing).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/ir/source_loc.h"
#include "core/math/bounds3.h"
#include "core/math/vec3.h"

namespace rt::ir {

/// An indexed triangle mesh in its own (object) coordinates.
struct Mesh {
    std::vector<Vec3> positions;
    /// Empty, or one unit normal per position (smooth shading).
    std::vector<Vec3> normals;
    /// Empty, or one texture coordinate per position; (0,0) is the top-left of the image, as in
    /// glTF.
    std::vector<std::array<float, 2>> uvs;
    /// Empty, or a second texture coordinate set per position (glTF TEXCOORD_1).
    std::vector<std::array<float, 2>> uvs1;
    /// Empty, or one tangent per position: xyz a unit vector along +u of `uvs`, w = +1 or -1,
    /// the handedness of the bitangent (glTF TANGENT: bitangent = cross(normal, tangent) * w).
    std::vector<std::array<float, 4>> tangents;
    /// Empty, or one linear RGBA colour per position (glTF COLOR_0; alpha 1 for vec3 colours),
    /// multiplying the material's base colour.
    std::vector<std::array<float, 4>> colors;
    /// Vertex indices, counter-clockwise seen from outside (the outward normal is
    /// (p1 - p0) x (p2 - p0)).
    std::vector<std::array<uint32_t, 3>> triangles;
    std::string name;
    SourceLoc loc;

    Bounds3 bounds() const;
};

using MeshPtr = std::shared_ptr<const Mesh>;

/// How the edges of a mesh are shared, which decides whether it bounds a solid. Vertices at
/// exactly the same position count as one, so split vertices do not open a mesh.
struct MeshTopology {
    size_t boundaryEdges = 0;        ///< edges used by one triangle (holes)
    size_t nonManifoldEdges = 0;     ///< edges used by more than two triangles
    size_t misorientedEdges = 0;     ///< edges whose two triangles traverse it the same way
    size_t degenerateTriangles = 0;  ///< repeated indices or zero area

    /// Every edge shared by exactly two triangles: the mesh bounds a solid (inside by parity).
    bool closed() const { return boundaryEdges == 0 && nonManifoldEdges == 0; }
    /// Closed and consistently oriented (inside by winding number).
    bool oriented() const { return closed() && misorientedEdges == 0; }
};

MeshTopology analyzeMesh(const Mesh &mesh);

/// Throws SceneError at mesh.loc for indices out of range or non-finite positions, normals or
/// texture coordinates.
void validateMesh(const Mesh &mesh);

/// An RGBA image in linear float, row 0 at the top, for base-colour textures.
struct Texture {
    int width = 0, height = 0;
    std::vector<float> rgba;  ///< 4 floats per pixel, linear (sRGB already decoded)
    /// What lies outside [0,1] along an axis (glTF sampler wrapS / wrapT).
    enum class Wrap { Repeat, ClampToEdge, MirroredRepeat };
    Wrap wrapU = Wrap::Repeat, wrapV = Wrap::Repeat;
    /// Texel lookup (glTF magFilter; there are no mipmaps, so minification filters the same
    /// way): bilinear between the four nearest texels, or the texel under the point.
    bool nearest = false;
    std::string name;  ///< for file names in exports
    SourceLoc loc;
};

using TexturePtr = std::shared_ptr<const Texture>;

/// The mean of each channel (R, G, B, A) over every texel of `t`, summed in texel order; 1
/// for an image without texels (a neutral factor). What the POV-Ray export and `check` use
/// for a map the classic material cannot express per texel.
std::array<double, 4> textureMean(const Texture &t);

}  // namespace rt::ir
