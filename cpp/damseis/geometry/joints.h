// Contraction joints with duplicated nodes: splitting a conforming
// tetrahedral mesh along joint planes (rank 0, before the mesh is
// distributed) and the node-pair lists a contact solver uses.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <dolfinx/mesh/Mesh.h>
#include <mpi.h>

namespace damseis::geometry
{
/// @brief The node pairs of one joint (same on every rank).
///
/// Pair i is (side-1 node a_i, side-2 node b_i), two coincident nodes;
/// side 1 is the block on the left of the joint (smaller x), side 2 the
/// block its normal points into. Node indices are the *input* indices of
/// the mesh nodes (the rows of the node array given to create_mesh), i.e.
/// the values of `mesh.geometry().input_global_indices()`; use
/// local_geometry_nodes() / local_vertices() to find them on a rank.
/// Nodes on the dam-foundation interface are not split (the joint is
/// bonded along its foot) and have no pair.
struct JointPairs
{
  int label_index = 0; ///< 0 for joint 'A', 1 for 'B', ...
  char label = 'A';
  int tag_side1 = 0; ///< facet tag of the side-1 face (tags::joint_side1)
  int tag_side2 = 0; ///< facet tag of the side-2 face
  std::array<double, 3> plane_point{};  ///< a point of the joint plane
  std::array<double, 3> plane_normal{}; ///< unit normal, side 1 -> side 2
  std::vector<std::int64_t> node1;      ///< side-1 input node indices
  std::vector<std::int64_t> node2;      ///< side-2 input node indices
  std::vector<double> x;                ///< pair coordinates, row-major (n, 3)
  std::vector<double> normal;           ///< area-weighted unit normals (n, 3),
                                        ///< side 1 -> side 2
  std::vector<double> area; ///< tributary area (1/3 of adjacent facets)
  std::size_t size() const { return node1.size(); }
};

/// A joint to split: plane and facet tags.
struct JointSplitSpec
{
  int label_index = 0;
  char label = 'A';
  std::array<double, 3> point{};
  std::array<double, 3> normal{}; ///< unit, from side 1 into side 2
  int tag_side1 = 0; ///< tag of the joint facets (input); side 1 after
  int tag_side2 = 0; ///< tag given to the side-2 copies of the facets
};

/// @brief Duplicates the nodes of joint facets (serial, on mesh arrays).
///
/// For each joint, the joint nodes are the nodes of the facets tagged
/// `tag_side1`, except the nodes of facets tagged `bonded_tag` (the
/// dam-foundation interface, which stays continuous). Every joint node
/// gets a copy appended to `x`; cells with region `split_region` that
/// contain a joint node and whose centroid is on the positive side of the
/// joint plane (side 2) are renumbered to the copies, and so are the
/// tagged facets on that side. The joint facets stay on side 1 and a
/// copy of each (on the copies, tag `tag_side2`) is appended.
///
/// @param[in,out] x Node coordinates (n, 3), row-major.
/// @param[in,out] cells Tetrahedra (4 node indices each).
/// @param[in] cell_values Region of each cell.
/// @param[in,out] facets Triangles (3 node indices each).
/// @param[in,out] facet_values Tag of each triangle.
/// @param[in] joints The joints.
/// @param[in] split_region Region of the cells that are split (the dam).
/// @param[in] bonded_tag Facet tag whose nodes are never split.
/// @return The pairs of each joint, in the order of `joints`.
/// @throws std::runtime_error if a joint has no facets or a cell would
/// touch a joint node while lying on the plane.
std::vector<JointPairs> split_joints(std::vector<double>& x,
                                     std::vector<std::int64_t>& cells,
                                     std::span<const std::int32_t> cell_values,
                                     std::vector<std::int64_t>& facets,
                                     std::vector<std::int32_t>& facet_values,
                                     std::span<const JointSplitSpec> joints,
                                     int split_region, int bonded_tag);

/// @brief The jointless model of the same mesh arrays: removes the joint
/// facets (tags::is_joint_tag) from the tagged facets, which leaves them
/// interior and untagged (serial, on mesh arrays; before split_joints).
/// @param[in,out] facets Triangles (3 node indices each).
/// @param[in,out] facet_values Tag of each triangle.
void untag_joint_facets(std::vector<std::int64_t>& facets,
                        std::vector<std::int32_t>& facet_values);

/// @brief Local geometry node index of each input node index (owned or
/// ghost on this rank), -1 where the node is not on this rank.
std::vector<std::int32_t>
local_geometry_nodes(const dolfinx::mesh::Mesh& mesh,
                     std::span<const std::int64_t> input_indices);

/// @brief Local vertex index (topology, dimension 0) of each input node
/// index, -1 where the node is not on this rank (P1 geometry).
std::vector<std::int32_t>
local_vertices(const dolfinx::mesh::Mesh& mesh,
               std::span<const std::int64_t> input_indices);

/// @brief Broadcasts pair lists from rank 0 to all ranks of `comm`.
void broadcast_joint_pairs(MPI_Comm comm, std::vector<JointPairs>& joints);
} // namespace damseis::geometry
