// Checks of a model read from the user's mesh file: degenerate cells, and
// joint surfaces given as two facet groups (duplicated nodes, matched node
// for node and facet for facet).
#pragma once

#include "gmsh_mesh.h"
#include <cstdint>
#include <string>
#include <vector>

namespace damseis::geometry
{
/// Number of cells (over all ranks) whose volume (area in 2D) is below
/// 1e-10 times the mean cell volume: flat or collapsed cells, on which
/// the element matrices are singular. Collective.
std::int64_t degenerate_cells(const Model& model);

/// Number of facets tagged `tag` (over all ranks) between two cells: where
/// an exterior-facet integral (a traction, the water pressure) finds
/// nothing. Collective.
std::int64_t interior_facets(const Model& model, int tag);

/// How the two sides of a joint match.
struct JointMatch
{
  /// "" if the sides match; otherwise what is wrong, in words naming the
  /// sides by `name1` and `name2` (the same text on every rank).
  std::string problem;
  std::int64_t pairs = 0;     ///< duplicated node pairs
  std::int64_t shared = 0;    ///< nodes on both sides (not split: bonded edge)
  double tolerance = 0.0;     ///< distance of coincident nodes used [m]
  std::vector<double> points; ///< the joint's distinct points (3 each)
};

/// Checks that the facets tagged `tag2` (side 2) and `tag1` (side 1) lie on
/// each other node for node (within `rel_tol` times the model's size) and
/// facet for facet, and that the joint is split (not every node shared).
/// Collective.
JointMatch match_joint_sides(const Model& model, int tag1, int tag2,
                             const std::string& name1, const std::string& name2,
                             double rel_tol = 1e-8);
/// Number of points two joints have in common (a node where joints meet
/// or cross: its three or four copies cannot be tied pairwise).
std::int64_t shared_joint_points(const JointMatch& a, const JointMatch& b);
} // namespace damseis::geometry
