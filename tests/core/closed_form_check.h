/// Shared check of the closed-form crack-opening returns against the
/// general iteration (test_material_plane_stress.cpp, 3D in
/// test_material_random.cpp).
#pragma once

#include <damseis/material/concrete.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

namespace damseis::material::test_support
{
/// f (closed form) and r (iteration) return to the Rankine plane alone
/// with the same stresses (to stress_tol), kappa_t (to kappa_rel,
/// relative) and kappa_c (exactly: neither moves it).
inline void expect_same_crack_opening(const Update& f, const Update& r,
                                      double stress_tol, double kappa_rel,
                                      int item)
{
  EXPECT_EQ(r.active, unsigned(rankine_1)) << "item " << item;
  for (int i = 0; i < 6; ++i)
    EXPECT_NEAR(f.state.stress[i], r.state.stress[i], stress_tol)
        << "item " << item << " component " << i;
  EXPECT_NEAR(f.state.kappa_t, r.state.kappa_t,
              kappa_rel * std::abs(r.state.kappa_t))
      << "item " << item;
  EXPECT_EQ(f.state.kappa_c, r.state.kappa_c) << "item " << item;
}

/// Every entry of the tangent f within rel x the largest entry of r.
template <class Array>
void expect_same_tangent(const Array& f, const Array& r, double rel, int item)
{
  double tmax = 0.0;
  for (double v : r)
    tmax = std::max(tmax, std::abs(v));
  for (std::size_t i = 0; i < r.size(); ++i)
    EXPECT_NEAR(f[i], r[i], rel * tmax) << "item " << item << " entry " << i;
}

/// Prints how many of the inelastic updates took the closed form, and
/// checks there were enough of both.
inline void expect_closed_form_share(Mode mode, int applied, int total)
{
  std::printf("[   metric ] %s: %d of %d inelastic updates by the closed "
              "form\n",
              mode == Mode::plastic ? "plastic" : "viscoplastic", applied,
              total);
  EXPECT_GT(total, 1000);
  EXPECT_GT(applied, total / 2);
}
} // namespace damseis::material::test_support
