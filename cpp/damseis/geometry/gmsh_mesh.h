// Conversion of a gmsh model (held by rank 0) into a distributed DOLFINx
// mesh with region (cell) and boundary (facet) tags.
#pragma once

#include <cstdint>
#include <memory>
#include <mpi.h>

#include <dolfinx/mesh/Mesh.h>
#include <dolfinx/mesh/MeshTags.h>

namespace damseis::geometry
{
/// A distributed mesh with its region (cell) and boundary (facet) tags
/// (values from tags.h).
struct Model
{
  /// The distributed mesh (P1 geometry, gdim = tdim).
  std::shared_ptr<dolfinx::mesh::Mesh> mesh;
  /// Region tags on cells (owned and ghost cells).
  std::shared_ptr<dolfinx::mesh::MeshTags<std::int32_t>> cell_tags;
  /// Boundary/interface tags on facets (owned and ghost facets).
  std::shared_ptr<dolfinx::mesh::MeshTags<std::int32_t>> facet_tags;
};

/// @brief Converts the gmsh model currently open on rank 0 into a
/// distributed DOLFINx mesh with cell and facet tags.
///
/// Physical groups of dimension `tdim` become cell tags and physical
/// groups of dimension `tdim - 1` become facet tags; the physical tag
/// number is the tag value. Only cells belonging to a physical group of
/// dimension `tdim` enter the mesh. The mesh has P1 geometry, gdim =
/// tdim (a 2D mesh has 2 coordinates per node; its gmsh z coordinates
/// must be zero) and ghost mode shared_facet. Linear triangles (tdim 2)
/// and tetrahedra (tdim 3) are supported.
///
/// Collective on `comm`: rank 0 must have gmsh initialised with a meshed
/// model open; the other ranks do not touch gmsh. Errors detected on
/// rank 0 (wrong element types, an element in two physical groups, no
/// cells, ...) are thrown on every rank (std::runtime_error).
///
/// @param[in] comm Communicator over which the mesh is distributed.
/// @param[in] tdim Topological dimension (2 or 3), same on all ranks.
/// @return The mesh with its cell and facet tags.
Model model_from_gmsh(MPI_Comm comm, int tdim);
} // namespace damseis::geometry
