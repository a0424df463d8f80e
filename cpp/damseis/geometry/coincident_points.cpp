#include "coincident_points.h"
#include <algorithm>
#include <cmath>
#include <numeric>

namespace damseis::geometry
{
CoincidentPoints::CoincidentPoints(
    std::size_t n,
    const std::function<std::array<double, 3>(std::size_t)>& point, double tol)
    : _tol(tol)
{
  std::vector<std::array<double, 3>> x(n);
  for (std::size_t i = 0; i < n; ++i)
    x[i] = point(i);
  _index.resize(n);
  std::iota(_index.begin(), _index.end(), 0);
  std::sort(_index.begin(), _index.end(),
            [&](std::size_t a, std::size_t b) { return x[a][0] < x[b][0]; });
  _x.reserve(n);
  for (std::size_t i : _index)
    _x.push_back(x[i]);
}

std::int64_t CoincidentPoints::find(const double* p) const
{
  auto it = std::lower_bound(_x.begin(), _x.end(), p[0] - _tol,
                             [](const std::array<double, 3>& q, double v)
                             { return q[0] < v; });
  for (; it != _x.end() && (*it)[0] <= p[0] + _tol; ++it)
  {
    const auto& q = *it;
    if (std::hypot(q[0] - p[0], q[1] - p[1], q[2] - p[2]) <= _tol)
      return static_cast<std::int64_t>(_index[it - _x.begin()]);
  }
  return -1;
}
} // namespace damseis::geometry
