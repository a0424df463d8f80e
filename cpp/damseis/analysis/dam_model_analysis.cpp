#include "dam_model_analysis.h"
#include "nonlinear_seismic.h"
#include "run_outputs.h"
#include <damseis/fem/group_loads.h>
#include <damseis/fem/tied_dofs.h>
#include <damseis/geometry/tagged.h>
#include <damseis/results/progress.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DirichletBC.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/fem/petsc.h>
#include <dolfinx/mesh/MeshTags.h>

namespace damseis::analysis
{
namespace
{
using dolfinx::la::petsc::Vector;

/// The initial velocity: per group the value at the nodes of its cells
/// (the later group wins on shared nodes), zero at fixed dofs. A node is
/// marked from every rank that holds one of the group's cells (summed into
/// its owner), so the result does not depend on the partition.
Vector initial_velocity(const fem::ElasticModel& fe, const DamModelConfig& cfg)
{
  const auto& map = *fe.V()->dofmap()->index_map;
  const int bs = fe.V()->dofmap()->index_map_bs();
  const std::int32_t owned = map.size_local();
  Vector v(dolfinx::la::petsc::create_vector(map, bs), false);
  Vector marker(dolfinx::la::petsc::create_vector(map, 1), false);
  VecSet(v.vec(), 0.0);
  for (const GroupVector& g : cfg.initial_velocity)
  {
    // Mark the group's nodes (owned and ghost), sum into the owners.
    Vec local;
    VecGhostGetLocalForm(marker.vec(), &local);
    VecSet(local, 0.0);
    double* m = nullptr;
    VecGetArray(local, &m);
    const int tag = cfg.mesh->groups.at(g.group).tag;
    for (std::int32_t c : region_cells(fe.model(), tag))
      for (std::int32_t b : fe.V()->dofmap()->cell_dofs(c))
        m[b] = 1.0;
    VecRestoreArray(local, &m);
    VecGhostRestoreLocalForm(marker.vec(), &local);
    VecGhostUpdateBegin(marker.vec(), ADD_VALUES, SCATTER_REVERSE);
    VecGhostUpdateEnd(marker.vec(), ADD_VALUES, SCATTER_REVERSE);
    const double* mk = nullptr;
    double* a = nullptr;
    VecGetArrayRead(marker.vec(), &mk);
    VecGetArray(v.vec(), &a);
    for (std::int32_t b = 0; b < owned; ++b)
      if (mk[b] > 0.0)
        for (int k = 0; k < bs; ++k)
          a[b * bs + k] = g.value[k];
    VecRestoreArray(v.vec(), &a);
    VecRestoreArrayRead(marker.vec(), &mk);
  }
  dolfinx::fem::petsc::set_bc(v.vec(), fe.bcs(), nullptr, 0.0);
  return v;
}
} // namespace

ModelLoads DamModel::loads(const DamModelConfig& cfg) const
{
  ModelLoads l;
  for (const auto& b : body_forces)
    l.static_loads.push_back(b.vec());
  // "static" tractions act before t = 0 and stay: a static load.
  for (const auto& t : tractions)
    if (cfg.traction_history_kind == "static")
      l.static_loads.push_back(t.vec());
    else
      l.timed.push_back({t.vec(), cfg.traction_history});
  l.initial_velocity = initial_velocity.vec();
  return l;
}

DamModel dam_model(MPI_Comm comm, const DamModelConfig& cfg)
{
  results::set_stage("model");
  DamModel m;
  // The dam's E is that of its concrete model (the factors of
  // material.model, as in the gravity-dam demos).
  std::map<int, fem::Material> materials;
  for (const Region& r : cfg.regions)
  {
    fem::Material mat = r.material;
    if (r.dam)
      mat.E = cfg.concrete.params.E;
    materials[cfg.mesh->groups.at(r.group).tag] = mat;
  }
  m.fe = std::make_unique<fem::ElasticModel>(cfg.mesh->model, cfg.order,
                                             materials, cfg.plane);
  // Fixed supports, or rock held by its viscous-spring boundary, or by its
  // multi-transmitting boundary (fixed for the static and modal stages; the
  // time history prescribes it).
  std::vector<int> fixed;
  for (const auto& g : cfg.fixed)
    fixed.push_back(facet_tag(cfg, g));
  for (const auto& g : cfg.transmitting)
    fixed.push_back(facet_tag(cfg, g));
  if (!fixed.empty())
    m.fe->fix(fixed);

  // Bonded joints: the sides' coincident dofs tied (checked node for node
  // when the case was read).
  std::vector<std::pair<int, int>> pairs;
  for (const auto& [side1, side2] : cfg.joints)
    pairs.emplace_back(cfg.mesh->groups.at(side1).tag,
                       cfg.mesh->groups.at(side2).tag);
  if (!pairs.empty())
  {
    m.tie = dolfinx::la::petsc::Matrix(
        fem::tie_prolongation(*m.fe->V(), *cfg.group_facets, pairs,
                              cfg.joint_tolerance),
        false);
    PetscInt rows = 0, cols = 0;
    MatGetSize(m.tie.mat(), &rows, &cols);
    m.joint_pairs = (rows - cols) / m.fe->dim();
  }
  if (cfg.contact.enabled)
  {
    ContactJoints c;
    for (std::size_t j = 0; j < cfg.joints.size(); ++j)
    {
      const auto& [side1, side2] = cfg.joints[j];
      c.joints.push_back(
          {side1, cfg.mesh->groups.at(side1).tag,
           cfg.mesh->groups.at(side2).tag, cfg.contact.friction[j],
           cfg.contact.keyed[j], cfg.contact.joint.tensile_strength[j],
           cfg.contact.joint.cohesion[j], cfg.contact.joint.initial_gap[j]});
    }
    c.facet_tags = cfg.group_facets.get();
    c.restitution = cfg.contact.restitution;
    c.statics = cfg.contact.statics;
    c.history_points = cfg.contact.history_points;
    c.ncp = cfg.contact.ncp;
    c.tolerance = cfg.joint_tolerance;
    m.contact = std::move(c);
  }

  // Loads beyond dead weight, water and ground motion.
  for (const GroupVector& b : cfg.body_forces)
  {
    const int tag = cfg.mesh->groups.at(b.group).tag;
    m.body_forces.emplace_back(
        fem::assemble_body_force(*m.fe, region_cells(m.fe->model(), tag),
                                 b.value),
        false);
  }
  for (const GroupVector& t : cfg.tractions)
  {
    m.tractions.emplace_back(
        fem::assemble_traction(
            *m.fe,
            geometry::tagged_entities(*cfg.group_facets,
                                      {cfg.mesh->groups.at(t.group).tag}),
            t.value),
        false);
  }
  if (!cfg.initial_velocity.empty())
    m.initial_velocity = initial_velocity(*m.fe, cfg);
  results::print(comm, "model of " + cfg.mesh_file.filename().string() + ": " +
                           std::to_string(cfg.regions.size()) + " regions, " +
                           std::to_string(cfg.joints.size()) + " joints (" +
                           std::to_string(m.joint_pairs) + " node pairs " +
                           (cfg.contact.enabled ? "in contact)" : "tied)"));
  return m;
}

std::unique_ptr<SeismicAnalysis>
dam_model_seismic_analysis(DamModel& model, const DamModelConfig& cfg,
                           const RunFolder& folder)
{
  if (cfg.concrete.kind == ConcreteModelKind::linear)
    return linear_seismic_analysis(*model.fe, cfg.seismic, model.loads(cfg),
                                   folder, model.tie.mat(),
                                   model.contact ? &*model.contact : nullptr,
                                   cfg.wave ? &*cfg.wave : nullptr);
  ConcreteBulk bulk{cfg.concrete, {}, cfg.plane, cfg.seismic.dam_regions};
  for (const Region& r : cfg.regions)
  {
    fem::Material mat = r.material;
    if (r.dam)
      mat.E = cfg.concrete.params.E;
    bulk.elastic[cfg.mesh->groups.at(r.group).tag] = mat;
  }
  return concrete_seismic_analysis(*model.fe, cfg.seismic, bulk,
                                   model.loads(cfg), folder, model.tie.mat(),
                                   cfg.wave ? &*cfg.wave : nullptr,
                                   model.contact ? &*model.contact : nullptr);
}

nlohmann::json dam_model_results(MPI_Comm comm, const DamModelConfig& cfg,
                                 const DamModel& model, nlohmann::json summary,
                                 const std::filesystem::path& out_dir)
{
  summary["analysis"] =
      (cfg.concrete.kind == ConcreteModelKind::linear
           ? std::string("user mesh, linear elastic")
           : "user mesh, HTC concrete (" + to_string(cfg.concrete.kind) + ")") +
      (!cfg.wave       ? ""
       : cfg.wave->mtf ? ", rock with mass and a multi-transmitting boundary"
                       : ", rock with mass and a viscous-spring boundary");
  summary["mesh_file"] = cfg.mesh_file.string();
  nlohmann::json regions = nlohmann::json::array();
  for (const Region& r : cfg.regions)
    regions.push_back({{"group", r.group},
                       {"E_pa", r.material.E},
                       {"nu", r.material.nu},
                       {"rho", r.material.rho},
                       {"dam", r.dam}});
  summary["regions"] = regions;
  if (cfg.contact.enabled)
    summary["joints"]["count"] = cfg.joints.size(); // the analysis' entry
  else
    summary["joints"] = {{"count", cfg.joints.size()},
                         {"model", "bonded"},
                         {"pairs", model.joint_pairs}};
  summary["loads"] = {{"tractions", cfg.tractions.size()},
                      {"traction_history", cfg.traction_history_kind},
                      {"body_forces", cfg.body_forces.size()},
                      {"initial_velocity_groups", cfg.initial_velocity.size()}};
  write_summary_and_plots(comm, summary, out_dir, cfg.seismic.plots,
                          cfg.dim == 2 ? "plot_gravity_dam.py"
                                       : "plot_arch_dam.py");
  return summary;
}
} // namespace damseis::analysis
