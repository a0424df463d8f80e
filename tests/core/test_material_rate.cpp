/// Strain-rate effect: single-point constant-rate uniaxial simulations
/// against the CEB-FIP MC90 dynamic increase factors.
#include <damseis/material/path.h>

#include <gtest/gtest.h>

using namespace damseis::material;

namespace
{
double peak(const HtcConcrete& m, double eps_end, double rate)
{
  const auto r = run_path(m, uniaxial_path(eps_end, rate, 1500));
  double pk = 0;
  for (const auto& q : r.points)
    pk = std::max(pk, std::abs(q.state.stress[0]));
  return pk;
}
} // namespace

// Reference: CEB-FIP Model Code 1990 DIF (CEB Bulletin 213/214; restated in
// Malvar & Crawford 1998), fcm = 30 MPa. Tolerance 10% (brief; issue 3).
// Same simulation as the calibration argument in rate.h: uniaxial stress,
// constant total strain rate, peak stress / static strength.
TEST(MaterialRate, PeakFollowsCebFipDif)
{
  ConcreteParameters p; // viscoplastic, ceb_fip, h = 0.1 m
  const HtcConcrete m(p);
  for (double rate : {1e-5, 1e-3, 1e-1, 10.0})
  {
    const double dt = peak(m, 3e-4, rate) / p.ft0;
    const double dc = peak(m, -2.5e-3, rate) / p.fc0;
    const double rt = ceb_dif_tension(rate, p.fc0);
    const double rc = ceb_dif_compression(rate, p.fc0);
    std::printf("rate %7.0e /s: tension %.3f (CEB %.3f, %+.1f%%), "
                "compression %.3f (CEB %.3f, %+.1f%%)\n",
                rate, dt, rt, 100 * (dt / rt - 1), dc, rc, 100 * (dc / rc - 1));
    EXPECT_NEAR(dt / rt, 1.0, 0.10) << rate;
    EXPECT_NEAR(dc / rc, 1.0, 0.10) << rate;
  }
}

// Reference: the MC90 formulas evaluated by hand at 1e-2 /s, fcm = 30 MPa:
// compression (1e-2/3e-5)^(1.026/32) = 1.2047, tension
// (1e-2/3e-6)^(1.016/28) = 1.3422 (algorithms.md 1.3 quotes 1.20, 1.34).
TEST(MaterialRate, CebFipFormulas)
{
  EXPECT_NEAR(ceb_dif_compression(1e-2, 30e6), 1.2047, 1e-4);
  EXPECT_NEAR(ceb_dif_tension(1e-2, 30e6), 1.3422, 1e-4);
  EXPECT_NEAR(ceb_dif_compression(30e-6, 30e6), 1.0, 1e-12);
}
