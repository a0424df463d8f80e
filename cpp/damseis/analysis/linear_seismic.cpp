#include "linear_seismic.h"
#include "checkpoint.h"
#include "ground_motion_load.h"
#include "modal_stage.h"
#include "run_outputs.h"
#include "stop_signals.h"
#include <chrono>
#include <cmath>
#include <csignal>
#include <damseis/fem/tied_dofs.h>
#include <damseis/geometry/tags.h>
#include <damseis/linalg/modal.h>
#include <damseis/linalg/petsc_vectors.h>
#include <damseis/results/displacement_envelope.h>
#include <damseis/results/face_points.h>
#include <damseis/results/field_writer.h>
#include <damseis/results/point_probe.h>
#include <damseis/results/progress.h>
#include <damseis/results/stress_envelope.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/la/petsc.h>
#include <dolfinx/mesh/Mesh.h>
#include <dolfinx/mesh/MeshTags.h>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>

namespace damseis::analysis
{
namespace
{
using dolfinx::la::petsc::Matrix;
using dolfinx::la::petsc::Vector;
using nlohmann::json;
using Clock = std::chrono::steady_clock;
} // namespace

json run_linear_seismic(fem::ElasticModel& fe, const SeismicSettings& s,
                        const std::filesystem::path& out_dir,
                        const std::string& case_text, Mat tie,
                        const std::vector<Vec>& extra_static_loads)
{
  results::set_stage("assembly");
  const auto wall_start = Clock::now();
  const auto model = fe.model();
  MPI_Comm comm = model.mesh->comm();
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const int dim = fe.dim();
  print_model_line(fe, "");

  const bool wet = s.reservoir.depth() > 0.0;
  const fem::Reservoir* added = s.westergaard && wet ? &s.reservoir : nullptr;
  // The system: all dofs, or the tied unknowns u_r with u = P u_r.
  Matrix K(fe.assemble_stiffness(), false);
  Matrix M(fe.assemble_mass(added), false);
  if (tie)
  {
    K = Matrix(fem::reduce_to_tied(K.mat(), tie), false);
    M = Matrix(fem::reduce_to_tied(M.mat(), tie), false);
  }
  // Full-space vector of a system vector, and system load of a full one.
  Vector u_full = tie ? linalg::row_vector(tie) : Vector(nullptr, false);
  auto full = [&](Vec x) -> Vec
  {
    if (!tie)
      return x;
    MatMult(tie, x, u_full.vec());
    return u_full.vec();
  };
  auto system_load = [&](Vec f_full) -> Vector
  {
    if (!tie)
    {
      Vec y;
      VecDuplicate(f_full, &y);
      VecCopy(f_full, y);
      return Vector(y, false);
    }
    Vector y = linalg::column_vector(tie);
    MatMultTranspose(tie, f_full, y.vec());
    return y;
  };

  // Static stage: dead weight and hydrostatic pressure.
  results::set_stage("static stage and modal analysis");
  std::array<double, 3> g = {0, 0, 0};
  g[dim - 1] = -s.gravity;
  Vector F_full(fe.assemble_gravity(g), false);
  if (wet)
  {
    Vector H(fe.assemble_hydrostatic(s.reservoir), false);
    VecAXPY(F_full.vec(), 1.0, H.vec());
  }
  for (Vec extra : extra_static_loads)
    VecAXPY(F_full.vec(), 1.0, extra);
  Vector F = system_load(F_full.vec());
  Vector u_static = linalg::column_vector(K.mat());
  // K u = F is solved with the modal analysis' factors of K (one
  // factorisation for both).
  const double setup_seconds = seconds_since(wall_start);

  // Modal analysis, with and without the added mass; Rayleigh damping.
  Matrix M0(nullptr, false);
  if (added)
  {
    M0 = Matrix(fe.assemble_mass(nullptr), false);
    if (tie)
      M0 = Matrix(fem::reduce_to_tied(M0.mat(), tie), false);
  }
  const ModalResult modal = modal_and_damping(
      K.mat(), M.mat(), added ? M0.mat() : nullptr, s,
      [&](KSP ksp) { KSPSolve(ksp, F.vec(), u_static.vec()); });
  const double static_seconds = setup_seconds + modal.with_K_factors_seconds;
  const linalg::Modes& modes = modal.modes;

  // Dynamic stage: displacement relative to the base under the ground
  // acceleration, M a + C v + K u = -M sum_c r_c a_gc(t). The added mass
  // multiplies the total acceleration, so it is part of M here.
  dynamics::LinearNewmark newmark(M.mat(), K.mat(), modal.damping, s.scheme,
                                  s.factorization);
  const GroundMotionLoad ground(fe, s, M.mat(), tie);
  Vector f = linalg::column_vector(K.mat());
  auto set_load = [&](int k) { ground.assemble(k, nullptr, f.vec()); };

  // Outputs: every input check has passed by now.
  std::filesystem::create_directories(out_dir);
  if (rank == 0)
    std::ofstream(out_dir / "case_used.toml") << case_text;
  write_modes(fe, modes, full, out_dir / "modes.xdmf");

  // Stress points, envelopes (dam only) and faces.
  Matrix B(fe.assemble_stress_operator(), false);
  if (tie)
  {
    Mat BP;
    MatMatMult(B.mat(), tie, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &BP);
    B = Matrix(BP, false);
  }
  Vector s_static = linalg::row_vector(B.mat()),
         s_field = linalg::row_vector(B.mat());
  MatMult(B.mat(), u_static.vec(), s_static.vec());
  const auto dam_cells = region_cells(model, tags::dam);
  results::StressEnvelope envelope(*fe.S(), dam_cells);
  std::vector<std::vector<std::int32_t>> face_pts;
  for (const auto& [name, face_tags] : s.faces)
    face_pts.push_back(
        results::face_points(*fe.S(), *model.facet_tags, face_tags));

  results::PointProbe crest(*fe.V(), s.crest_point);
  results::PointProbe base(*fe.V(), s.base_point);
  // 2D: envelope of the horizontal displacement along the upstream face.
  std::optional<results::DisplacementEnvelope> face_u;
  if (dim == 2 && !tie)
    face_u.emplace(*fe.V(), *model.facet_tags, tags::upstream_face);
  const auto crest_static = crest.value_on_all(full(u_static.vec()));
  const auto base_static = base.value_on_all(full(u_static.vec()));
  const int n = s.steps;
  const double dt = s.scheme.dt;
  // Per step: crest then base displacement components (owner rank only).
  std::vector<double> hist(2 * dim * (n + 1), 0.0);

  // Start at rest: a = -sum_c r_c a_gc(0) satisfies M a = f(0) exactly, also
  // where M is singular (massless foundation, fixed dofs).
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
           a = linalg::column_vector(K.mat());
    const CheckpointData& d = *restart;
    restore_collectively(
        comm, ckpt_dir,
        [&]
        {
          linalg::set_owned_values(u.vec(), checkpoint_array(d, "u"));
          linalg::set_owned_values(v.vec(), checkpoint_array(d, "v"));
          linalg::set_owned_values(a.vec(), checkpoint_array(d, "a"));
          envelope.restore(
              checkpoint_array(d, "env_max"), checkpoint_array(d, "env_t_max"),
              checkpoint_array(d, "env_min"), checkpoint_array(d, "env_t_min"));
          hist = checkpoint_array(d, "history", hist.size());
          if (face_u)
            face_u->restore(checkpoint_array(d, "face_u"));
        });
    set_load(k0);
    newmark.set_state(u.vec(), v.vec(), a.vec(), f.vec());
    results::print(comm, "restarting from the checkpoint at step " +
                             std::to_string(k0));
  }
  else
  {
    Vector zero = linalg::column_vector(K.mat()),
           a0 = linalg::column_vector(K.mat());
    ground.initial_acceleration(a0.vec());
    set_load(0);
    newmark.set_state(zero.vec(), zero.vec(), a0.vec(), f.vec());
  }

