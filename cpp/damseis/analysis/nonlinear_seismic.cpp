#include "nonlinear_seismic.h"
#include "concrete_stepper.h"
#include "concrete_system.h"
#include "engine_settings.h"
#include "ground_motion_load.h"
#include "modal_stage.h"
#include "recorders.h"
#include "run_outputs.h"
#include "static_stage.h"
#include <chrono>
#include <cmath>
#include <damseis/engine/time_history.h>
#include <damseis/fem/concrete_model.h>
#include <damseis/geometry/tags.h>
#include <damseis/linalg/petsc_vectors.h>
#include <damseis/results/displacement_envelope.h>
#include <damseis/results/face_points.h>
#include <damseis/results/field_writer.h>
#include <damseis/results/gather.h>
#include <damseis/results/point_probe.h>
#include <damseis/results/principal.h>
#include <damseis/results/progress.h>
#include <damseis/results/stress_envelope.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/la/petsc.h>
#include <dolfinx/mesh/Mesh.h>
#include <fstream>
#include <limits>
#include <sstream>

namespace damseis::analysis
{
namespace
{
using dolfinx::la::petsc::Matrix;
using dolfinx::la::petsc::Vector;
using nlohmann::json;
using Clock = std::chrono::steady_clock;

/// Per owned point of the stress space, the maximum over time of a scalar
/// and when it occurred.
struct ScalarEnvelope
{
  std::vector<double> max, t;
  explicit ScalarEnvelope(std::size_t n, double start = 0.0)
      : max(n, start), t(n, 0.0)
  {
  }
  void update(std::span<const double> v, double time)
  {
    for (std::size_t i = 0; i < max.size(); ++i)
    {
      if (v[i] > max[i])
      {
        max[i] = v[i];
        t[i] = time;
      }
    }
  }
};

/// The envelopes of the concrete state at the dam points: the strain rate,
/// the rate of kappa_t, and the vertical stress sigma_yy (the paper's Fig.
/// 8: largest and, as the largest of -sigma_yy, smallest; same stress as the
/// principal envelopes).
class ConcreteRecorder : public engine::Observer
{
public:
  ConcreteRecorder(const fem::ConcreteModel& cm, const StressRecorder& stresses,
                   std::int32_t points)
      : _envelopes{ScalarEnvelope(points), ScalarEnvelope(points),
                   ScalarEnvelope(points, -HUGE_VAL),
                   ScalarEnvelope(points, -HUGE_VAL)},
        _cm(cm), _stresses(stresses), _syy(points)
  {
  }
  void record(int, double t) override
  {
    rate().update(_cm.strain_rate(), t);
    kt_rate().update(_cm.kappa_t_rate(), t);
    const auto s = _stresses.stress();
    for (std::size_t i = 0; i < _syy.size(); ++i)
      _syy[i] = s[3 * i + 1];
    syy_max().update(_syy, t);
    for (double& v : _syy)
      v = -v;
    syy_min().update(_syy, t);
  }
  void save(engine::Arrays& arrays) const override
  {
    for (std::size_t i = 0; i < _envelopes.size(); ++i)
    {
      arrays[std::string(names[i]) + "_max"] = _envelopes[i].max;
      arrays[std::string(names[i]) + "_t"] = _envelopes[i].t;
    }
  }
  void restore(const engine::CheckpointData& d) override
  {
    for (std::size_t i = 0; i < _envelopes.size(); ++i)
    {
      _envelopes[i].max = engine::checkpoint_array(
          d, std::string(names[i]) + "_max", _syy.size());
      _envelopes[i].t = engine::checkpoint_array(
          d, std::string(names[i]) + "_t", _syy.size());
    }
  }
  ScalarEnvelope& rate() { return _envelopes[0]; }
  ScalarEnvelope& kt_rate() { return _envelopes[1]; }
  ScalarEnvelope& syy_max() { return _envelopes[2]; }
  ScalarEnvelope& syy_min() { return _envelopes[3]; }

private:
  /// The envelopes and their checkpoint names.
  std::array<ScalarEnvelope, 4> _envelopes;
  static constexpr std::array<const char*, 4> names = {"rate", "kt_rate",
                                                       "syy_hi", "syy_lo"};
  const fem::ConcreteModel& _cm;
  const StressRecorder& _stresses;
  std::vector<double> _syy;
};

/// Largest value over the flagged owned points of all ranks, with where and
/// when.
results::Extreme scalar_extreme(MPI_Comm comm, const ScalarEnvelope& e,
                                std::span<const double> coords,
                                const std::vector<std::int8_t>& flag)
{
  struct
  {
    double v;
    int rank;
  } local{-HUGE_VAL, 0}, global;
  MPI_Comm_rank(comm, &local.rank);
  std::size_t arg = 0;
  for (std::size_t i = 0; i < e.max.size(); ++i)
  {
    if (flag[i] && e.max[i] > local.v)
    {
      local.v = e.max[i];
      arg = i;
    }
  }
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm);
  std::array<double, 4> data = {0, 0, 0, 0};
  if (local.rank == global.rank && !e.max.empty())
    data = {coords[3 * arg], coords[3 * arg + 1], coords[3 * arg + 2],
            e.t[arg]};
  MPI_Bcast(data.data(), 4, MPI_DOUBLE, global.rank, comm);
  return {global.v, {data[0], data[1], data[2]}, data[3]};
}

/// Global number of cells of a region.
std::int64_t region_cell_count(MPI_Comm comm, const geometry::Model& model,
                               int region)
{
  const std::int32_t owned = model.mesh->topology()
                                 .index_map(model.mesh->topology().dim())
                                 ->size_local();
  std::int64_t n = 0;
  for (std::int32_t c : region_cells(model, region))
    n += c < owned ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &n, 1, MPI_INT64_T, MPI_SUM, comm);
  return n;
}

