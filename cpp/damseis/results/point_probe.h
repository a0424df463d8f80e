// Displacement history at a point: the mesh node nearest to it.
#pragma once

#include <array>
#include <dolfinx/fem/FunctionSpace.h>
#include <petscvec.h>
#include <vector>

namespace damseis::results
{
/// Finds the node of V nearest to `x` (over all ranks) and records its
/// displacement components on the owning rank. Where several nodes
/// coincide there (a joint's two faces), the probe is their mean (on each
/// owning rank its part of the mean: sums over the ranks give it).
class PointProbe
{
public:
  PointProbe(const dolfinx::fem::FunctionSpace& V, std::array<double, 3> x);
  /// Where the probe actually is (the node's coordinates).
  const std::array<double, 3>& node() const { return _node; }
  /// This rank's share of the probe: 1 on the owner of a single node, the
  /// fraction of the coincident nodes it owns, 0 elsewhere (sums to 1).
  double share() const { return static_cast<double>(_local.size()) / _count; }
  /// Distance from the requested point to the node [m].
  double distance() const { return _distance; }
  /// Values of the node's components in `u` (owner rank, or this rank's
  /// part of the mean of coincident nodes; 0 elsewhere).
  std::array<double, 3> value(Vec u) const;
  /// Values of the node's components in `u` on every rank (collective).
  std::array<double, 3> value_on_all(Vec u) const;

private:
  int _bs = 0;
  std::vector<std::int32_t> _local; ///< owned block indices (coincident)
  int _count = 1;                   ///< coincident nodes over all ranks
  std::array<double, 3> _node = {0, 0, 0};
  double _distance = 0.0;
};

/// Sums per-rank histories (zeros off the owner) onto every rank.
void reduce_history(MPI_Comm comm, std::vector<double>& history);
} // namespace damseis::results
