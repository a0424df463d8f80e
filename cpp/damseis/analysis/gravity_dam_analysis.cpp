#include "gravity_dam_analysis.h"
#include "foundation_study.h"
#include "linear_seismic.h"
#include "nonlinear_seismic.h"
#include "run_outputs.h"
#include "table1.h"
#include <damseis/fem/gravity_dam_loads.h>
#include <damseis/geometry/mesh_estimate.h>
#include <damseis/geometry/tags.h>
#include <damseis/results/progress.h>
#include <dolfinx/la/petsc.h>

namespace damseis::analysis
{
namespace
{
/// The elastic materials per region. The dam's E is that of its model
/// (rate-independent: +30% convention; viscoplastic: static unless asked
/// otherwise).
std::map<int, fem::Material> section_materials(const GravityDamConfig& cfg)
{
  fem::Material dam = cfg.concrete;
  dam.E = cfg.concrete_model.params.E;
  std::map<int, fem::Material> materials = {{tags::dam, dam}};
  if (cfg.section.foundation)
    materials[tags::foundation] = cfg.rock;
  if (cfg.section.band_layers > 0)
    materials[tags::foundation_band] = cfg.rock;
  if (cfg.section.foundation_split != geometry::GravityDamSection::Split::none)
  {
    fem::Material second = cfg.rock;
    second.E = cfg.rock_E2;
    materials[tags::foundation_2] = second;
  }
  return materials;
}

} // namespace

std::vector<Vec> GravityDamModel::static_loads() const
{
  std::vector<Vec> v;
  for (const auto& x : silt_and_uplift)
    v.push_back(x.vec());
  return v;
}

GravityDamModel gravity_dam_model(MPI_Comm comm, const GravityDamConfig& cfg,
                                  const std::filesystem::path& out_dir)
{
  const bool foundation = cfg.section.foundation;
  results::set_stage("meshing");
  if (cfg.write_mesh_file)
    std::filesystem::create_directories(out_dir); // rank 0 writes the mesh
  GravityDamModel m;
  m.fe = std::make_unique<fem::ElasticModel>(
      geometry::build_gravity_dam(comm, cfg.section, false,
                                  cfg.write_mesh_file
                                      ? out_dir / "model.msh"
                                      : std::filesystem::path()),
      cfg.order, section_materials(cfg), cfg.plane);
  // A massless block is fixed at its far boundary; a block with a
  // viscous-spring boundary is held by its springs.
  if (!foundation)
    m.fe->fix({tags::dam_base});
  else if (!cfg.wave || cfg.wave->mtf) // (mtf: for the static and modal
    // stages; the time history prescribes these nodes)
    m.fe->fix({tags::foundation_bottom, tags::foundation_sides});
  if (cfg.silt.level > 0.0)
    m.silt_and_uplift.emplace_back(fem::assemble_silt(*m.fe, cfg.silt), false);
  if (cfg.uplift_on)
    m.silt_and_uplift.emplace_back(fem::assemble_uplift(*m.fe, cfg.uplift),
                                   false);
  return m;
}

std::unique_ptr<SeismicAnalysis>
gravity_dam_seismic_analysis(GravityDamModel& model,
                             const GravityDamConfig& cfg,
                             const RunFolder& folder)
{
  if (cfg.concrete_model.kind == ConcreteModelKind::linear)
  {
    return linear_seismic_analysis(*model.fe, cfg.seismic,
                                   {model.static_loads()}, folder, nullptr,
                                   nullptr, cfg.wave ? &*cfg.wave : nullptr);
  }
  // The regions other than the dam stay linear elastic.
  return concrete_seismic_analysis(
      *model.fe, cfg.seismic,
      {cfg.concrete_model, section_materials(cfg), cfg.plane},
      {model.static_loads()}, folder, nullptr, cfg.wave ? &*cfg.wave : nullptr);
}

nlohmann::json gravity_dam_results(MPI_Comm comm, const GravityDamConfig& cfg,
                                   nlohmann::json summary,
                                   const std::filesystem::path& out_dir)
{
  const auto kind = cfg.concrete_model.kind;
  summary["analysis"] =
      kind == ConcreteModelKind::linear
          ? std::string("gravity dam section, linear elastic")
          : "gravity dam section, HTC concrete (" + to_string(kind) + ")";
  summary["plane"] = cfg.plane == fem::PlaneMode::plane_stress ? "plane_stress"
                                                               : "plane_strain";
  summary["base"] =
      !cfg.section.foundation ? "rigid"
      : cfg.wave              ? (cfg.wave->mtf ? "foundation with mass, multi-"
                                                 "transmitting boundary"
                                               : "foundation with mass, viscous-spring "
                                                 "boundary")
                              : "massless foundation";
  summary["dam_E_pa"] = cfg.concrete_model.params.E;
  summary["dam_E_factor"] = cfg.concrete_model.applied.E;
  summary["silt_level_m"] = cfg.silt.level;
  summary["uplift"] = cfg.uplift_on;
  write_summary_and_plots(comm, summary, out_dir, cfg.seismic.plots,
                          "plot_gravity_dam.py");
  return summary;
}

nlohmann::json run_gravity_dam_study(MPI_Comm comm, const GravityDamConfig& cfg,
                                     const std::filesystem::path& out_dir,
                                     const std::string& case_text,
                                     const GravityDamRun& analyse)
{
  print_size_estimate(comm, geometry::estimated_cells(cfg.section), 2,
                      cfg.order, cfg.seismic.steps);
  if (!cfg.table6_ratios.empty())
    return run_table6_study(comm, cfg, out_dir, case_text, analyse);
  if (!cfg.table1)
    return analyse(comm, cfg, {out_dir, case_text});
  std::vector<Table1Run> runs;
  for (ConcreteModelKind kind :
       {ConcreteModelKind::elastic, ConcreteModelKind::plastic,
        ConcreteModelKind::viscoplastic})
  {
    GravityDamConfig c = cfg;
    c.table1 = false;
    c.concrete_model = with_model(cfg.concrete_model, kind);
    results::print(comm, "== " + to_string(kind) + " ==");
    runs.push_back({to_string(kind), std::nan(""),
                    analyse(comm, c, {out_dir / to_string(kind), case_text})});
  }
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0)
    write_table1(runs, out_dir);
  return runs.back().summary;
}
nlohmann::json run_gravity_dam_analysis(MPI_Comm comm,
                                        const GravityDamConfig& config,
                                        const std::filesystem::path& out_dir,
                                        const std::string& case_text)
{
  return run_gravity_dam_study(
      comm, config, out_dir, case_text,
      [](MPI_Comm c, const GravityDamConfig& cfg, const RunFolder& folder)
      {
        GravityDamModel model = gravity_dam_model(c, cfg, folder.dir);
        return gravity_dam_results(
            c, cfg, gravity_dam_seismic_analysis(model, cfg, folder)->run(),
            folder.dir);
      });
}
} // namespace damseis::analysis
