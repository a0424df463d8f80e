#include "gravity_dam_analysis.h"
#include "linear_seismic.h"
#include "nonlinear_seismic.h"
#include "run_outputs.h"
#include <damseis/geometry/mesh_estimate.h>
#include <damseis/geometry/tags.h>
#include <damseis/results/progress.h>
#include <dolfinx/la/petsc.h>
#include <fstream>
#include <iomanip>

namespace damseis::analysis
{
namespace
{
nlohmann::json run_one(MPI_Comm comm, const GravityDamConfig& cfg,
                       const std::filesystem::path& out_dir,
                       const std::string& case_text)
{
  const bool foundation = cfg.section.foundation;
  // The dam's E with the factor of its model (rate-independent: +30%
  // convention; viscoplastic: static unless asked otherwise).
  fem::Material dam = cfg.concrete;
  dam.E = cfg.concrete_model.params.E;
  std::map<int, fem::Material> materials = {{tags::dam, dam}};
  if (foundation)
    materials[tags::foundation] = cfg.rock;
  results::set_stage("meshing");
  if (cfg.write_mesh_file)
    std::filesystem::create_directories(out_dir); // rank 0 writes the mesh
  fem::ElasticModel fe(geometry::build_gravity_dam(
                           comm, cfg.section, false,
                           cfg.write_mesh_file ? out_dir / "model.msh"
                                               : std::filesystem::path()),
                       cfg.order, materials, cfg.plane);
  if (foundation)
    fe.fix({tags::foundation_bottom, tags::foundation_sides});
  else
    fe.fix({tags::dam_base});

  // Silt and uplift (static loads besides dead weight and water).
  std::vector<dolfinx::la::petsc::Vector> extra;
  if (cfg.silt.level > 0.0)
    extra.emplace_back(fem::assemble_silt(fe, cfg.silt), false);
  if (cfg.uplift_on)
    extra.emplace_back(fem::assemble_uplift(fe, cfg.uplift), false);
  std::vector<Vec> extra_vecs;
  for (auto& v : extra)
    extra_vecs.push_back(v.vec());

  const auto kind = cfg.concrete_model.kind;
  nlohmann::json summary;
  if (kind == ConcreteModelKind::linear)
  {
    summary =
        run_linear_seismic(fe, cfg.seismic, extra_vecs, {out_dir, case_text});
    summary["analysis"] = "gravity dam section, linear elastic";
  }
  else
  {
    summary = run_nonlinear_seismic(fe, cfg.seismic,
                                    {cfg.concrete_model, materials, cfg.plane},
                                    extra_vecs, {out_dir, case_text});
    summary["analysis"] =
        "gravity dam section, HTC concrete (" + to_string(kind) + ")";
  }
  summary["plane"] = cfg.plane == fem::PlaneMode::plane_stress ? "plane_stress"
                                                               : "plane_strain";
  summary["base"] = foundation ? "massless foundation" : "rigid";
  summary["dam_E_pa"] = dam.E;
  summary["dam_E_factor"] = cfg.concrete_model.applied.E;
  summary["silt_level_m"] = cfg.silt.level;
  summary["uplift"] = cfg.uplift_on;
  write_summary_and_plots(comm, summary, out_dir, cfg.seismic.plots,
                          "plot_gravity_dam.py");
  return summary;
}

/// table1.csv and table1.md from the summaries of the three models.
void write_table1(
    const std::vector<std::pair<std::string, nlohmann::json>>& runs,
    const std::filesystem::path& out_dir)
{
  std::ofstream csv(out_dir / "table1.csv"), md(out_dir / "table1.md");
  const double radius =
      runs.front().second["away_from_singular_points"]["radius_m"];
  csv << "model,max_compression_mpa,max_tension_mpa,"
         "max_compression_away_mpa,max_tension_away_mpa,"
         "crest_displacement_cm,max_kappa_t,newton_iterations_per_step,"
         "seconds_per_step,material_integration\n";
  md << std::setprecision(3) << "| Model | Compression (MPa) | Tension (MPa) "
     << "| Compression > " << radius << " m from corners (MPa) | Tension > "
     << radius
     << " m from corners (MPa) | Crest displacement (cm) | max kappa_t | "
        "Newton it./step | s/step | integration |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& [name, s] : runs)
  {
    const double c = s["max_principal_compression_mpa"]["value"];
    const double t = s["max_principal_tension_mpa"]["value"];
    const auto& away = s["away_from_singular_points"];
    const double ca = away["max_principal_compression_mpa"]["value"];
    const double ta = away["max_principal_tension_mpa"]["value"];
    const double u =
        s["crest_displacement_max_m"]["value"].get<double>() * 100.0;
    const double kt = s["max_kappa_t"]["value"];
    const double it = s["newton"]["iterations_per_step"];
    const double sps = s["seconds_per_step"];
    // The elastic model has nothing to integrate.
    const std::string integ =
        name == "elastic"
            ? "-"
            : s["concrete"]["material_integration"].get<std::string>();
    csv << name << "," << c << "," << t << "," << ca << "," << ta << "," << u
        << "," << kt << "," << it << "," << sps << "," << integ << "\n";
    md << std::fixed << "| " << name << " | " << std::setprecision(2) << c
       << " | " << t << " | " << ca << " | " << ta << " | " << u << " | "
       << std::scientific << std::setprecision(2) << kt << std::fixed << " | "
       << std::setprecision(2) << it << " | " << std::setprecision(4) << sps
       << " | " << integ << " |\n";
  }
}
} // namespace

nlohmann::json run_gravity_dam_analysis(MPI_Comm comm,
                                        const GravityDamConfig& cfg,
                                        const std::filesystem::path& out_dir,
                                        const std::string& case_text)
{
  print_size_estimate(comm, geometry::estimated_cells(cfg.section), 2,
                      cfg.order, cfg.seismic.steps);
  if (!cfg.table1)
    return run_one(comm, cfg, out_dir, case_text);
  std::vector<std::pair<std::string, nlohmann::json>> runs;
  for (ConcreteModelKind kind :
       {ConcreteModelKind::elastic, ConcreteModelKind::plastic,
        ConcreteModelKind::viscoplastic})
  {
    GravityDamConfig c = cfg;
    c.table1 = false;
    c.concrete_model = with_model(cfg.concrete_model, kind);
    results::print(comm, "== " + to_string(kind) + " ==");
    runs.emplace_back(to_string(kind),
                      run_one(comm, c, out_dir / to_string(kind), case_text));
  }
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0)
    write_table1(runs, out_dir);
  return runs.back().second;
}
} // namespace damseis::analysis
