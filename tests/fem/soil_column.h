// Helpers of the soil-column tests of transmitting boundaries
// (test_viscous_boundary, test_mtf_boundary): the input pulse and the value
// at a node.
#pragma once

#include "fem_test_support.h"
#include <cmath>
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

/// Its acceleration at k dt, k = 0..n.
inline std::vector<double> pulse_acceleration(double A, double T, double dt,
                                              int n)
{
  std::vector<double> a(n + 1, 0.0);
  const double w = std::numbers::pi / T;
  for (int k = 0; k <= n && k * dt < T; ++k)
  {
    const double s = std::sin(w * k * dt), c = std::cos(w * k * dt);
    a[k] = A * w * w * (12 * s * s * c * c - 4 * s * s * s * s);
  }
  return a;
}

/// The value of component c of x at the node at p (collective).
inline double node_value(const dolfinx::fem::FunctionSpace& V, Vec x,
                         const Point& p, int c)
{
  const int bs = V.dofmap()->index_map_bs();
  const std::int32_t n = V.dofmap()->index_map->size_local();
  const std::vector<double> X = V.tabulate_dof_coordinates(false);
  const double* a = nullptr;
  VecGetArrayRead(x, &a);
  double v = 0.0;
  for (std::int32_t i = 0; i < n; ++i)
    if (std::abs(X[3 * i] - p[0]) < 1e-9 &&
        std::abs(X[3 * i + 1] - p[1]) < 1e-9)
      v = a[bs * i + c];
  VecRestoreArrayRead(x, &a);
  return global_sum(v);
}
} // namespace damseis::test
