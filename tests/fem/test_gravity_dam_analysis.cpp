// The gravity-dam analysis as the demos run it (case file -> configuration
// -> run_gravity_dam_analysis), on the rcc_gravity case (silt, uplift,
// massless foundation) with a coarse mesh and a short record:
//  1. The nonlinear engine with the elastic material equals the linear
//     engine (a different algorithm: LinearNewmark's one solve per step)
//     with every static load on: static crest displacement and the crest
//     history (total), to the Newton tolerance (1e-6 of the load; asserted
//     1e-7 of the largest value; measured: the same 10 digits of crest.csv).
//     Silt and uplift must matter: the static crest without them differs
//     by more than 1% (6.9% here).
//  2. The +30% convention (Lin, Hu, Xiao & Li; the Chinese specification):
//     the rate-independent models take the dynamic factors, the viscoplastic
//     model the static values unless its own factors are set.
#include "fem_test_support.h"

#include <damseis/analysis/gravity_dam_analysis.h>
#include <damseis/analysis/gravity_dam_case.h>
#include <damseis/input/case.h>

#include <filesystem>
#include <fstream>

namespace
{
using namespace damseis::test;
using damseis::analysis::ConcreteModelKind;
namespace analysis = damseis::analysis;

const std::filesystem::path rcc_case =
    DAMSEIS_SOURCE_DIR "/demos/rcc_gravity/rcc_gravity.toml";

/// The rcc_gravity case, coarse and short, with `more` overrides.
analysis::GravityDamConfig rcc_config(std::vector<std::string> more)
{
  std::vector<std::string> o = {
      "study.table1=false",          "mesh.size=8",
      "foundation.mesh_size=40",     "time.duration=0.1",
      "output.plots=false",          "output.every=100000",
      "concrete.dynamic_factor_E=1", "concrete.dynamic_factor_strength=1"};
  o.insert(o.end(), more.begin(), more.end());
  const auto c =
      damseis::input::Case::load(analysis::gravity_dam_schema(), rcc_case, o);
  return analysis::read_gravity_dam_config(c);
}

/// Columns ux_total_m, uy_total_m of crest.csv (with `seismic`: ux_m,
/// uy_m), flattened.
std::vector<double> crest_totals(const std::filesystem::path& csv_file,
                                 bool seismic = false)
{
  std::ifstream csv(csv_file);
  std::string line;
  std::getline(csv, line);
  std::vector<double> v;
  while (std::getline(csv, line))
  {
    std::stringstream ss(line);
    std::string cell;
    std::vector<double> row;
    while (std::getline(ss, cell, ','))
      row.push_back(std::stod(cell));
    v.push_back(row.at(seismic ? 1 : 3));
    v.push_back(row.at(seismic ? 2 : 4));
  }
  return v;
}

nlohmann::json run(const analysis::GravityDamConfig& cfg,
                   const std::filesystem::path& dir)
{
  return analysis::run_gravity_dam_analysis(MPI_COMM_WORLD, cfg, dir, "");
}

TEST(GravityDamAnalysis, ElasticNonlinearEngineKeepsSiltAndUplift)
{
  const auto dir =
      std::filesystem::temp_directory_path() / "damseis_rcc_engines";
  const auto lin = rcc_config({"material.model=linear"});
  const auto ela = rcc_config({"material.model=elastic"});
  ASSERT_GT(lin.silt.level, 0.0);
  ASSERT_TRUE(lin.uplift_on);
  const auto a = run(lin, dir / "linear");
  const auto b = run(ela, dir / "elastic");

  const auto sa = a["crest_static_m"], sb = b["crest_static_m"];
  const double ref = std::hypot(sa[0].get<double>(), sa[1].get<double>());
  for (int i = 0; i < 2; ++i)
  {
    print_metric(fmt("static crest u", i, ": linear ", sa[i].get<double>(),
                     " m, nonlinear-elastic ", sb[i].get<double>(), " m"));
    EXPECT_NEAR(sb[i].get<double>(), sa[i].get<double>(), 1e-7 * ref);
  }
  const auto ha = crest_totals(dir / "linear" / "crest.csv");
  const auto hb = crest_totals(dir / "elastic" / "crest.csv");
  ASSERT_EQ(ha.size(), hb.size());
  ASSERT_GT(ha.size(), 40u);
  double diff = 0.0, peak = 0.0;
  for (std::size_t i = 0; i < ha.size(); ++i)
  {
    diff = std::max(diff, std::abs(ha[i] - hb[i]));
    peak = std::max(peak, std::abs(ha[i]));
  }
  print_metric(fmt("crest history (total): largest difference ", diff / peak,
                   " of the peak ", peak, " m"));
  EXPECT_LT(diff, 1e-7 * peak);

  // The loads under test must matter.
  const auto bare = rcc_config(
      {"material.model=linear", "silt.level=0", "uplift.enabled=false"});
  const auto c = run(bare, dir / "bare");
  const double ux_bare = c["crest_static_m"][0];
  print_metric(fmt("static crest ux without silt and uplift ", ux_bare,
                   " m, with ", sa[0].get<double>(), " m"));
  EXPECT_GT(std::abs(ux_bare - sa[0].get<double>()), 0.01 * std::abs(ux_bare));
}

// 3. On a foundation with mass and a viscous-spring boundary (the springs
//    supports of the concrete system and in K0, the dashpots extra damping
//    of the nonlinear integrator, the free field's load on the static
//    loads) the nonlinear engine with the elastic material equals the
//    linear engine, which treats the same boundary by a different route
//    (LinearNewmark's images, the state relative to the static one): the
//    static crest to 1e-7, the crest's seismic history to 1e-4 of its peak
//    (the Newton tolerance is 1e-6 of the load, static included, and the
//    seismic part is a third of the static displacement here; measured
//    7.7e-12: the elastic steps take one iteration with J0 exact).
TEST(GravityDamAnalysis, ElasticNonlinearEngineEqualsLinearOnViscousSprings)
{
  const auto dir = std::filesystem::temp_directory_path() / "damseis_rcc_vs";
  auto with = [&](std::string model)
  {
    return rcc_config({"foundation.boundary=viscous_spring",
                       "time.duration=1.5", "material.model=" + model});
  };
  const auto a = run(with("linear"), dir / "linear");
  const auto b = run(with("elastic"), dir / "elastic");
  ASSERT_TRUE(b.contains("foundation"));
  const auto sa = a["crest_static_m"], sb = b["crest_static_m"];
  const double ref = std::hypot(sa[0].get<double>(), sa[1].get<double>());
  for (int i = 0; i < 2; ++i)
    EXPECT_NEAR(sb[i].get<double>(), sa[i].get<double>(), 1e-7 * ref);
  const auto ha = crest_totals(dir / "linear" / "crest.csv", true);
  const auto hb = crest_totals(dir / "elastic" / "crest.csv", true);
  ASSERT_EQ(ha.size(), hb.size());
  double diff = 0.0, peak = 0.0;
  for (std::size_t i = 0; i < ha.size(); ++i)
  {
    diff = std::max(diff, std::abs(ha[i] - hb[i]));
    peak = std::max(peak, std::abs(ha[i]));
  }
  print_metric(fmt("viscous-spring foundation, crest's seismic history: "
                   "largest difference ",
                   diff / peak, " of the peak ", peak, " m (static ", ref,
                   " m)"));
  EXPECT_GT(peak, 1e-3 * ref); // the waves reached the dam
  EXPECT_LT(diff, 1e-4 * peak);
}

// 4. On a foundation with mass and Liao's multi-transmitting boundary (the
//    Hughes-Liu partition in the Newton integrator: the band's elements at
//    the predictor, the boundary's nodes prescribed by the formula on the
//    motion from the static state) the nonlinear engine with the elastic
//    material equals the linear engine's PartitionedNewmark (acceleration
//    form, the state relative to the static one): the crest's seismic
//    history to 1e-4 of its peak, the Newton tolerance as in 3 (measured:
//    to the digits of crest.csv).
TEST(GravityDamAnalysis,
     ElasticNonlinearEngineEqualsLinearOnTransmittingBoundary)
{
  const auto dir = std::filesystem::temp_directory_path() / "damseis_rcc_mtf";
  auto with = [&](std::string model)
  {
    return rcc_config({"foundation.boundary=mtf", "mesh.order=1",
                       "foundation.band_size=10", "time.dt=0.0015",
                       "time.duration=1.5", "material.model=" + model});
  };
  const auto a = run(with("linear"), dir / "linear");
  const auto b = run(with("elastic"), dir / "elastic");
  ASSERT_TRUE(b["foundation"].contains("mtf"));
  // The band's own stiffness damping (foundation.band_damping) is on.
  EXPECT_GT(b["foundation"]["mtf"]["band_stiffness_damping_s"].get<double>(),
            0.0);
  const auto ha = crest_totals(dir / "linear" / "crest.csv", true);
  const auto hb = crest_totals(dir / "elastic" / "crest.csv", true);
  ASSERT_EQ(ha.size(), hb.size());
  double diff = 0.0, peak = 0.0;
  for (std::size_t i = 0; i < ha.size(); ++i)
  {
    diff = std::max(diff, std::abs(ha[i] - hb[i]));
    peak = std::max(peak, std::abs(ha[i]));
  }
  const auto sa = a["crest_static_m"];
  const double ref = std::hypot(sa[0].get<double>(), sa[1].get<double>());
  print_metric(fmt("multi-transmitting foundation, crest's seismic history: "
                   "largest difference ",
                   diff / peak, " of the peak ", peak, " m (static ", ref,
                   " m)"));
  EXPECT_GT(peak, 1e-3 * ref); // the waves reached the dam
  EXPECT_LT(diff, 1e-4 * peak);
}

TEST(GravityDamAnalysis, DynamicFactorsApplyToRateIndependentModelsOnly)
{
  const std::vector<std::string> f = {"concrete.dynamic_factor_E=1.3",
                                      "concrete.dynamic_factor_strength=1.3"};
  auto with = [&](std::vector<std::string> more)
  {
    more.insert(more.end(), f.begin(), f.end());
    return rcc_config(more).concrete_model;
  };
  const double E = 25e9, fc = 20e6, ft = 1.8e6; // rcc_gravity.toml
  for (const char* m : {"linear", "elastic", "plastic"})
  {
    const auto s = with({std::string("material.model=") + m});
    EXPECT_DOUBLE_EQ(s.params.E, 1.3 * E) << m;
    EXPECT_DOUBLE_EQ(s.params.fc0, 1.3 * fc) << m;
    EXPECT_DOUBLE_EQ(s.params.ft0, 1.3 * ft) << m;
  }
  const auto vp = with({"material.model=viscoplastic"});
  EXPECT_DOUBLE_EQ(vp.params.E, E);
  EXPECT_DOUBLE_EQ(vp.params.fc0, fc);
  EXPECT_DOUBLE_EQ(vp.params.ft0, ft);
  EXPECT_EQ(vp.params.mode, damseis::material::Mode::viscoplastic);
  // An explicit override.
  const auto vp13 = with(
      {"material.model=viscoplastic", "concrete.viscoplastic_factor_E=1.3"});
  EXPECT_DOUBLE_EQ(vp13.params.E, 1.3 * E);
  EXPECT_DOUBLE_EQ(vp13.params.ft0, ft);
  // A study switches model by model.
  const auto pl = analysis::with_model(vp, ConcreteModelKind::plastic);
  EXPECT_DOUBLE_EQ(pl.params.E, 1.3 * E);
  EXPECT_DOUBLE_EQ(pl.params.ft0, 1.3 * ft);
  EXPECT_EQ(pl.params.mode, damseis::material::Mode::plastic);
}
} // namespace
