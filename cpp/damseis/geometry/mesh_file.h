// A model from the user's mesh file: a gmsh .msh file with physical groups
// (the cells of the top dimension's groups, the facets of the groups one
// dimension below), distributed over the ranks.
#pragma once

#include "gmsh_mesh.h"
#include <filesystem>
#include <map>
#include <mpi.h>
#include <string>

namespace damseis::geometry
{
/// A physical group of the file: its dimension and tag (the value it has
/// in the model's cell or facet tags).
struct PhysicalGroup
{
  int dim = 0;
  int tag = 0;
};

/// The model of a mesh file and its named physical groups.
struct MeshFile
{
  Model model;
  int tdim = 0; ///< 2 (triangles, z = 0) or 3 (tetrahedra)
  /// Physical groups by name (groups without a name: "<dim>:<tag>").
  std::map<std::string, PhysicalGroup> groups;
};

/// The grids of an XDMF mesh file: the mesh and its cell and facet tags.
struct XdmfGrids
{
  std::string mesh = "mesh";
  std::string cell_tags = "cell_tags";
  std::string facet_tags = "facet_tags";
};

/// Reads a mesh file and distributes it. Collective. Throws
/// std::runtime_error, the same on every rank, for a missing or unreadable
/// file, no groups, or elements the model does not take.
///  - gmsh (.msh, format 2 or 4), read on rank 0 (model_from_gmsh): the
///    topological dimension is the highest one with a physical group;
///    groups by their names.
///  - XDMF (.xdmf, as DOLFINx writes it), read in parallel: linear
///    triangles with 2 coordinates or tetrahedra, the cell and facet tags
///    in the grids `grids` names; a tag value v is the group "<dim>:<v>"
///    (the name gmsh gives an unnamed group).
MeshFile read_mesh_file(MPI_Comm comm, const std::filesystem::path& file,
                        const XdmfGrids& grids = {});
} // namespace damseis::geometry