  results::FieldWriter writer(
      fe,
      out_dir / (k0 == 0 ? std::string("fields.xdmf")
                         : "fields_from_step" + std::to_string(k0) + ".xdmf"));
  dolfinx::fem::Function<double> u_fn(fe.V());
  Vector u_out = tie ? linalg::row_vector(tie) : linalg::column_vector(K.mat());

  auto record_state = [&](int k, double t, Vec ud)
  {
    if (s.stress_total)
      MatMultAdd(B.mat(), ud, s_static.vec(), s_field.vec());
    else
      MatMult(B.mat(), ud, s_field.vec());
    const double* sa = nullptr;
    PetscInt ns = 0;
    VecGetLocalSize(s_field.vec(), &ns);
    VecGetArrayRead(s_field.vec(), &sa);
    envelope.update(std::span<const double>(sa, ns), t);
    Vec uf = full(ud);
    const auto c = crest.value(uf), b = base.value(uf);
    if (face_u)
      face_u->update(uf, base.value_on_all(uf)[0], nullptr);
    for (int i = 0; i < dim; ++i)
    {
      hist[2 * dim * k + i] = c[i];
      hist[2 * dim * k + dim + i] = b[i];
    }
    if (k % s.output_every == 0)
    {
      VecCopy(uf, u_out.vec());
      if (s.stress_total)
        VecAXPY(u_out.vec(), 1.0, full(u_static.vec()));
      linalg::to_function(u_out.vec(), u_fn);
      writer.write(u_fn, std::span<const double>(sa, ns), t);
    }
    VecRestoreArrayRead(s_field.vec(), &sa);
  };
  auto checkpoint = [&](int k)
  {
    CheckpointData data;
    data.step = k;
    data.arrays = {{"u", linalg::owned_values(newmark.u())},
                   {"v", linalg::owned_values(newmark.v())},
                   {"a", linalg::owned_values(newmark.a())},
                   {"history", hist}};
    auto span_vec = [](std::span<const double> x)
    { return std::vector<double>(x.begin(), x.end()); };
    data.arrays["env_max"] = span_vec(envelope.max_principal());
    data.arrays["env_t_max"] = span_vec(envelope.max_times());
    data.arrays["env_min"] = span_vec(envelope.min_principal());
    data.arrays["env_t_min"] = span_vec(envelope.min_times());
    if (face_u)
      data.arrays["face_u"] = face_u->save();
    write_checkpoint(comm, ckpt_dir, data, print);
  };

