// A distributed DOLFINx model (mesh, cell tags, facet tags) from plain mesh
// arrays held by rank 0: the step after split_joints (joints.h), for
// meshes that do not come from the arch-dam builder (tests, other shapes).
#pragma once

#include "gmsh_mesh.h"

#include <cstdint>
#include <mpi.h>
#include <span>

namespace damseis::geometry
{
/// @brief Creates a distributed tetrahedral Model from mesh arrays.
///
/// The arrays are significant on rank 0 only (the other ranks pass empty
/// spans): node coordinates `x` (n, 3) row-major, linear tetrahedra
/// `cells` (4 node indices each, DOLFINx node order, 0-based rows of `x`)
/// with their region `cell_values`, and triangles `facets` (3 node indices
/// each) with their tag `facet_values` (tags.h). Node indices become the
/// mesh's input global indices (`geometry().input_global_indices()`), so
/// JointPairs from split_joints refer to them. P1 geometry, gdim 3, ghost
/// mode shared_facet, connectivities (3, 0), (2, 0) and (2, 3) created.
/// Collective.
Model model_from_arrays(MPI_Comm comm, std::span<const double> x,
                        std::span<const std::int64_t> cells,
                        std::span<const std::int32_t> cell_values,
                        std::span<const std::int64_t> facets,
                        std::span<const std::int32_t> facet_values);
} // namespace damseis::geometry
