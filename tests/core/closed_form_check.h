/// Shared check of the closed-form crack-opening returns against the
/// general iteration (test_material_plane_stress.cpp, 3D in
/// test_material_random.cpp).
#pragma once

#include "damseis/material/concrete.h"

#include <cmath>
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
} // namespace damseis::material::test_support
