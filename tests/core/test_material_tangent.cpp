/// Consistent tangent against central differences of the return map.
#include <damseis/material/concrete.h>

#include <gtest/gtest.h>

using namespace damseis::material;

namespace
{
/// max relative error ||D_fd - D_alg||_F / ||D_alg||_F; abs (if given)
/// receives ||D_fd - D_alg||_F / ||D_e||_F and alg ||D_alg||_F / ||D_e||_F.
double fd_error(const HtcConcrete& m, const State& old, const Vector6& de,
                double dt, unsigned& active, double* abs = nullptr,
                double* alg = nullptr)
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
  double el = 0;
  for (double x : m.elastic_tangent())
    el += x * x;
  if (abs)
    *abs = std::sqrt(num / el);
  if (alg)
    *alg = std::sqrt(den / el);
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
// relative (brief, algorithms.md 1.9: FD check of the algorithmic tangent,
// relative error below 1e-6). Points chosen away from active-set switches;
// the HTC + Rankine corner (HTC+R1) point is one where the plastic and both
// viscoplastic steps end in that set.
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
        {"HTC + Rankine corner (tension-shear)",
         old,
         {-1.9e-4, 8.9e-4, -1.1e-4, 8.1e-4, -9.8e-4, 6e-5},
         htc_surface | rankine_1},
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

// The HTC apex set (hydrostatic tension on a compression-softened HTC whose
// apex lies inside the Rankine planes; fc = 0.22 fc0 here). Reference:
// central finite differences of integrate(), as above; tolerance 1e-6
// (algorithms.md 1.9: FD check of the algorithmic tangent, relative error
// below 1e-6). There the return is perfectly plastic: the stress is
// p_apex(fc) 1, the flow is all tensile (Lee & Fenves weight w = 1, so
// kappa_c does not change) and ft/fc is clamped at rho_max (the HTC does
// not depend on kappa_t), so the exact tangent is zero; the computed one is
// 1e-13 to 1e-9 of the elastic stiffness (measured; the |s| smoothing of
// w). The relative error ||D_fd - D_alg|| / ||D_alg|| then only measures
// the round-off of the difference quotients (~0.2 Pa per unit strain, more
// than ||D_alg||), so here the error is measured relative to the elastic
// stiffness ||D_e|| (same 1e-6), and the tangent itself must vanish at
// that level.
TEST(MaterialTangent, MatchesFiniteDifferencesAtTheApex)
{
  for (Mode mode : {Mode::plastic, Mode::viscoplastic})
  {
    ConcreteParameters p;
    p.mode = mode;
    const HtcConcrete m(p);
    State old;
    old.kappa_t = 1e-5;
    old.kappa_c = 1.5 * m.derived().kappa_cs;
    const Vector6 de = {1e-4, 0.95e-4, 0.9e-4, 1e-6, 2e-6, 0};
    for (double dt : {1e-3, 1.0})
    {
      unsigned act = 0;
      double abs = 0, alg = 0;
      const double rel = fd_error(m, old, de, dt, act, &abs, &alg);
      std::printf("%-13s apex dt=%-5g active %-6s |D_alg|/|D_e| %.2e, "
                  "|D_fd - D_alg|/|D_e| %.2e (relative to D_alg %.2e)\n",
                  mode == Mode::plastic ? "plastic" : "viscoplastic", dt,
                  active_set_name(act).c_str(), alg, abs, rel);
      EXPECT_EQ(act, unsigned(htc_apex));
      EXPECT_LT(abs, 1e-6);
      EXPECT_LT(alg, 1e-6);
    }
  }
}
