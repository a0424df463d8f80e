// Design spectra (motion/design_spectrum): values at the corner periods and
// on each branch, computed by hand from the code formulas, and a published
// worked value (DL 5073-2000: arch dam, site II, T = 1.5 s, Tg = 0.35 s,
// beta = 0.6747; ../shared/docs/algorithms.md §8.1).
#include <cmath>
#include <damseis/motion/design_spectrum.h>
#include <damseis/motion/record.h>
#include <gtest/gtest.h>

using namespace damseis::motion;
namespace
{
constexpr double g = standard_gravity;

DesignSpectrum chinese(SpectrumCode code, DamType dam, const std::string& site,
                       double pga_g, bool vertical = false)
{
  DesignSpectrumSettings s;
  s.code = code;
  s.dam = dam;
  s.site_class = site;
  s.pga = pga_g * g;
  s.vertical = vertical;
  return DesignSpectrum(s);
}
} // namespace

// DL 5073-2000, arch dam (beta_max 2.5), site II (Tg 0.30 s), a = 0.2 g:
// beta(0) = 1, beta(0.05) = 1 + 1.5 x 0.5 = 1.75, 2.5 on [0.1, 0.3],
// beta(1.5) = 2.5 x 0.2^0.9 = 0.58730, beta(3) = max(2.5 x 0.1^0.9,
// 0.5) = 0.5 (the floor).
TEST(DesignSpectrum, Dl5073Branches)
{
  const auto s = chinese(SpectrumCode::dl5073_2000, DamType::arch, "II", 0.2);
  const double a = 0.2 * g;
  EXPECT_NEAR(s(0.0), a, 1e-12);
  EXPECT_NEAR(s(0.05), 1.75 * a, 1e-12);
  EXPECT_NEAR(s(0.1), 2.5 * a, 1e-12);
  EXPECT_NEAR(s(0.3), 2.5 * a, 1e-12);
  EXPECT_NEAR(s(1.5), 2.5 * std::pow(0.2, 0.9) * a, 1e-12);
  EXPECT_NEAR(s(1.5) / a, 0.58730, 1e-5);
  EXPECT_NEAR(s(3.0), 0.5 * a, 1e-12);
  EXPECT_NEAR(s.corner_period(), 0.30, 1e-12);
}

// The worked solution quoting DL 5073 §4.3.4/§4.3.6: Tg = 0.30 + 0.05 s,
// T = 1.5 s, arch: beta = 0.6747; with NB 35047's exponent 0.6 it would be
// 1.044.
TEST(DesignSpectrum, PublishedWorkedValue)
{
  DesignSpectrumSettings s;
  s.code = SpectrumCode::dl5073_2000;
  s.dam = DamType::arch;
  s.tg = 0.35;
  s.pga = 1.0;
  EXPECT_NEAR(DesignSpectrum(s)(1.5), 0.6747, 5e-5);
  s.code = SpectrumCode::nb35047_2015;
  EXPECT_NEAR(DesignSpectrum(s)(1.5), 1.044, 5e-4);
}

// NB 35047-2015, gravity dam (2.0), zoning-map Tg 0.40 s, site I1 (Tg
// 0.30 s, GB 18306-2015 Table 1), a = 0.3 g, vertical (2/3): plateau
// 2 x 0.2 g; T = 1.2: 2 (0.3/1.2)^0.6 = 0.87055; the floor 0.4 is reached
// only beyond 0.3 x 5^(1/0.6) = 4.39 s.
TEST(DesignSpectrum, Nb35047BranchesAndVertical)
{
  const auto s =
      chinese(SpectrumCode::nb35047_2015, DamType::gravity, "I1", 0.3, true);
  const double av = 0.2 * g;
  EXPECT_NEAR(s.pga(), av, 1e-12);
  EXPECT_NEAR(s(0.2), 2.0 * av, 1e-12);
  EXPECT_NEAR(s(1.2) / av, 2.0 * std::pow(0.25, 0.6), 1e-12);
  EXPECT_NEAR(s(1.2) / av, 0.87055, 1e-5);
  EXPECT_NEAR(s(4.0) / av, 2.0 * std::pow(0.075, 0.6), 1e-12);
  EXPECT_NEAR(s(5.0) / av, 0.4, 1e-12);
  EXPECT_NEAR(s.corner_period(), 0.30, 1e-12);
  // Site classes of the 0.45 s map: I0 0.30 ... IV 0.90.
  DesignSpectrumSettings t;
  t.code = SpectrumCode::nb35047_2015;
  t.pga = 1;
  t.tg_map = 0.45;
  t.site_class = "IV";
  EXPECT_NEAR(DesignSpectrum(t).corner_period(), 0.90, 1e-12);
}

