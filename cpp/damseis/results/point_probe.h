// Displacement history at a point: the mesh node nearest to it.
#pragma once

#include <array>
#include <dolfinx/fem/FunctionSpace.h>
#include <petscvec.h>
#include <vector>

namespace damseis::results
{
/// Finds the node of V nearest to `x` (over all ranks) and records its
/// displacement components on the owning rank.
class PointProbe
{
public:
  PointProbe(const dolfinx::fem::FunctionSpace& V, std::array<double, 3> x);
  /// Where the probe actually is (the node's coordinates).
  const std::array<double, 3>& node() const { return _node; }
  /// True on the rank that owns the node (and records its values).
  bool owned() const { return _local >= 0; }
  /// Distance from the requested point to the node [m].
  double distance() const { return _distance; }
  /// Values of the node's components in `u` (owner rank; 0 elsewhere).
  std::array<double, 3> value(Vec u) const;
  /// Values of the node's components in `u` on every rank (collective).
  std::array<double, 3> value_on_all(Vec u) const;

private:
  int _bs = 0;
  std::int32_t _local = -1; ///< owned block index, -1 if not on this rank
  std::array<double, 3> _node = {0, 0, 0};
  double _distance = 0.0;
};

/// Sums per-rank histories (zeros off the owner) onto every rank.
void reduce_history(MPI_Comm comm, std::vector<double>& history);
} // namespace damseis::results