/// The snap-back limit of the cell size, E Gf / (s ft^2) [m], s the
/// snap-back safety factor (1.25; material/README.md).
double concrete_characteristic_length(const ConcreteSettings& c)
{
  const auto& p = c.params;
  return p.E * p.Gf / (p.snap_back_safety * p.ft0 * p.ft0);
}

/// dam_points.csv on rank 0: one row per owned dam point of every rank.
void write_dam_points(MPI_Comm comm, const results::StressEnvelope& env,
                      const std::vector<std::int8_t>& in_dam,
                      const std::vector<const std::vector<double>*>& columns,
                      const std::filesystem::path& file)
{
  const int nc = 4 + static_cast<int>(columns.size());
  std::vector<double> local;
  for (std::size_t i = 0; i < in_dam.size(); ++i)
  {
    if (!in_dam[i])
      continue;
    const auto& x = env.point(static_cast<std::int32_t>(i));
    local.insert(local.end(), {x[0], x[1], env.max_principal()[i] * 1e-6,
                               env.min_principal()[i] * 1e-6});
    for (const auto* c : columns)
      local.push_back((*c)[i]);
  }
  write_rows_csv(comm, local, nc,
                 "x_m,y_m,max_principal_mpa,min_principal_mpa,kappa_t,kappa_c,"
                 "max_strain_rate_per_s,t_max_strain_rate_s,"
                 "max_kappa_t_rate_per_s,max_syy_mpa,min_syy_mpa",
                 file);
}
} // namespace

