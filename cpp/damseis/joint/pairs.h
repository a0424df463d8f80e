// The node pairs of contraction joints in a displacement space: every node
// (dof block) of a joint's side-2 facets with its coincident node on the
// side-1 facets, the local frame (n, t_a, t_b) of the pair and the joint's
// law. With P2 displacements the edge-midpoint nodes are pairs too, so the
// joint faces cannot interpenetrate between vertices. Same list, in the
// same order, on every rank (sorted by joint, then by z, x, y).
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cstdint>
#include <damseis/contact/alart_curnier.h>
#include <dolfinx/fem/FunctionSpace.h>
#include <dolfinx/mesh/MeshTags.h>
#include <petscmat.h>
#include <string>
#include <vector>

namespace damseis::joint
{
/// A joint: the facet tags of its two faces and its law.
struct JointSpec
{
  std::string label;  ///< "A", "B", ... or the user's name
  int tag_side1 = 0;  ///< facets of side 1 (the normal points away from it)
  int tag_side2 = 0;  ///< the coincident facets of side 2
  double mu = 1.0;    ///< friction coefficient (the paper: 1.0)
  bool keyed = false; ///< shear keys: no sliding, opening free
  /// A grouted (bonded) joint until it fails: tensile strength and
  /// cohesion [Pa] (0: none, the paper's joints).
  double tensile_strength = 0.0;
  double cohesion = 0.0;
  /// An open joint's gap at the start [m] (an ungrouted joint's shrinkage
  /// opening): the faces meet after closing by this much. 0 with a bond.
  double initial_gap = 0.0;
};

struct PairSet
{
  std::vector<JointSpec> joints;
  std::vector<int> joint;               ///< joint index of each pair
  std::vector<std::int64_t> block1;     ///< global block of the side-1 node
  std::vector<std::int64_t> block2;     ///< global block of the side-2 node
  std::vector<std::array<double, 3>> x; ///< pair coordinates
  /// Columns n (unit normal of side 1 into side 2, averaged over the
  /// side-1 facets at the node, area-weighted), t_a (the steepest-descent
  /// direction in the joint plane: vertical sliding), t_b = n x t_a.
  std::vector<Eigen::Matrix3d> frame;
  /// The side-1 face area the pair stands for [m2]: a third of its facets'
  /// areas (the lumped load of a uniform traction on P1 facets; with P2 the
  /// same once the midside pairs follow the vertex pairs).
  std::vector<double> area;
  /// Pairs at the midpoints of the faces' edges (P2): their edge's two end
  /// pairs (indices; -1 where the end is a single bonded node).
  std::vector<std::array<int, 2>> edge_ends;
  std::vector<bool> midside;
  std::size_t size() const { return joint.size(); }
  /// The law of pair i (friction, keys and bond of its joint; the bond's
  /// strengths times the pair's area).
  contact::PairLaw law(std::size_t i) const;
};

/// The subset of pairs `keep` (indices, ascending), edge ends renumbered
/// (-1 where an end was dropped).
PairSet subset(const PairSet& set, const std::vector<std::size_t>& keep);

/// P2 joints: the prolongation u = P u_r that makes the relative
/// displacement of each midside pair the mean of its edge's end pairs'
/// (u_2 = u_1 + ((u_2 - u_1)_end1 + (u_2 - u_1)_end2) / 2; a bonded end
/// counts 0). The gap is then linear along the face's edges, so contact at
/// the vertex pairs keeps the faces apart everywhere, as with linear
/// elements, while the bulk keeps P2. Collective; the caller owns P.
Mat midside_prolongation(const dolfinx::fem::FunctionSpace& V,
                         const PairSet& set);

/// The pairs of `joints` in the 3D vector space V (block size 3).
/// Collective. Nodes on both faces (where a joint meets bonded material)
/// are not pairs. Throws std::runtime_error if a side-2 node has no
/// coincident side-1 node (within `tol`) or a joint has no pairs.
PairSet joint_pairs(const dolfinx::fem::FunctionSpace& V,
                    const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags,
                    const std::vector<JointSpec>& joints, double tol = 1e-8);
} // namespace damseis::joint
