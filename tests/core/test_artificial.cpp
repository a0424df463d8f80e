// Spectrum-compatible artificial records (motion/artificial): the
// acceptance criteria of practice, checked independently of the
// generator's own bookkeeping (spectra recomputed here).
#include <cmath>
#include <damseis/motion/artificial.h>
#include <damseis/motion/record.h>
#include <damseis/motion/spectrum.h>
#include <gtest/gtest.h>

using namespace damseis::motion;
namespace
{
constexpr double pi = 3.14159265358979323846;
DesignSpectrum nb35047(bool vertical)
{
  DesignSpectrumSettings d;
  d.code = SpectrumCode::nb35047_2015;
  d.dam = DamType::arch;
  d.site_class = "I1";
  d.pga = 0.321 * standard_gravity; // the paper's arch-dam study
  d.vertical = vertical;
  return DesignSpectrum(d);
}
} // namespace

// Three seeds of the paper's three-component motion (NB 35047-2015, arch
// dam, site I1, 0.321 g, vertical 2/3), 20 s at 0.01 s: every component's
// 5%-damped spectrum within +-10% of the target at the 100 control periods
// from 0.04 to 4 s (the acceptance of Chinese dam practice and US NRC SRP
// 3.7.1's lower bound), PGA equal to the design value, final velocity and
// displacement zero (end_at_rest: asserted 1e-6 m/s and 1e-5 m), the
// components' correlations within 0.16 (SRP 3.7.1; ASCE 4 allows 0.3).
// Displacement: no content is matched beyond the longest control period
// Tmax, so the ground displacement is of the order of the target's
// spectral displacement there (Newmark & Hall 1982: median 5%-damped
// spectral displacement 1.39 PGD in the displacement range); PGD at most
// 2 Sd(Tmax) (1.34 m here) is asserted. Matching the code spectrum out to
// 12.6 s, as the generator once did, gave 1.5 m for seed 1 (2.9 m over 20
// seeds).
TEST(Artificial, ThreeComponentsMeetTheAcceptanceCriteria)
{
  const auto h = nb35047(false), v = nb35047(true);
  ArtificialSettings s;
  for (std::uint64_t seed : {1u, 7u, 12u})
  {
    s.seed = seed;
    const ArtificialMotion m = generate_motion({h, h, v}, s);
    ASSERT_EQ(m.components.size(), 3u);
    EXPECT_TRUE(m.accepted) << "seed " << seed;
    for (std::size_t c = 0; c < 3; ++c)
    {
      const auto& a = m.components[c].acceleration;
      const DesignSpectrum& target = c < 2 ? h : v;
      ASSERT_EQ(a.size(), 2001u);
      const Spectrum sp =
          response_spectrum(a, s.dt, s.control_periods, s.damping);
      for (std::size_t i = 0; i < sp.period.size(); ++i)
      {
        const double ratio = sp.psa[i] / target(sp.period[i]);
        EXPECT_NEAR(ratio, 1.0, 0.10 + 1e-9)
            << "seed " << seed << " component " << c << " T " << sp.period[i];
      }
      const Measures me = measures(a, s.dt);
      EXPECT_NEAR(me.pga, target.pga(), 1e-9 * target.pga());
      EXPECT_LT(std::abs(me.final_velocity), 1e-6);
      EXPECT_LT(std::abs(me.final_displacement), 1e-5);
      const double t_max = s.control_periods.back();
      const double sd_max = target(t_max) * std::pow(t_max / (2 * pi), 2);
      EXPECT_LE(me.pgd, 2.0 * sd_max) << "seed " << seed << " component " << c;
      // The intensity envelope: the 5-95% Arias interval lies around the
      // strong phase (2 to 12 s, decay 0.35/s), not spread over the record.
      EXPECT_GT(me.t5, 0.5);
      EXPECT_LT(me.t95, 17.0);
    }
    for (double r : m.correlations)
      EXPECT_LE(std::abs(r), 0.16) << "seed " << seed;
  }
}

// The seed makes the record: the same seed gives the same record bit for
// bit, another seed another record.
TEST(Artificial, SeedIsReproducible)
{
  const auto h = nb35047(false);
  ArtificialSettings s;
  s.seed = 3;
  const auto a = generate_motion({h}, s).components[0].acceleration;
  const auto b = generate_motion({h}, s).components[0].acceleration;
  s.seed = 4;
  const auto c = generate_motion({h}, s).components[0].acceleration;
  EXPECT_EQ(a, b);
  EXPECT_GT(std::abs(correlation(a, c) - 1.0), 0.1);
}

TEST(Artificial, BadSettingsThrow)
{
  const auto h = nb35047(false);
  ArtificialSettings s;
  s.dt = 0;
  EXPECT_THROW(generate_component(h, s, 1), std::invalid_argument);
  s = ArtificialSettings{};
  s.envelope.strong_end = 30; // beyond the 20 s duration
  EXPECT_THROW(generate_component(h, s, 1), std::invalid_argument);
  s = ArtificialSettings{};
  s.control_periods = {0.01}; // below 2 dt
  EXPECT_THROW(generate_component(h, s, 1), std::invalid_argument);
  s = ArtificialSettings{};
  s.duration = 600; // 60,001 samples x 100 periods: hours, refused
  s.envelope.strong_end = 300;
  EXPECT_THROW(generate_component(h, s, 1), std::invalid_argument);
}
