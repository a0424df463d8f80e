// Helpers of the soil-column tests of transmitting boundaries
// (test_viscous_boundary, test_mtf_boundary): the input pulse, the value
// at a node, and the march that measures a column's errors.
#pragma once

#include "fem_test_support.h"
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <vector>

namespace damseis::test
{
/// d(t) = A sin^4(pi t / T) on [0, T]: a pulse from rest to rest.
inline double pulse(double A, double T, double t)
{
  return t <= 0 || t >= T ? 0.0
                          : A * std::pow(std::sin(std::numbers::pi * t / T), 4);
}

/// Its acceleration at time t.
inline double pulse_acceleration(double A, double T, double t)
{
  if (t <= 0 || t >= T)
    return 0.0;
  const double w = std::numbers::pi / T;
  const double s = std::sin(w * t), c = std::cos(w * t);
  return A * w * w * (12 * s * s * c * c - 4 * s * s * s * s);
}

/// Its acceleration at k dt, k = 0..n.
inline std::vector<double> pulse_acceleration(double A, double T, double dt,
                                              int n)
{
  std::vector<double> a(n + 1);
  for (int k = 0; k <= n; ++k)
    a[k] = pulse_acceleration(A, T, k * dt);
  return a;
}

/// A node of V at p: its values in vectors of V's layout, the node found
/// once (a rank that does not own it reads 0; the values are summed).
class NodeProbe
{
public:
  NodeProbe(const dolfinx::fem::FunctionSpace& V, const Point& p)
      : _bs(V.dofmap()->index_map_bs())
  {
    const std::int32_t n = V.dofmap()->index_map->size_local();
    const std::vector<double> X = V.tabulate_dof_coordinates(false);
    for (std::int32_t i = 0; i < n; ++i)
      if (std::hypot(X[3 * i] - p[0], X[3 * i + 1] - p[1],
                     X[3 * i + 2] - p[2]) < 1e-9)
        _local = i;
  }
  /// Component c of x at the node (collective).
  double operator()(Vec x, int c) const
  {
    double v = 0.0;
    if (_local >= 0)
    {
      const double* a = nullptr;
      VecGetArrayRead(x, &a);
      v = a[_bs * _local + c];
      VecRestoreArrayRead(x, &a);
    }
    return global_sum(v);
  }

private:
  int _bs;
  std::int32_t _local = -1;
};

/// Tags the local cells of `model` whose centre satisfies `in_band` with
/// `band_region`, the others with tags::dam (the model's cell tags are
/// replaced), and returns the band's cells (the transmitting boundary's
/// explicit group).
inline std::vector<std::int32_t>
tag_band(Model& model, int band_region,
         const std::function<bool(const Point&)>& in_band)
{
  const int tdim = model.mesh->topology().dim();
  const auto& dofs = model.mesh->geometry().dofmap();
  std::span<const double> x = model.mesh->geometry().x();
  const std::int32_t n = dofs.num_nodes();
  std::vector<std::int32_t> cells(n), regions(n), band;
  for (std::int32_t cell = 0; cell < n; ++cell)
  {
    Point mid{0, 0, 0};
    auto nodes = dofs.links(cell);
    for (auto node : nodes)
      for (int k = 0; k < 3; ++k)
        mid[k] += x[3 * node + k] / double(nodes.size());
    cells[cell] = cell;
    regions[cell] = in_band(mid) ? band_region : tags::dam;
    if (regions[cell] == band_region)
      band.push_back(cell);
  }
  model.cell_tags = std::make_shared<dolfinx::mesh::MeshTags<std::int32_t>>(
      model.mesh, tdim, std::move(cells), std::move(regions));
  return band;
}

/// A soil column's errors relative to the pulse's peak A.
struct ColumnErrors
{
  double surface = 0.0;  ///< max over the steps |u(top) - exact(k)| / A
  double residual = 0.0; ///< max |u| in the column at the end / A
};

/// Runs `step(k)` (the load of step k assembled, the integrator advanced)
/// for k = 1..steps and measures component c of the displacement u at the
/// node `top` against exact(k), and calls `observe(k)` after each step;
/// then the residual motion (collective).
template <class Step, class Exact, class Observe>
ColumnErrors march_column(const dolfinx::fem::FunctionSpace& V, Vec u,
                          const Point& top, int c, int steps, double A,
                          Step step, Exact exact, Observe observe)
{
  ColumnErrors e;
  const NodeProbe surface(V, top);
  for (int k = 1; k <= steps; ++k)
  {
    step(k);
    e.surface = std::max(e.surface, std::abs(surface(u, c) - exact(k)) / A);
    observe(k);
  }
  double umax = 0.0;
  VecNorm(u, NORM_INFINITY, &umax);
  e.residual = umax / A;
  return e;
}

template <class Step, class Exact>
ColumnErrors march_column(const dolfinx::fem::FunctionSpace& V, Vec u,
                          const Point& top, int c, int steps, double A,
                          Step step, Exact exact)
{
  return march_column(V, u, top, c, steps, A, step, exact, [](int) {});
}
} // namespace damseis::test
