// 3D arch dam + canyon + foundation block, built with the gmsh
// OpenCASCADE kernel, meshed with tetrahedra, split along the contraction
// joints and distributed as a DOLFINx mesh.
#pragma once

#include "arch_dam.h"
#include "gmsh_mesh.h"
#include "joints.h"

#include <cstdint>
#include <filesystem>
#include <mpi.h>
#include <vector>

namespace damseis::geometry
{
/// A distributed arch-dam model with its joints.
struct ArchModel
{
  /// Mesh, cell tags (tags::dam, tags::foundation) and facet tags.
  Model model;
  /// The joints ordered by label (= by x), with their node pairs; the
  /// same on every rank.
  std::vector<JointPairs> joints;
  std::int64_t num_cells = 0;     ///< tetrahedra (dam + foundation)
  std::int64_t num_dam_cells = 0; ///< tetrahedra of the dam
  std::int64_t num_nodes = 0;     ///< nodes, joint copies included
  double geometry_seconds = 0;    ///< OCC construction (rank 0)
  double mesh_seconds = 0;        ///< gmsh meshing (rank 0)
  double total_seconds = 0;       ///< whole build, distribution included
};

/// @brief Builds the dam, canyon and foundation on rank 0 with gmsh/OCC,
/// meshes them with linear tetrahedra, splits the joints and distributes
/// the mesh over `comm`.
///
/// Construction: the arch rings of `mesh.sections` elevations (from
/// 5 % of the height below the floor to the crest), each extending beyond
/// the canyon walls, are lofted (ThruSections) into an over-long dam
/// solid, intersected with the valley prism (the canyon cross-section
/// extruded along y) so that the dam fills the valley between its faces,
/// split by the joint planes (vertical planes through crest centre-line
/// points, normal to the crest arch) and fragmented with the foundation
/// (the box minus the valley) so that the interface is conforming. The
/// foundation top is at the crest elevation.
///
/// Facet tags (tags.h): upstream_face, downstream_face, crest, dam_base
/// (the whole dam-foundation interface: floor and abutments),
/// reservoir_floor (valley rock upstream of the dam), foundation_top_-
/// downstream (valley rock downstream), foundation_top (plateau),
/// foundation_bottom, foundation_sides (x ends), foundation_upstream,
/// foundation_downstream (y ends), joint_side1(k) / joint_side2(k).
/// With a water level (ArchMeshOptions::water_level, which the arch_dam
/// demo sets from reservoir.level) the dam is also cut at that elevation:
/// the mesh follows the water line, the upstream face below it is tagged
/// upstream_wetted and upstream_face keeps the dry part above it (the
/// forms load both tags).
/// Cell tags: dam, foundation (and foundation_band: with
/// ArchMeshOptions::band_layers the structured band of a transmitting
/// boundary, geometry/arch_band). Joint nodes are duplicated except on the
/// dam-foundation interface (see split_joints).
///
/// gmsh is initialised and finalised here on rank 0 (it must not be in
/// use by the caller). Collective on `comm`.
/// @param[in] comm Communicator.
/// @param[in] def The definition (validated; std::invalid_argument on all
/// ranks for impossible input).
/// @param[in] verbose gmsh terminal output.
/// @return The model and its joints.
/// @throws std::runtime_error on all ranks if gmsh fails.
ArchModel build_arch_dam(MPI_Comm comm, const ArchDamDefinition& def,
                         bool verbose = false);

/// @brief Writes the mesh, the cell tags ("cell_tags") and the facet tags
/// ("facet_tags") to an XDMF/HDF5 file pair (path.xdmf, path.h5).
/// Collective.
void write_model(const Model& model, const std::filesystem::path& path);
} // namespace damseis::geometry