json run_nonlinear_seismic(fem::ElasticModel& fe, const SeismicSettings& s,
                           const ConcreteBulk& bulk,
                           const std::vector<Vec>& extra_static_loads,
                           const RunFolder& folder)
{
  const ConcreteSettings& concrete = bulk.concrete;
  const std::filesystem::path& out_dir = folder.dir;
  const std::string& case_text = folder.case_text;
  results::set_stage("assembly");
  const auto wall_start = Clock::now();
  const auto model = fe.model();
  MPI_Comm comm = model.mesh->comm();
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const int dim = fe.dim();
  print_model_line(fe, ", concrete " + to_string(concrete.kind));

  const bool wet = s.reservoir.depth() > 0.0;
  const fem::Reservoir* added = s.westergaard && wet ? &s.reservoir : nullptr;
  Matrix K(fe.assemble_stiffness(), false);
  Matrix M(fe.assemble_mass(added), false);
  fem::ConcreteModel cm(fe, {{tags::dam, concrete.params}}, bulk.elastic,
                        bulk.plane);
  // An elastic material has no plastic strain to extrapolate: no IMPL-EX
  // steps, no extrapolated predictor.
  const bool plastic = concrete.kind != ConcreteModelKind::elastic;
  cm.set_implex(concrete.implex && plastic);
  ConcreteSystem system(cm);

  // Softening regularised by the crack band: say where it is not exact
  // (material/README.md, README "softening studies").
  if (plastic && fe.degree() > 1)
  {
    results::print(comm,
                   "note: P" + std::to_string(fe.degree()) +
                       " elements: the crack band (energy Gf per unit crack "
                       "area) is exact for P1 only (a P2 cell can localise in "
                       "part of its points: 0.75 Gf in the crack-band test); "
                       "use mesh.order = 1 for softening studies");
  }
  const auto ft_low = cm.reduced_tensile_strength_range();
  if (plastic && cm.cells_with_reduced_strength() > 0)
  {
    std::ostringstream note;
    note.precision(3);
    note << "note: " << cm.cells_with_reduced_strength() << " of "
         << region_cell_count(comm, model, tags::dam)
         << " dam cells are larger than E Gf / ("
         << concrete.params.snap_back_safety
         << " ft^2) = " << concrete_characteristic_length(concrete)
         << " m (snap-back "
         << "limit of the softening): their tensile strength is lowered "
         << "from " << concrete.params.ft0 * 1e-6 << " to " << ft_low[0] * 1e-6
         << ".." << ft_low[1] * 1e-6
         << " MPa (the crack band is not honoured there; summary.json "
            "concrete.cells_with_reduced_tensile_strength); refine the mesh "
            "where the concrete cracks";
    results::print(comm, note.str());
  }

  // Modal analysis of the initial elastic system; Rayleigh damping with K0.
  results::set_stage("modal analysis");
  Matrix M0(nullptr, false);
  if (added)
    M0 = Matrix(fe.assemble_mass(nullptr), false);
  const ModalResult modal =
      modal_and_damping(K.mat(), M.mat(), added ? M0.mat() : nullptr, s);

  // Static stage: dead weight, then the reservoir (and silt, uplift) in
  // increments, with the rate-independent material.
  results::set_stage("static stage");
  std::array<double, 3> g = {0, 0, 0};
  g[dim - 1] = -s.gravity;
  Vector F_g(fe.assemble_gravity(g), false);
  Vector F_static = linalg::column_vector(K.mat());
  VecCopy(F_g.vec(), F_static.vec());
  if (wet)
  {
    Vector H(fe.assemble_hydrostatic(s.reservoir), false);
    VecAXPY(F_static.vec(), 1.0, H.vec());
  }
  for (Vec extra : extra_static_loads)
    VecAXPY(F_static.vec(), 1.0, extra);
  Vector u_static = linalg::column_vector(K.mat());
  StaticStageSettings stage;
  stage.increments = concrete.static_increments;
  stage.newton = concrete.newton;
  stage.factorization = s.factorization;
  stage.f1_hz = modal.f1;
  stage.f2_hz = modal.f2;
  const StaticStageReport static_stage =
      solve_static_stage(system, K.mat(), M.mat(), F_g.vec(), F_static.vec(),
                         u_static.vec(), stage);
  const std::vector<double> sig_static(cm.stress().begin(), cm.stress().end());
  Vector fint0 = linalg::column_vector(K.mat());
  system.internal_force(fint0.vec());
  const double static_seconds = seconds_since(wall_start) - modal.seconds;
  results::print(comm,
                 "static stage: " + std::to_string(static_stage.iterations) +
                     " Newton iterations, " +
                     std::to_string(system.accepted.inelastic) +
                     " inelastic points");

  // Dynamic stage: M a + C v + f_int(u) = F_static - M sum_c r_c a_gc(t),
  // u relative to the base, total (static included).
  // (IMPL-EX steps are extrapolated anyway.)
  dynamics::NewtonSettings newton_settings = concrete.newton;
  newton_settings.extrapolated_predictor =
      concrete.newton.extrapolated_predictor && !concrete.implex && plastic;
  ConcreteStepper stepper(M.mat(), K.mat(), modal.damping, s.scheme, system, cm,
                          newton_settings, s.factorization, u_static.vec(),
                          fint0.vec());
  const GroundMotionLoad ground(fe, s, M.mat(), nullptr, F_static.vec());

  std::filesystem::create_directories(out_dir);
  if (rank == 0)
    std::ofstream(out_dir / "case_used.toml") << case_text;
  write_modes(
      fe, modal.modes, [](Vec x) { return x; }, out_dir / "modes.xdmf");

  // Recorders. Points: the quadrature points of the owned cells.
  auto Sq = cm.stress_space();
  const std::int32_t n_pts = Sq->dofmap()->index_map->size_local();
  std::vector<std::int8_t> in_dam(n_pts, 0);
  for (std::int32_t c : region_cells(model, tags::dam))
  {
    for (std::int32_t d : Sq->dofmap()->cell_dofs(c))
    {
      if (d < n_pts)
        in_dam[d] = 1;
    }
  }
  FullDisplacement u(stepper, nullptr);
  std::vector<double> s_field(cm.stress().size());
  StressRecorder stresses(results::StressEnvelope(3, cm.coordinates(), in_dam),
                          [&]() -> std::span<const double>
                          {
                            auto sig = cm.stress();
                            for (std::size_t i = 0; i < s_field.size(); ++i)
                              s_field[i] = s.stress_total
                                               ? sig[i]
                                               : sig[i] - sig_static[i];
                            return s_field;
                          });
  ConcreteRecorder concrete_state(cm, stresses, n_pts);
  std::vector<std::vector<std::int32_t>> face_pts;
  for (const auto& [name, face_tags] : s.faces)
    face_pts.push_back(
        results::face_points(*Sq, *model.facet_tags, face_tags, false));
  PointHistories points(*fe.V(), s.crest_point, s.base_point, s.steps, u);
  const auto crest_static = points.crest().value_on_all(u_static.vec());
  const auto base_static = points.base().value_on_all(u_static.vec());
  // Envelope of the seismic horizontal displacement along the upstream face.
  FaceDisplacementRecorder face_u(*fe.V(), *model.facet_tags,
                                  tags::upstream_face, points.base(), u,
                                  u_static.vec(), base_static[0]);
  FieldRecorder fields(fe, out_dir, s.output_every, [&] { return u.vec(); },
                       stresses,
                       {Sq,
                        {"kappa_t", "kappa_c", "strain_rate_per_s"},
                        [&]() -> std::vector<std::span<const double>> {
                          return {cm.kappa_t(), cm.kappa_c(), cm.strain_rate()};
                        }});

  // The time history.
  engine::TimeHistory history(
      comm, time_history_settings(s, fe, out_dir, case_text), stepper, ground);
  for (engine::Observer* o : std::initializer_list<engine::Observer*>{
           &u, &stresses, &concrete_state, &points, &face_u, &fields})
    history.observe(*o);
  const engine::TimeHistoryReport run = history.run();
  const int n = s.steps;
  const double dt = s.scheme.dt;
  const auto& envelope = stresses.envelope();
  results::set_stage("writing outputs");
  const std::vector<double>& hist = points.reduce(comm);
  const json crest_summary =
      write_crest_history(comm, hist, dim, n, dt, crest_static, base_static,
                          true, out_dir / "crest.csv");

  // Envelopes: stresses, and the state variables as cell maxima.
  std::vector<double> rate_all(cm.strain_rate().size(), 0.0),
      kt_rate_all(rate_all.size(), 0.0);
  std::copy(concrete_state.rate().max.begin(), concrete_state.rate().max.end(),
            rate_all.begin());
  std::copy(concrete_state.kt_rate().max.begin(),
            concrete_state.kt_rate().max.end(), kt_rate_all.begin());
  results::write_envelopes(fe, envelope, region_cells(model, tags::dam),
                           out_dir / "envelopes.xdmf", Sq, false,
                           {{"kappa_t", cm.kappa_t()},
                            {"kappa_c", cm.kappa_c()},
                            {"max_strain_rate_per_s", rate_all},
                            {"max_kappa_t_rate_per_s", kt_rate_all}});
  const json faces = write_faces(comm, s, envelope, face_pts, dim, out_dir);
  face_u.write_csv(comm, out_dir / "displacement_envelope.csv");
  {
    std::vector<double> kt(cm.kappa_t().begin(), cm.kappa_t().begin() + n_pts),
        kc(cm.kappa_c().begin(), cm.kappa_c().begin() + n_pts);
    std::vector<double> syy_hi(n_pts), syy_lo(n_pts);
    for (std::int32_t i = 0; i < n_pts; ++i)
    {
      syy_hi[i] = 1e-6 * concrete_state.syy_max().max[i];
      syy_lo[i] = -1e-6 * concrete_state.syy_min().max[i];
    }
    write_dam_points(comm, envelope, in_dam,
                     {&kt, &kc, &concrete_state.rate().max,
                      &concrete_state.rate().t, &concrete_state.kt_rate().max,
                      &syy_hi, &syy_lo},
                     out_dir / "dam_points.csv");
  }
  ScalarEnvelope kt_final(n_pts);
  kt_final.update(cm.kappa_t(), n * dt);
  const auto kt_max = scalar_extreme(comm, kt_final, cm.coordinates(), in_dam);
  const auto rate_max =
      scalar_extreme(comm, concrete_state.rate(), cm.coordinates(), in_dam);
  const auto syy_hi =
      scalar_extreme(comm, concrete_state.syy_max(), cm.coordinates(), in_dam);
  const auto syy_lo =
      scalar_extreme(comm, concrete_state.syy_min(), cm.coordinates(), in_dam);

  // The Newton statistics cover every step (restored at a restart).
  const int steps_all = std::max(1, n);
  const NewtonTotals& nt = stepper.totals();
  const auto& p = concrete.params;
  json summary = seismic_summary(
      comm, fe, s, modal, added != nullptr, points.crest().node(), envelope,
      faces, stepper.solver_name(),
      {static_seconds, modal.seconds, stepper.factor_seconds(),
       run.loop_seconds, run.restarted_from_step});
  summary.update(crest_summary);
  summary["concrete"] = {
      {"model", to_string(concrete.kind)},
      {"E_pa", p.E},
      {"fc_mpa", p.fc0 * 1e-6},
      {"ft_mpa", p.ft0 * 1e-6},
      {"Gf_n_per_m", p.Gf},
      {"static_E_pa", concrete.static_E},
      {"static_fc_mpa", concrete.static_fc * 1e-6},
      {"static_ft_mpa", concrete.static_ft * 1e-6},
      {"factor_E", concrete.applied.E},
      {"factor_strength", concrete.applied.strength},
      {"material_bins", cm.material_count()},
      {"material_integration", concrete.implex ? "implex" : "implicit"},
      {"characteristic_length_m", concrete_characteristic_length(concrete)},
      {"cells_with_reduced_tensile_strength", cm.cells_with_reduced_strength()},
      // Energy Gf per unit crack area whatever the mesh: P1 cells no
      // larger than the snap-back limit.
      {"crack_band_exact",
       fe.degree() == 1 && cm.cells_with_reduced_strength() == 0}};
  if (cm.cells_with_reduced_strength() > 0)
  {
    summary["concrete"]["reduced_tensile_strength_mpa"] = {
        {"min", ft_low[0] * 1e-6}, {"max", ft_low[1] * 1e-6}};
  }
  summary["max_kappa_t"] = {{"value", kt_max.value},
                            {"x", coordinate(kt_max.x[0])},
                            {"y", coordinate(kt_max.x[1])}};
  summary["max_strain_rate_per_s"] = {{"value", rate_max.value},
                                      {"x", coordinate(rate_max.x[0])},
                                      {"y", coordinate(rate_max.x[1])},
                                      {"t", instant(rate_max.t)}};
  summary["max_vertical_stress_mpa"] = {{"value", 1e-6 * syy_hi.value},
                                        {"x", coordinate(syy_hi.x[0])},
                                        {"y", coordinate(syy_hi.x[1])},
                                        {"t", instant(syy_hi.t)}};
  summary["min_vertical_stress_mpa"] = {{"value", -1e-6 * syy_lo.value},
                                        {"x", coordinate(syy_lo.x[0])},
                                        {"y", coordinate(syy_lo.x[1])},
                                        {"t", instant(syy_lo.t)}};
  summary["static_stage"] = static_stage.to_json();
  summary["newton"] = {
      {"rtol", concrete.newton.rtol},
      {"extrapolated_predictor", newton_settings.extrapolated_predictor},
      {"static_iterations", static_stage.iterations},
      {"static_cuts", static_stage.cuts},
      {"iterations", nt.iterations},
      {"iterations_per_step", nt.iterations / steps_all},
      {"max_iterations_in_a_step", nt.max_iterations_in_a_step},
      {"tangent_factorizations", nt.tangent_factorizations},
      {"krylov_iterations", nt.krylov_iterations},
      {"substepped_point_updates", nt.substepped},
      {"return_maps", nt.return_maps},
      {"local_newton_iterations", nt.local_iterations},
      // In-run throughput of the points that left the elastic fast path
      // (plane stress: all return maps of a point's sigma_zz iteration and
      // its tangent), per core.
      {"returned_points", nt.returned_points},
      {"returned_points_per_core_second",
       nt.return_map_seconds > 0.0 ? nt.returned_points / nt.return_map_seconds
                                   : 0.0},
      {"seconds",
       {{"residual", nt.seconds_residual},
        {"tangent_assembly", nt.seconds_tangent},
        {"factorization", nt.seconds_factorization},
        {"direction_solves", nt.seconds_solve},
        {"return_maps_core_seconds", nt.return_map_seconds}}},
      {"step_cuts", nt.cuts},
      {"max_inelastic_points", nt.max_inelastic_points}};
  if (concrete.implex)
  {
    // How far the implicit stresses of the IMPL-EX steps are from
    // equilibrium, in the units of the Newton tolerance (README).
    summary["implex_equilibrium_error"] = {
        {"rms", std::sqrt(nt.implex_error_squares / steps_all)},
        {"max", nt.implex_error_max},
        {"t_of_max", nt.implex_error_time}};
  }
  summary["wall_seconds"] = seconds_since(wall_start);
  print_summary_line(comm, summary,
                     ", Newton iterations per step " +
                         std::to_string(nt.iterations / steps_all));
  return summary;
}
} // namespace damseis::analysis
