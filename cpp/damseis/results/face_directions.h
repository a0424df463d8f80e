// The arch and cantilever directions of a dam face at its stress points:
// the arch direction is horizontal in the face (t = e_z x n, normalised),
// the cantilever direction lies in the face across it (c = n x t, mostly
// vertical), n the face's unit normal at the point (the area-weighted mean
// of the normals of the face's facets touching it). The normal stresses
// along them are the arch and cantilever stresses arch-dam design reads.
#pragma once

#include <array>
#include <cstdint>
#include <dolfinx/fem/FunctionSpace.h>
#include <dolfinx/mesh/MeshTags.h>
#include <vector>

namespace damseis::results
{
/// Per point of `points` (owned points of the stress space S on the facets
/// tagged with `tags`, as results::face_points gives them): the arch
/// direction (3) then the cantilever direction (3). Where the face is
/// horizontal (no arch direction), t = e_x. 3D only.
std::vector<std::array<double, 6>> arch_cantilever_directions(
    const dolfinx::fem::FunctionSpace& S,
    const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags,
    const std::vector<int>& tags, const std::vector<std::int32_t>& points);
} // namespace damseis::results
