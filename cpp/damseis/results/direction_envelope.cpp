#include "direction_envelope.h"
#include <limits>
#include <stdexcept>

namespace damseis::results
{
double normal_stress(const double* s, const double* d)
{
  return s[0] * d[0] * d[0] + s[1] * d[1] * d[1] + s[2] * d[2] * d[2] +
         2.0 * (s[3] * d[0] * d[1] + s[4] * d[1] * d[2] + s[5] * d[0] * d[2]);
}

DirectionEnvelope::DirectionEnvelope(
    std::vector<std::int32_t> points,
    std::vector<std::array<double, 6>> directions)
    : _points(std::move(points)), _directions(std::move(directions))
{
  if (_points.size() != _directions.size())
    throw std::invalid_argument("DirectionEnvelope: one pair of directions "
                                "per point");
  const std::size_t n = 2 * _points.size();
  _max.assign(n, -std::numeric_limits<double>::infinity());
  _min.assign(n, std::numeric_limits<double>::infinity());
  _t_max.assign(n, 0.0);
  _t_min.assign(n, 0.0);
}

void DirectionEnvelope::update(std::span<const double> s, double t)
{
  for (std::size_t i = 0; i < _points.size(); ++i)
  {
    const double* si = s.data() + 6 * static_cast<std::size_t>(_points[i]);
    for (int d = 0; d < 2; ++d)
    {
      const double v = normal_stress(si, _directions[i].data() + 3 * d);
      const std::size_t k = 2 * i + d;
      if (v > _max[k])
      {
        _max[k] = v;
        _t_max[k] = t;
      }
      if (v < _min[k])
      {
        _min[k] = v;
        _t_min[k] = t;
      }
    }
  }
}

std::vector<double> DirectionEnvelope::state() const
{
  std::vector<double> out;
  for (const auto* v : {&_max, &_t_max, &_min, &_t_min})
    out.insert(out.end(), v->begin(), v->end());
  return out;
}

void DirectionEnvelope::restore(std::span<const double> state)
{
  const std::size_t n = _max.size();
  if (state.size() != 4 * n)
    throw std::runtime_error("checkpoint: the arch and cantilever envelope "
                             "has the wrong size");
  std::size_t o = 0;
  for (auto* v : {&_max, &_t_max, &_min, &_t_min})
  {
    v->assign(state.begin() + o, state.begin() + o + n);
    o += n;
  }
}
} // namespace damseis::results
