// Envelopes (largest and smallest over time) of the normal stresses along
// given directions at given stress points: the arch and cantilever
// stresses on a dam face (face_directions.h). Tension positive.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace damseis::results
{
class DirectionEnvelope
{
public:
  /// `points`: owned stress points (indices into the stress layout of 6
  /// components sxx, syy, szz, sxy, syz, sxz per point); `directions`: per
  /// point two unit vectors (3 + 3).
  DirectionEnvelope(std::vector<std::int32_t> points,
                    std::vector<std::array<double, 6>> directions);

  /// Updates with the owned stress values `s` at time t.
  void update(std::span<const double> s, double t);

  const std::vector<std::int32_t>& points() const { return _points; }
  /// Per point and direction d (0, 1): largest and smallest normal stress
  /// and their times, index 2 * point + d.
  std::span<const double> max() const { return _max; }
  std::span<const double> min() const { return _min; }
  std::span<const double> max_times() const { return _t_max; }
  std::span<const double> min_times() const { return _t_min; }
  /// The values as a checkpoint keeps them (max, t_max, min, t_min).
  std::vector<double> state() const;
  void restore(std::span<const double> state);

private:
  std::vector<std::int32_t> _points;
  std::vector<std::array<double, 6>> _directions;
  std::vector<double> _max, _min, _t_max, _t_min;
};

/// The normal stress d^T sigma d of the 3D stress vector s (sxx, syy, szz,
/// sxy, syz, sxz) along the unit vector d.
double normal_stress(const double* s, const double* d);
} // namespace damseis::results