// EN 1998-1 type 1, ground C (S 1.15, TB 0.2, TC 0.6, TD 2.0), a_g = 0.3 g,
// 5%: Se(0) = 0.345 g, plateau 0.8625 g, Se(1) = 0.5175 g, Se(3) = 0.8625
// x 0.6 x 2 / 9 g = 0.115 g; at 10% damping eta = sqrt(10/15). Vertical
// type 1: avg = 0.27 g, plateau 0.81 g on [0.05, 0.15], 0.81 x 0.15 / 0.5
// at 0.5 s.
TEST(DesignSpectrum, Eurocode8)
{
  DesignSpectrumSettings s;
  s.code = SpectrumCode::ec8_type1;
  s.site_class = "C";
  s.pga = 0.3 * g;
  const DesignSpectrum h(s);
  EXPECT_NEAR(h(0.0), 0.345 * g, 1e-12);
  EXPECT_NEAR(h(0.2), 0.8625 * g, 1e-12);
  EXPECT_NEAR(h(0.1), 0.345 * g + 0.5 * (0.8625 - 0.345) * g, 1e-12);
  EXPECT_NEAR(h(1.0), 0.5175 * g, 1e-12);
  EXPECT_NEAR(h(3.0), 0.115 * g, 1e-12);
  s.damping = 0.10;
  EXPECT_NEAR(DesignSpectrum(s)(0.4), 0.8625 * g * std::sqrt(10.0 / 15.0),
              1e-12);
  s.damping = 0.05;
  s.vertical = true;
  const DesignSpectrum v(s);
  EXPECT_NEAR(v(0.0), 0.27 * g, 1e-12);
  EXPECT_NEAR(v(0.1), 0.81 * g, 1e-12);
  EXPECT_NEAR(v(0.5), 0.81 * 0.3 * g, 1e-12);
}

TEST(DesignSpectrum, TableIsLinearAndBounded)
{
  DesignSpectrumSettings s;
  s.code = SpectrumCode::table;
  s.table_period = {0.0, 0.1, 1.0};
  s.table_sa = {2.0, 5.0, 1.0};
  const DesignSpectrum t(s);
  EXPECT_NEAR(t(0.05), 3.5, 1e-12);
  EXPECT_NEAR(t(0.55), 3.0, 1e-12);
  EXPECT_THROW(t(2.0), std::out_of_range);
  // The vertical motion of a table: vertical_ratio x the table.
  s.vertical = true;
  s.vertical_ratio = 0.5;
  EXPECT_NEAR(DesignSpectrum(s)(0.05), 1.75, 1e-12);
  EXPECT_NEAR(DesignSpectrum(s).pga(), 1.0, 1e-12);
}

TEST(DesignSpectrum, BadSettingsThrowNamingTheValue)
{
  auto throws = [](DesignSpectrumSettings s, const std::string& phrase)
  {
    try
    {
      DesignSpectrum d(s);
      ADD_FAILURE() << "accepted";
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos)
          << e.what();
    }
  };
  DesignSpectrumSettings s;
  s.pga = 1.0;
  s.site_class = "V";
  throws(s, "site class \"V\"");
  s.site_class = "II";
  s.tg_map = 0.5;
  throws(s, "0.35, 0.40 or 0.45");
  s.tg_map = 0.40;
  s.pga = -1;
  throws(s, "design acceleration");
  s.pga = 1;
  s.code = SpectrumCode::table;
  s.table_period = {0.0, 0.0};
  s.table_sa = {1.0, 1.0};
  throws(s, "increasing");
  EXPECT_THROW(parse_spectrum_code("GB50011"), std::invalid_argument);
  EXPECT_EQ(parse_spectrum_code(to_string(SpectrumCode::dl5073_2000)),
            SpectrumCode::dl5073_2000);
}
