/// Consistent tangent against central differences of the return map.
#include "damseis/material/concrete.h"

#include <gtest/gtest.h>

using namespace damseis::material;

namespace
{
/// max relative error ||D_fd - D_alg||_F / ||D_alg||_F
double fd_error(const HtcConcrete& m, const State& old, const Vector6& de,
                double dt, unsigned& active)
{
  const Update u = m.integrate(old, de, dt);
  EXPECT_TRUE(u.converged);
  active = u.active;
  double num = 0, den = 0;
  for (int j = 0; j < 6; ++j)
  {
    const double h = 1e-9;
    Vector6 ep = de, em = de;
    ep[j] += h;
    em[j] -= h;
    const Update up = m.integrate(old, ep, dt), um = m.integrate(old, em, dt);
    EXPECT_EQ(up.active, u.active);
    EXPECT_EQ(um.active, u.active);
    for (int i = 0; i < 6; ++i)
    {
      const double fd = (up.state.stress[i] - um.state.stress[i]) / (2 * h);
      num += (fd - u.tangent[i * 6 + j]) * (fd - u.tangent[i * 6 + j]);
      den += u.tangent[i * 6 + j] * u.tangent[i * 6 + j];
    }
  }
  return std::sqrt(num / den);
}

struct Case
{
  const char* name;
  State old;
  Vector6 de;
  unsigned expect;
};
} // namespace

// Reference: central finite differences of integrate() (step 1e-9 on strains
// of 1e-4: truncation ~1e-10, round-off ~1e-8 relative to E). Tolerance 1e-6
// relative (brief, algorithms.md 1.9). Points chosen away from active-set
// switches.
TEST(MaterialTangent, MatchesFiniteDifferences)
{
  for (Mode mode : {Mode::plastic, Mode::viscoplastic})
  {
    ConcreteParameters p;
    p.mode = mode;
    const HtcConcrete m(p);
    State old;
    old.kappa_t = 1e-5;
    old.kappa_c = 2e-5;
    std::vector<Case> cases = {
        {"HTC (compression-shear)",
         old,
         {-1.6e-3, 1e-4, 3e-4, 5e-4, -2e-4, 1e-4},
         htc_surface},
        {"Rankine (tension)",
         old,
         {2.5e-4, -2e-5, 1e-5, 3e-5, 0, 1e-5},
         rankine_1},
        {"Rankine corner R1+R2 (biaxial tension)",
         old,
         {2.5e-4, 2.4e-4, -1e-4, 1e-5, 0, 0},
         rankine_1 | rankine_2},
        {"compressive-meridian edge",
         old,
         {-2.5e-3, 3e-4, 3.1e-4, 1e-5, 2e-5, 0},
         htc_surface | htc_edge},
        {"near the apex (triaxial tension)",
         old,
         {2e-4, 1.9e-4, 1.8e-4, 1e-5, 2e-5, 0},
         rankine_1 | rankine_2 | rankine_3},
    };
    for (const auto& c : cases)
    {
      for (double dt : {1e-3, 1.0})
      {
        unsigned act = 0;
        const double err = fd_error(m, c.old, c.de, dt, act);
        std::printf("%-13s %-34s dt=%-5g active %-10s FD error %.2e\n",
                    mode == Mode::plastic ? "plastic" : "viscoplastic", c.name,
                    dt, active_set_name(act).c_str(), err);
        // The rate effect enlarges the surfaces, so the viscoplastic active
        // sets may differ; the plastic ones are the intended cases.
        if (mode == Mode::plastic)
          EXPECT_EQ(act, c.expect) << c.name;
        EXPECT_LT(err, 1e-6) << c.name;
      }
    }
  }
}
