#include "arch_dam_analysis.h"
#include "linear_seismic.h"
#include "nonlinear_seismic.h"
#include "run_outputs.h"
#include "table1.h"
#include <cstdio>
#include <cstdlib>
#include <damseis/fem/tied_dofs.h>
#include <damseis/geometry/arch_mesh.h>
#include <damseis/geometry/mesh_estimate.h>
#include <damseis/geometry/tags.h>
#include <damseis/results/progress.h>
#include <damseis/results/singular_points.h>
#include <dolfinx/la/petsc.h>
#include <sstream>

namespace damseis::analysis
{
ArchDamModel arch_dam_model(MPI_Comm comm, const ArchDamConfig& cfg)
{
  print_size_estimate(comm, geometry::estimated_cells(cfg.geometry), 3,
                      cfg.order, cfg.seismic.steps);
  results::set_stage("meshing");
  ArchDamModel m{geometry::build_arch_dam(comm, cfg.geometry)};
  const auto& arch = m.mesh;
  results::print(
      comm, "arch dam mesh: " + std::to_string(arch.num_cells) + " cells (" +
                std::to_string(arch.num_dam_cells) + " in the dam), " +
                std::to_string(arch.joints.size()) + " joints, built in " +
                std::to_string(arch.total_seconds) + " s");
  // The dam's E is that of its concrete model (the rate-independent
  // models' +30% convention; the linear engine's too).
  fem::Material dam = cfg.concrete;
  dam.E = cfg.concrete_model.params.E;
  m.concrete = cfg.concrete_model;
  m.materials = {{tags::dam, dam}, {tags::foundation, cfg.rock}};
  if (cfg.geometry.mesh.band_layers > 0)
    m.materials[tags::foundation_band] = cfg.rock;
  m.fe =
      std::make_unique<fem::ElasticModel>(arch.model, cfg.order, m.materials);
  // A massless foundation is fixed on its far boundaries; rock with mass
  // is held there by the viscous-spring boundary (the multi-transmitting
  // one: fixed for the static and modal stages, the time history
  // prescribes it).
  if (!cfg.wave || cfg.wave->mtf)
    m.fe->fix({tags::foundation_bottom, tags::foundation_sides,
               tags::foundation_upstream, tags::foundation_downstream});

  // Bonded joints: the two sides' coincident dofs tied.
  std::vector<std::pair<int, int>> joint_tags;
  for (const auto& j : arch.joints)
    joint_tags.emplace_back(j.tag_side1, j.tag_side2);
  if (!joint_tags.empty())
  {
    m.tie = dolfinx::la::petsc::Matrix(
        fem::tie_prolongation(*m.fe->V(), *arch.model.facet_tags, joint_tags),
        false);
  }

  if (cfg.joints == JointModel::contact)
  {
    ContactJoints c;
    for (const auto& j : arch.joints)
      c.joints.push_back({std::string(1, j.label), j.tag_side1, j.tag_side2,
                          cfg.friction.at(j.label),
                          cfg.keyed.find(j.label) != std::string::npos,
                          cfg.bonds.at(j.label).first,
                          cfg.bonds.at(j.label).second,
                          cfg.initial_gap.at(j.label)});
    c.facet_tags = arch.model.facet_tags.get();
    c.restitution = cfg.restitution;
    c.statics = cfg.statics;
    c.history_points = cfg.history_points;
    c.ncp = cfg.ncp;
    m.contact = std::move(c);
  }

  m.wave = cfg.wave;
  // Singular lines: where the faces meet the rock.
  m.seismic = cfg.seismic;
  const int faces[3] = {tags::upstream_face, tags::upstream_wetted,
                        tags::downstream_face};
  m.seismic.singular_points =
      results::meeting_points(arch.model, faces, tags::dam_base);
  m.seismic.singular_where =
      "the mesh nodes where the upstream and downstream faces meet the rock";
  return m;
}

std::unique_ptr<SeismicAnalysis>
arch_dam_seismic_analysis(ArchDamModel& model, const RunFolder& folder)
{
  if (model.concrete.kind != ConcreteModelKind::linear)
    return concrete_seismic_analysis(*model.fe, model.seismic,
                                     {model.concrete,
                                      model.materials,
                                      fem::PlaneMode::plane_strain,
                                      {tags::dam}},
                                     {}, folder, model.tie.mat(),
                                     model.wave ? &*model.wave : nullptr,
                                     model.contact ? &*model.contact : nullptr);
  return linear_seismic_analysis(*model.fe, model.seismic, {}, folder,
                                 model.tie.mat(),
                                 model.contact ? &*model.contact : nullptr,
                                 model.wave ? &*model.wave : nullptr);
}

nlohmann::json arch_dam_results(MPI_Comm comm, const ArchDamConfig& cfg,
                                const ArchDamModel& model,
                                nlohmann::json summary,
                                const std::filesystem::path& out_dir)
{
  const auto& arch = model.mesh;
  const auto kind = cfg.concrete_model.kind;
  summary["analysis"] =
      std::string("arch dam, ") +
      (kind == ConcreteModelKind::linear
           ? std::string("linear elastic, ")
           : "HTC concrete (" + to_string(kind) + "), ") +
      (!cfg.wave       ? "massless foundation"
       : cfg.wave->mtf ? "foundation with mass, multi-transmitting boundary"
                       : "foundation with mass, viscous-spring boundary") +
      (model.contact ? ", contact joints" : "");
  std::size_t pairs = 0;
  for (const auto& j : arch.joints)
    pairs += j.size();
  if (model.contact)
    summary["joints"]["count"] = arch.joints.size(); // the analysis' entry
  else
    summary["joints"] = {
        {"count", arch.joints.size()}, {"model", "bonded"}, {"pairs", pairs}};
  summary["mesh_seconds"] = arch.total_seconds;
  write_summary_and_plots(comm, summary, out_dir, cfg.seismic.plots,
                          "plot_arch_dam.py");
  if (cfg.seismic.plots)
  {
    // The model with its tags (model.xdmf, for ParaView) and its pictures:
    // mesh_model.png in perspective and mesh_joints.png, the dam from
    // downstream with the joints labelled (the paper's Figs. 10-11, 16-17).
    geometry::write_model(arch.model, out_dir / "model.xdmf");
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    if (rank == 0)
    {
      const std::string cmd =
          std::string(DAMSEIS_PYTHON) + " " + DAMSEIS_SOURCE_DIR +
          "/scripts/plot_arch_mesh.py \"" + (out_dir / "model.xdmf").string() +
          "\" --out \"" + (out_dir / "mesh").string() + "\"";
      if (std::system(cmd.c_str()) != 0)
        std::fprintf(stderr, "warning: plotting failed: %s\n", cmd.c_str());
    }
  }
  return summary;
}

nlohmann::json run_arch_table1_study(MPI_Comm comm, const ArchDamConfig& cfg,
                                     const std::filesystem::path& out_dir,
                                     const ArchDamRun& analyse)
{
  const bool levels = cfg.table1_levels.size() > 1;
  std::vector<Table1Run> runs;
  for (double level : cfg.table1_levels)
  {
    std::ostringstream name;
    name << "level_" << level << "m";
    for (ConcreteModelKind kind :
         {ConcreteModelKind::elastic, ConcreteModelKind::plastic,
          ConcreteModelKind::viscoplastic})
    {
      ArchDamConfig c = with_reservoir_level(cfg, level);
      c.table1 = false;
      c.table1_levels.clear();
      c.concrete_model = with_model(cfg.concrete_model, kind);
      const std::filesystem::path dir =
          levels ? out_dir / name.str() / to_string(kind)
                 : out_dir / to_string(kind);
      results::print(comm, "== " + (levels ? name.str() + ", " : "") +
                               to_string(kind) + " ==");
      runs.push_back(
          {to_string(kind), levels ? level : std::nan(""), analyse(c, dir)});
    }
  }
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0)
    write_table1(runs, out_dir, true);
  return runs.back().summary;
}
} // namespace damseis::analysis
