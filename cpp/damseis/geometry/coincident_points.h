// The point of a fixed set that coincides with a query point, within a
// tolerance: the partner of a node across a joint or a tie. The points are
// sorted by x once; a query searches the window x +- tol.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace damseis::geometry
{
class CoincidentPoints
{
public:
  /// The `n` points point(0), ..., point(n - 1).
  CoincidentPoints(
      std::size_t n,
      const std::function<std::array<double, 3>(std::size_t)>& point,
      double tol);
  /// The index of a point within tol of p (the first by x), -1 if none.
  std::int64_t find(const double* p) const;

private:
  std::vector<std::array<double, 3>> _x; ///< sorted by x
  std::vector<std::size_t> _index;       ///< the given index of each
  double _tol;
};
} // namespace damseis::geometry
