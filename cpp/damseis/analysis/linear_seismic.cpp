#include "linear_seismic.h"
#include "engine_settings.h"
#include "ground_motion_load.h"
#include "modal_stage.h"
#include "recorders.h"
#include "run_outputs.h"
#include <chrono>
#include <cmath>
#include <damseis/engine/linear_stepper.h>
#include <damseis/engine/time_history.h>
#include <damseis/fem/tied_dofs.h>
#include <damseis/geometry/tags.h>
#include <damseis/linalg/modal.h>
#include <damseis/linalg/petsc_vectors.h>
#include <damseis/results/face_points.h>
#include <damseis/results/progress.h>
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
                        const std::vector<Vec>& extra_static_loads,
                        const RunFolder& folder, Mat tie)
{
  const std::filesystem::path& out_dir = folder.dir;
  const std::string& case_text = folder.case_text;
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
  // The system load of a full-space load.
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
  engine::LinearStepper stepper(M.mat(), K.mat(), modal.damping, s.scheme,
                                s.factorization);
  const GroundMotionLoad ground(fe, s, M.mat(), tie);

  // Outputs: every input check has passed by now.
  std::filesystem::create_directories(out_dir);
  if (rank == 0)
    std::ofstream(out_dir / "case_used.toml") << case_text;
  FullDisplacement u(stepper, tie);
  write_modes(
      fe, modes, [&](Vec x) { return u.full(x); }, out_dir / "modes.xdmf");

  // Recorders: stresses at the stress points (B u, with the static stress
  // if asked) with their envelopes (dam only) and faces, the crest and base
  // histories, in 2D the upstream face's displacement envelope, the fields.
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
  std::vector<double> s_values;
  const auto dam_cells = region_cells(model, tags::dam);
  StressRecorder stresses(results::StressEnvelope(*fe.S(), dam_cells),
                          [&]() -> std::span<const double>
                          {
                            if (s.stress_total)
                              MatMultAdd(B.mat(), stepper.u(), s_static.vec(),
                                         s_field.vec());
                            else
                              MatMult(B.mat(), stepper.u(), s_field.vec());
                            linalg::read_owned_values(s_field.vec(), s_values);
                            return s_values;
                          });
  std::vector<std::vector<std::int32_t>> face_pts;
  for (const auto& [name, face_tags] : s.faces)
    face_pts.push_back(
        results::face_points(*fe.S(), *model.facet_tags, face_tags));
  PointHistories points(*fe.V(), s.crest_point, s.base_point, s.steps, u);
  const auto crest_static = points.crest().value_on_all(u.full(u_static.vec()));
  const auto base_static = points.base().value_on_all(u.full(u_static.vec()));
  std::optional<FaceDisplacementRecorder> face_u;
  if (dim == 2 && !tie)
    face_u.emplace(*fe.V(), *model.facet_tags, tags::upstream_face,
                   points.base(), u);
  Vector u_static_full = linalg::row_vector(tie ? tie : K.mat());
  VecCopy(u.full(u_static.vec()), u_static_full.vec());
  Vector u_out = linalg::row_vector(tie ? tie : K.mat());
  FieldRecorder fields(
      fe, out_dir, s.output_every,
      [&]
      {
        VecCopy(u.vec(), u_out.vec());
        if (s.stress_total)
          VecAXPY(u_out.vec(), 1.0, u_static_full.vec());
        return u_out.vec();
      },
      stresses);

  // The time history.
  engine::TimeHistory history(
      comm, time_history_settings(s, fe, out_dir, case_text), stepper, ground);
  for (engine::Observer* o :
       std::initializer_list<engine::Observer*>{&u, &stresses, &points})
    history.observe(*o);
  if (face_u)
    history.observe(*face_u);
  history.observe(fields);
  const engine::TimeHistoryReport run = history.run();
  const auto& envelope = stresses.envelope();
  const int n = s.steps;
  const double dt = s.scheme.dt;
  results::set_stage("writing outputs");
  const std::vector<double>& hist = points.reduce(comm);

  // Crest history relative to the base point.
  const json crest_summary =
      write_crest_history(comm, hist, dim, n, dt, crest_static, base_static,
                          false, out_dir / "crest.csv");

  results::write_envelopes(fe, envelope, dam_cells, out_dir / "envelopes.xdmf");
  if (face_u)
    face_u->write_csv(comm, out_dir / "displacement_envelope.csv");
  const json faces = write_faces(comm, s, envelope, face_pts, dim, out_dir);
  json summary = seismic_summary(
      comm, fe, s, modal, added != nullptr, points.crest().node(), envelope,
      faces, stepper.solver_name(),
      {static_seconds, modal.seconds, stepper.factor_seconds(),
       run.loop_seconds, run.restarted_from_step});
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