  results::set_stage("time history");
  results::print(comm, "time history: " + std::to_string(n) + " steps of " +
                           std::to_string(dt) + " s, factorisation " +
                           newmark.solver().name());
  if (k0 == 0)
    record_state(0, 0.0, newmark.u());
  StopSignals signals;
  results::Progress progress(comm, n - k0);
  const auto loop_start = Clock::now();
  for (int k = k0 + 1; k <= n; ++k)
  {
    set_load(k);
    newmark.step(f.vec());
    record_state(k, k * dt, newmark.u());
    progress.report(k - k0, k * dt);
    signals.checkpoint_or_stop(comm, s, k, n, checkpoint, ckpt_dir);
  }
  const double loop_seconds = seconds_since(loop_start);
  results::set_stage("writing outputs");
  results::reduce_history(comm, hist);

  // Crest history relative to the base point.
  const json crest_summary =
      write_crest_history(comm, hist, dim, n, dt, crest_static, base_static,
                          false, out_dir / "crest.csv");

  results::write_envelopes(fe, envelope, dam_cells, out_dir / "envelopes.xdmf");
  if (face_u)
    face_u->write_csv(comm, out_dir / "displacement_envelope.csv");
  const json faces = write_faces(comm, s, envelope, face_pts, dim, out_dir);
  json summary =
      seismic_summary(comm, fe, s, modal, added != nullptr, crest.node(),
                      envelope, faces, newmark.solver().name(),
                      {static_seconds, modal.seconds,
                       newmark.solver().factor_seconds(), loop_seconds, k0});
  summary.update(crest_summary);
  summary["wall_seconds"] = seconds_since(wall_start);
  print_summary_line(comm, summary);
  return summary;
}
} // namespace damseis::analysis

namespace damseis::analysis
{
void write_summary_and_plots(MPI_Comm comm, const nlohmann::json& summary,
                             const std::filesystem::path& out_dir, bool plots,
                             const std::string& plot_script)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank != 0)
    return;
  nlohmann::json s = summary;
  s["warnings"] = results::warnings();
  std::ofstream(out_dir / "summary.json") << s.dump(2) << "\n";
  if (plots)
  {
    const std::string cmd = std::string(DAMSEIS_PYTHON) + " " +
                            DAMSEIS_SOURCE_DIR + "/scripts/" + plot_script +
                            " \"" + out_dir.string() + "\"";
    if (std::system(cmd.c_str()) != 0)
      std::fprintf(stderr, "warning: plotting failed: %s\n", cmd.c_str());
  }
}
} // namespace damseis::analysis
