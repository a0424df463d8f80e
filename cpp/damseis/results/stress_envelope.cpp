#include "stress_envelope.h"
#include "principal.h"
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>
#include <limits>
#include <stdexcept>
#include <string>

namespace damseis::results
{
StressEnvelope::StressEnvelope(const dolfinx::fem::FunctionSpace& S,
                               std::span<const std::int32_t> region_cells)
{
  const auto& dofmap = *S.dofmap();
  _ncomp = dofmap.index_map_bs();
  const std::int32_t n = dofmap.index_map->size_local();
  _max.assign(n, -std::numeric_limits<double>::infinity());
  _min.assign(n, std::numeric_limits<double>::infinity());
  _t_max.assign(n, 0.0);
  _t_min.assign(n, 0.0);
  const std::vector<double> x = S.tabulate_dof_coordinates(false);
  _x.resize(n);
  for (std::int32_t i = 0; i < n; ++i)
    _x[i] = {x[3 * i], x[3 * i + 1], x[3 * i + 2]};
  _in_region.assign(n, 0);
  for (std::int32_t c : region_cells)
  {
    for (std::int32_t d : dofmap.cell_dofs(c))
    {
      if (d < n)
        _in_region[d] = 1;
    }
  }
  finite_outside_region();
}

void StressEnvelope::finite_outside_region()
{
  // Points outside the region are never updated nor read; 0 rather than
  // the +-infinity the tracked points start from, so that a checkpoint
  // (which takes non-finite values for damage) can hold the envelope.
  for (std::size_t i = 0; i < _in_region.size(); ++i)
  {
    if (!_in_region[i])
      _max[i] = _min[i] = 0.0;
  }
}

StressEnvelope::StressEnvelope(int ncomp, std::span<const double> x,
                               std::vector<std::int8_t> in_region)
    : _ncomp(ncomp), _in_region(std::move(in_region))
{
  const std::size_t n = _in_region.size();
  _max.assign(n, -std::numeric_limits<double>::infinity());
  _min.assign(n, std::numeric_limits<double>::infinity());
  _t_max.assign(n, 0.0);
  _t_min.assign(n, 0.0);
  _x.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    _x[i] = {x[3 * i], x[3 * i + 1], x[3 * i + 2]};
  finite_outside_region();
}

void StressEnvelope::update(std::span<const double> s, double t)
{
  const std::size_t n = _max.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    if (!_in_region[i])
      continue;
    const auto [p1, p3] = principal_extremes(s.data() + i * _ncomp, _ncomp);
    if (p1 > _max[i])
    {
      _max[i] = p1;
      _t_max[i] = t;
    }
    if (p3 < _min[i])
    {
      _min[i] = p3;
      _t_min[i] = t;
    }
  }
}

void StressEnvelope::restore(std::span<const double> max,
                             std::span<const double> t_max,
                             std::span<const double> min,
                             std::span<const double> t_min)
{
  for (std::size_t n : {max.size(), t_max.size(), min.size(), t_min.size()})
  {
    if (n != _max.size())
      throw std::runtime_error("stress envelope of " + std::to_string(n) +
                               " points, expected " +
                               std::to_string(_max.size()));
  }
  std::copy(max.begin(), max.end(), _max.begin());
  std::copy(t_max.begin(), t_max.end(), _t_max.begin());
  std::copy(min.begin(), min.end(), _min.begin());
  std::copy(t_min.begin(), t_min.end(), _t_min.begin());
}

Extreme global_extreme(MPI_Comm comm, const std::vector<double>& v,
                       const std::vector<double>& t,
                       const std::vector<std::array<double, 3>>& x,
                       const std::vector<std::int32_t>& candidates, double sign)
{
  struct
  {
    double value;
    int rank;
  } local{-std::numeric_limits<double>::infinity(), 0}, global;
  MPI_Comm_rank(comm, &local.rank);
  std::int32_t best = -1;
  for (std::int32_t i : candidates)
  {
    if (sign * v[i] > local.value)
    {
      local.value = sign * v[i];
      best = i;
    }
  }
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm);
  std::array<double, 5> data = {0, 0, 0, 0, 0};
  if (global.rank == local.rank && best >= 0)
    data = {v[best], x[best][0], x[best][1], x[best][2], t[best]};
  MPI_Bcast(data.data(), 5, MPI_DOUBLE, global.rank, comm);
  return {data[0], {data[1], data[2], data[3]}, data[4]};
}

std::vector<std::int32_t> StressEnvelope::region_points() const
{
  std::vector<std::int32_t> c;
  for (std::size_t i = 0; i < _in_region.size(); ++i)
  {
    if (_in_region[i])
      c.push_back(static_cast<std::int32_t>(i));
  }
  return c;
}

Extreme StressEnvelope::max_tension(MPI_Comm comm) const
{
  return global_extreme(comm, _max, _t_max, _x, region_points(), 1.0);
}

Extreme StressEnvelope::max_compression(MPI_Comm comm) const
{
  return global_extreme(comm, _min, _t_min, _x, region_points(), -1.0);
}

Extreme StressEnvelope::max_tension(MPI_Comm comm,
                                    std::span<const std::int32_t> subset) const
{
  return global_extreme(comm, _max, _t_max, _x,
                        std::vector<std::int32_t>(subset.begin(), subset.end()),
                        1.0);
}

Extreme
StressEnvelope::max_compression(MPI_Comm comm,
                                std::span<const std::int32_t> subset) const
{
  return global_extreme(comm, _min, _t_min, _x,
                        std::vector<std::int32_t>(subset.begin(), subset.end()),
                        -1.0);
}
} // namespace damseis::results
