#include "nonlinear_seismic.h"
#include "checkpoint.h"
#include "concrete_system.h"
#include "ground_motion_load.h"
#include "linear_seismic.h"
#include "modal_stage.h"
#include "run_outputs.h"
#include "static_stage.h"
#include "stop_signals.h"
#include <chrono>
#include <cmath>
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
                           const ConcreteSettings& concrete,
                           const std::map<int, fem::Material>& elastic,
                           fem::PlaneMode plane,
                           const std::vector<Vec>& extra_static_loads,
                           const std::filesystem::path& out_dir,
                           const std::string& case_text)
{
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
  fem::ConcreteModel cm(fe, {{tags::dam, concrete.params}}, elastic, plane);
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
  dynamics::NonlinearNewmark newmark(M.mat(), K.mat(), modal.damping, s.scheme,
                                     system, newton_settings, s.factorization);
  const GroundMotionLoad ground(fe, s, M.mat());
  Vector f = linalg::column_vector(K.mat());
  auto set_load = [&](int k) { ground.assemble(k, F_static.vec(), f.vec()); };

  std::filesystem::create_directories(out_dir);
  if (rank == 0)
    std::ofstream(out_dir / "case_used.toml") << case_text;
  write_modes(
      fe, modal.modes, [](Vec x) { return x; }, out_dir / "modes.xdmf");

  // Points: the quadrature points of the owned cells.
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
  results::StressEnvelope envelope(3, cm.coordinates(), in_dam);
  ScalarEnvelope rate_env(n_pts), kt_rate_env(n_pts);
  // Vertical stress sigma_yy (the paper's Fig. 8): largest and, as the
  // largest of -sigma_yy, smallest; same stress as the principal envelopes.
  ScalarEnvelope syy_max(n_pts, -HUGE_VAL), syy_min(n_pts, -HUGE_VAL);
  std::vector<double> syy(n_pts);
  std::vector<std::vector<std::int32_t>> face_pts;
  for (const auto& [name, face_tags] : s.faces)
    face_pts.push_back(
        results::face_points(*Sq, *model.facet_tags, face_tags, false));

  results::PointProbe crest(*fe.V(), s.crest_point);
  results::PointProbe base(*fe.V(), s.base_point);
  const auto crest_static = crest.value_on_all(u_static.vec());
  const auto base_static = base.value_on_all(u_static.vec());
  // Envelope of the seismic horizontal displacement along the upstream face.
  results::DisplacementEnvelope face_u(*fe.V(), *model.facet_tags,
                                       tags::upstream_face);
  const int n = s.steps;
  const double dt = s.scheme.dt;
  std::vector<double> hist(2 * dim * (n + 1), 0.0);
  // Newton statistics of the time history (checkpointed): iterations,
  // tangent factorisations, cuts, max iterations in a step, max inelastic
  // points, GMRES iterations, seconds in residuals, tangent assembly,
  // factorisations and direction solves, sub-stepped point updates, return
  // maps, local Newton iterations, points that left the elastic fast path
  // and the core-seconds of their updates; IMPL-EX equilibrium error: sum of
  // squares, largest, its time.
  std::vector<double> stats(18, 0.0);

  int k0 = 0;
  const std::filesystem::path ckpt_dir = out_dir / "checkpoint";
  const std::vector<double> coords = fe.V()->tabulate_dof_coordinates(false);
  const std::uint64_t print = fingerprint(coords) ^ case_fingerprint(case_text);
  std::optional<CheckpointData> restart;
  if (s.restart)
    restart = read_checkpoint(comm, ckpt_dir, print);
  if (restart)
  {
    k0 = restart->step;
    Vector u = linalg::column_vector(K.mat()),
           v = linalg::column_vector(K.mat()),
           a = linalg::column_vector(K.mat()),
           fi = linalg::column_vector(K.mat());
    const CheckpointData& d = *restart;
    const std::size_t np = static_cast<std::size_t>(n_pts);
    restore_collectively(
        comm, ckpt_dir,
        [&]
        {
          linalg::set_owned_values(u.vec(), checkpoint_array(d, "u"));
          linalg::set_owned_values(v.vec(), checkpoint_array(d, "v"));
          linalg::set_owned_values(a.vec(), checkpoint_array(d, "a"));
          linalg::set_owned_values(fi.vec(), checkpoint_array(d, "f_int"));
          cm.restore(d.arrays);
          envelope.restore(
              checkpoint_array(d, "env_max"), checkpoint_array(d, "env_t_max"),
              checkpoint_array(d, "env_min"), checkpoint_array(d, "env_t_min"));
          rate_env.max = checkpoint_array(d, "rate_max", np);
          rate_env.t = checkpoint_array(d, "rate_t", np);
          kt_rate_env.max = checkpoint_array(d, "kt_rate_max", np);
          kt_rate_env.t = checkpoint_array(d, "kt_rate_t", np);
          syy_max.max = checkpoint_array(d, "syy_max", np);
          syy_max.t = checkpoint_array(d, "syy_t_max", np);
          syy_min.max = checkpoint_array(d, "syy_min", np);
          syy_min.t = checkpoint_array(d, "syy_t_min", np);
          face_u.restore(checkpoint_array(d, "face_u"));
          hist = checkpoint_array(d, "history", hist.size());
          stats = checkpoint_array(d, "newton");
          if (stats.size() > 18)
            throw std::runtime_error("array newton is too long");
          stats.resize(18, 0.0);
        });
    set_load(k0);
    newmark.set_state(u.vec(), v.vec(), a.vec(), f.vec(), fi.vec());
    results::print(comm, "restarting from the checkpoint at step " +
                             std::to_string(k0));
  }
  else
  {
    Vector v0 = linalg::column_vector(K.mat()),
           a0 = linalg::column_vector(K.mat());
    ground.initial_acceleration(a0.vec());
    set_load(0);
    newmark.set_state(u_static.vec(), v0.vec(), a0.vec(), f.vec(), fint0.vec());
  }

  results::FieldWriter writer(
      fe,
      out_dir / (k0 == 0 ? std::string("fields.xdmf")
                         : "fields_from_step" + std::to_string(k0) + ".xdmf"),
      Sq, {"kappa_t", "kappa_c", "strain_rate_per_s"});
  dolfinx::fem::Function<double> u_fn(fe.V());
  std::vector<double> s_field(cm.stress().size());

  auto record_state = [&](int k, double t)
  {
    auto sig = cm.stress();
    if (s.stress_total)
      std::copy(sig.begin(), sig.end(), s_field.begin());
    else
    {
      for (std::size_t i = 0; i < s_field.size(); ++i)
        s_field[i] = sig[i] - sig_static[i];
    }
    envelope.update(std::span<const double>(s_field.data(), 3 * n_pts), t);
    rate_env.update(cm.strain_rate(), t);
    kt_rate_env.update(cm.kappa_t_rate(), t);
    for (std::int32_t i = 0; i < n_pts; ++i)
      syy[i] = s_field[3 * i + 1];
    syy_max.update(syy, t);
    for (double& v : syy)
      v = -v;
    syy_min.update(syy, t);
    const auto c = crest.value(newmark.u()), b = base.value(newmark.u());
    face_u.update(newmark.u(),
                  base.value_on_all(newmark.u())[0] - base_static[0],
                  u_static.vec());
    for (int i = 0; i < dim; ++i)
    {
      hist[2 * dim * k + i] = c[i];
      hist[2 * dim * k + dim + i] = b[i];
    }
    if (k % s.output_every == 0)
    {
      linalg::to_function(newmark.u(), u_fn);
      writer.write(u_fn, s_field, t,
                   {cm.kappa_t(), cm.kappa_c(), cm.strain_rate()});
    }
  };
  auto checkpoint = [&](int k)
  {
    CheckpointData data;
    data.step = k;
    data.arrays = cm.save();
    data.arrays["u"] = linalg::owned_values(newmark.u());
    data.arrays["v"] = linalg::owned_values(newmark.v());
    data.arrays["a"] = linalg::owned_values(newmark.a());
    data.arrays["f_int"] = linalg::owned_values(newmark.f_int());
    data.arrays["history"] = hist;
    data.arrays["newton"] = stats;
    auto span_vec = [](std::span<const double> x)
    { return std::vector<double>(x.begin(), x.end()); };
    data.arrays["env_max"] = span_vec(envelope.max_principal());
    data.arrays["env_t_max"] = span_vec(envelope.max_times());
    data.arrays["env_min"] = span_vec(envelope.min_principal());
    data.arrays["env_t_min"] = span_vec(envelope.min_times());
    data.arrays["rate_max"] = rate_env.max;
    data.arrays["rate_t"] = rate_env.t;
    data.arrays["kt_rate_max"] = kt_rate_env.max;
    data.arrays["kt_rate_t"] = kt_rate_env.t;
    data.arrays["syy_max"] = syy_max.max;
    data.arrays["syy_t_max"] = syy_max.t;
    data.arrays["syy_min"] = syy_min.max;
    data.arrays["syy_t_min"] = syy_min.t;
    data.arrays["face_u"] = face_u.save();
    write_checkpoint(comm, ckpt_dir, data, print);
  };

  results::set_stage("time history");
  results::print(comm, "time history: " + std::to_string(n) + " steps of " +
                           std::to_string(dt) + " s, factorisation " +
                           newmark.solver().name());
  if (k0 == 0)
    record_state(0, 0.0);
  StopSignals signals;
  results::Progress progress(comm, n - k0);
  // count the time history only
  system.reset_counts();
  const auto loop_start = Clock::now();
  for (int k = k0 + 1; k <= n; ++k)
  {
    set_load(k);
    dynamics::StepReport rep;
    try
    {
      rep = newmark.step(f.vec());
    }
    catch (const dynamics::StepFailure& e)
    {
      throw dynamics::StepFailure("step " + std::to_string(k) + " (t = " +
                                  std::to_string(k * dt) + " s): " + e.what());
    }
    stats[0] += rep.iterations;
    stats[1] += rep.tangent_factorizations;
    stats[2] += rep.cuts;
    stats[3] = std::max(stats[3], double(rep.iterations));
    stats[4] = std::max(stats[4], double(system.accepted.inelastic));
    stats[5] += rep.krylov_iterations;
    stats[6] += rep.seconds_residual;
    stats[7] += rep.seconds_tangent;
    stats[8] += rep.seconds_factorization;
    stats[9] += rep.seconds_solve;
    stats[10] += static_cast<double>(system.substepped);
    stats[11] += static_cast<double>(system.return_maps);
    stats[12] += static_cast<double>(system.local_iterations);
    stats[13] += static_cast<double>(system.returned_points);
    stats[14] += system.return_map_seconds;
    stats[15] += rep.extrapolation_error * rep.extrapolation_error;
    if (rep.extrapolation_error > stats[16])
    {
      stats[16] = rep.extrapolation_error;
      stats[17] = k * dt;
    }
    system.reset_counts();
    record_state(k, k * dt);
    progress.report(
        k - k0, k * dt,
        "  Newton " + std::to_string(rep.iterations) +
            (rep.tangent_factorizations
                 ? " (" + std::to_string(rep.tangent_factorizations) +
                       " tangents)"
                 : std::string()) +
            (rep.cuts ? ", " + std::to_string(rep.cuts) + " cuts"
                      : std::string()) +
            ", inelastic points " + std::to_string(system.accepted.inelastic));
    signals.checkpoint_or_stop(comm, s, k, n, checkpoint, ckpt_dir);
  }
  const double loop_seconds = seconds_since(loop_start);
  results::set_stage("writing outputs");
  results::reduce_history(comm, hist);
  const json crest_summary =
      write_crest_history(comm, hist, dim, n, dt, crest_static, base_static,
                          true, out_dir / "crest.csv");

  // Envelopes: stresses, and the state variables as cell maxima.
  std::vector<double> rate_all(cm.strain_rate().size(), 0.0),
      kt_rate_all(rate_all.size(), 0.0);
  std::copy(rate_env.max.begin(), rate_env.max.end(), rate_all.begin());
  std::copy(kt_rate_env.max.begin(), kt_rate_env.max.end(),
            kt_rate_all.begin());
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
      syy_hi[i] = 1e-6 * syy_max.max[i];
      syy_lo[i] = -1e-6 * syy_min.max[i];
    }
    write_dam_points(comm, envelope, in_dam,
                     {&kt, &kc, &rate_env.max, &rate_env.t, &kt_rate_env.max,
                      &syy_hi, &syy_lo},
                     out_dir / "dam_points.csv");
  }
  ScalarEnvelope kt_final(n_pts);
  kt_final.update(cm.kappa_t(), n * dt);
  const auto kt_max = scalar_extreme(comm, kt_final, cm.coordinates(), in_dam);
  const auto rate_max =
      scalar_extreme(comm, rate_env, cm.coordinates(), in_dam);
  const auto syy_hi = scalar_extreme(comm, syy_max, cm.coordinates(), in_dam);
  const auto syy_lo = scalar_extreme(comm, syy_min, cm.coordinates(), in_dam);

  // The Newton statistics cover every step (restored at a restart).
  const int steps_all = std::max(1, n);
  const auto& p = concrete.params;
  json summary =
      seismic_summary(comm, fe, s, modal, added != nullptr, crest.node(),
                      envelope, faces, newmark.solver().name(),
                      {static_seconds, modal.seconds,
                       newmark.solver().factor_seconds(), loop_seconds, k0});
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
      {"iterations", stats[0]},
      {"iterations_per_step", stats[0] / steps_all},
      {"max_iterations_in_a_step", stats[3]},
      {"tangent_factorizations", stats[1]},
      {"krylov_iterations", stats[5]},
      {"substepped_point_updates", stats[10]},
      {"return_maps", stats[11]},
      {"local_newton_iterations", stats[12]},
      // In-run throughput of the points that left the elastic fast path
      // (plane stress: all return maps of a point's sigma_zz iteration and
      // its tangent), per core.
      {"returned_points", stats[13]},
      {"returned_points_per_core_second",
       stats[14] > 0.0 ? stats[13] / stats[14] : 0.0},
      {"seconds",
       {{"residual", stats[6]},
        {"tangent_assembly", stats[7]},
        {"factorization", stats[8]},
        {"direction_solves", stats[9]},
        {"return_maps_core_seconds", stats[14]}}},
      {"step_cuts", stats[2]},
      {"max_inelastic_points", stats[4]}};
  if (concrete.implex)
  {
    // How far the implicit stresses of the IMPL-EX steps are from
    // equilibrium, in the units of the Newton tolerance (README).
    summary["implex_equilibrium_error"] = {
        {"rms", std::sqrt(stats[15] / steps_all)},
        {"max", stats[16]},
        {"t_of_max", stats[17]}};
  }
  summary["wall_seconds"] = seconds_since(wall_start);
  print_summary_line(comm, summary,
                     ", Newton iterations per step " +
                         std::to_string(stats[0] / steps_all));
  return summary;
}
} // namespace damseis::analysis
