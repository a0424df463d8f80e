// Envelopes over time of the largest and smallest principal stress at every
// stress point of the model.
#pragma once

#include <array>
#include <dolfinx/fem/FunctionSpace.h>
#include <mpi.h>
#include <span>
#include <vector>

namespace damseis::results
{
/// A value with where and when it occurred.
struct Extreme
{
  double value = 0.0;
  std::array<double, 3> x = {0, 0, 0};
  double t = 0.0;
};

/// The extreme of `v` (largest if `sign` = 1, smallest if -1) over the
/// `candidates` (indices into v, t, x) of all ranks, with its location and
/// time. Collective.
Extreme global_extreme(MPI_Comm comm, const std::vector<double>& v,
                       const std::vector<double>& t,
                       const std::vector<std::array<double, 3>>& x,
                       const std::vector<std::int32_t>& candidates,
                       double sign);

/// Tracks, per owned stress point, the maximum of the largest principal
/// stress (tension) and the minimum of the smallest (compression), with the
/// times they occurred.
class StressEnvelope
{
public:
  /// @param[in] S stress-point space (blocked by the number of components)
  /// @param[in] region_cells the local cells whose points are tracked (e.g.
  /// the dam's); a rank may own none of them: it then tracks no point.
  /// (An empty list once meant "every cell": a rank without dam cells then
  /// reported the foundation's extremes on 2 ranks.)
  StressEnvelope(const dolfinx::fem::FunctionSpace& S,
                 std::span<const std::int32_t> region_cells);
  /// Points given explicitly (e.g. quadrature points, whose space cannot
  /// tabulate coordinates): `ncomp` stress components per point, the
  /// coordinates `x` (3 per owned point) and a region flag per owned point.
  StressEnvelope(int ncomp, std::span<const double> x,
                 std::vector<std::int8_t> in_region);

  /// Updates with the owned stress values `s` (layout of S, owned part).
  void update(std::span<const double> s, double t);

  /// Extreme tension (largest max principal) over the region; collective.
  Extreme max_tension(MPI_Comm comm) const;
  /// Extreme compression (most negative min principal) over the region;
  /// collective.
  Extreme max_compression(MPI_Comm comm) const;
  /// The same over the owned points listed in `subset` (a rank may list
  /// none); collective.
  Extreme max_tension(MPI_Comm comm,
                      std::span<const std::int32_t> subset) const;
  Extreme max_compression(MPI_Comm comm,
                          std::span<const std::int32_t> subset) const;
  /// The owned points of the region.
  std::vector<std::int32_t> region_points() const;
  /// Coordinates of owned point i.
  const std::array<double, 3>& point(std::int32_t i) const { return _x[i]; }

  /// Per owned point: envelope values (+-infinity outside the region).
  std::span<const double> max_principal() const { return _max; }
  std::span<const double> min_principal() const { return _min; }
  std::span<const double> max_times() const { return _t_max; }
  std::span<const double> min_times() const { return _t_min; }

  /// Restores envelope values and times (e.g. from a checkpoint); the
  /// arrays hold the owned points in order.
  void restore(std::span<const double> max, std::span<const double> t_max,
               std::span<const double> min, std::span<const double> t_min);
  int components() const { return _ncomp; }

private:
  /// Sets the points outside the region to 0 (see the .cpp).
  void finite_outside_region();
  int _ncomp;
  std::vector<double> _max, _min, _t_max, _t_min;
  std::vector<std::array<double, 3>> _x;
  std::vector<std::int8_t> _in_region;
};
} // namespace damseis::results
