#include "linear_seismic.h"
#include "engine_settings.h"
#include "ground_motion_load.h"
#include "initial_motion.h"
#include "modal_stage.h"
#include "recorders.h"
#include "run_outputs.h"
#include "seismic_system.h"
#include "timed_loads.h"
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

/// The linear analysis: K and M (reduced to the tied unknowns with ties),
/// Newmark with the effective matrix factorised once, stresses B u at the
/// stress points.
class LinearSeismicAnalysis : public SeismicAnalysis
{
public:
  LinearSeismicAnalysis(fem::ElasticModel& fe, const SeismicSettings& s,
                        const ModelLoads& loads, RunFolder folder, Mat tie);
  void modal_stage() override;
  void static_stage() override;
  void time_history() override;
  json results() override;

private:
  void add_recorders(engine::TimeHistory& history);

  /// The initial state of a run with an initial velocity.
  engine::InitialState initial_state();

  fem::ElasticModel& _fe;
  const SeismicSettings& _s;
  const ModelLoads _loads;
  RunFolder _folder;
  Mat _tie;
  MPI_Comm _comm;
  const Clock::time_point _wall_start = Clock::now();
  const fem::Reservoir* _added = nullptr; ///< Westergaard added mass
  Matrix _K{nullptr, false}, _M{nullptr, false}, _B{nullptr, false};
  /// Static load and solution, static stresses (system layout).
  Vector _F{nullptr, false}, _u_static{nullptr, false},
      _s_static{nullptr, false};
  std::optional<ModalResult> _modal;
  double _static_seconds = 0.0;

  // The time history's parts and its report.
  std::unique_ptr<engine::LinearStepper> _stepper;
  std::unique_ptr<FullDisplacement> _u;
  std::unique_ptr<StressRecorder> _stresses;
  std::unique_ptr<PointHistories> _points;
  std::unique_ptr<FaceDisplacementRecorder> _face_u;
  std::unique_ptr<FieldRecorder> _fields;
  std::unique_ptr<NamedHistories> _named;
  Vector _v0{nullptr, false}, _a0{nullptr, false};
  Vector _s_field{nullptr, false}, _u_static_full{nullptr, false},
      _u_out{nullptr, false};
  std::vector<double> _s_values;
  std::vector<std::vector<std::int32_t>> _face_points;
  engine::TimeHistoryReport _run;
};

LinearSeismicAnalysis::LinearSeismicAnalysis(fem::ElasticModel& fe,
                                             const SeismicSettings& s,
                                             const ModelLoads& loads,
                                             RunFolder folder, Mat tie)
    : _fe(fe), _s(s), _loads(loads), _folder(std::move(folder)), _tie(tie),
      _comm(fe.mesh()->comm())
{
  results::set_stage("assembly");
  print_model_line(fe, "");
  // The system (all dofs, or the tied unknowns u_r with u = P u_r) and the
  // static load: dead weight, hydrostatic pressure, the extra loads.
  SeismicSystem sys =
      assemble_seismic_system(fe, s, loads.static_loads, tie, false);
  _added = sys.added;
  _K = std::move(sys.K);
  _M = std::move(sys.M);
  _F = std::move(sys.F_static);
  _u_static = linalg::column_vector(_K.mat());
  _static_seconds = seconds_since(_wall_start);
}

void LinearSeismicAnalysis::modal_stage()
{
  results::set_stage("static stage and modal analysis");
  Matrix M0 = dry_mass(_fe, _added, _tie);
  // K u = F is solved with the modal analysis' factors of K.
  _modal = modal_and_damping(
      _K.mat(), _M.mat(), _added ? M0.mat() : nullptr, _s,
      [&](KSP ksp) { KSPSolve(ksp, _F.vec(), _u_static.vec()); });
  _static_seconds += _modal->with_K_factors_seconds;
}

void LinearSeismicAnalysis::static_stage()
{
  if (!_modal)
    throw std::logic_error("the linear static stage uses the modal stage's "
                           "factors: call modal_stage() first");
  // The static stresses at the stress points.
  _B = Matrix(_fe.assemble_stress_operator(), false);
  if (_tie)
  {
    Mat BP;
    MatMatMult(_B.mat(), _tie, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &BP);
    _B = Matrix(BP, false);
  }
  _s_static = linalg::row_vector(_B.mat());
  MatMult(_B.mat(), _u_static.vec(), _s_static.vec());
}

void LinearSeismicAnalysis::time_history()
{
  // Displacement relative to the base under the ground acceleration,
  // M a + C v + K u = -M sum_c r_c a_gc(t). The added mass multiplies the
  // total acceleration, so it is part of M here.
  _stepper = std::make_unique<engine::LinearStepper>(
      _M.mat(), _K.mat(), _modal->damping, _s.scheme, _s.factorization);
  const GroundMotionLoad ground(_fe, _s, _M.mat(), _tie);
  // Tractions with their histories on top of the ground motion's load.
  const LoadWithTimedTerms load(ground, _loads.timed, _tie);

  // Outputs: every input check has passed by now.
  open_run_folder(_comm, _folder);
  _u = std::make_unique<FullDisplacement>(*_stepper, _tie);
  write_modes(
      _fe, _modal->modes, [&](Vec x) { return _u->full(x); },
      _folder.dir / "modes.xdmf");

  engine::TimeHistory history(
      _comm, time_history_settings(_s, _fe, _folder.dir, _folder.case_text),
      *_stepper, load);
  add_recorders(history);
  // (A restart takes its state from the checkpoint.)
  _run = history.run(_s.restart ? engine::InitialState{} : initial_state());
}

engine::InitialState LinearSeismicAnalysis::initial_state()
{
  if (!_loads.initial_velocity)
    return {};
  const GroundMotionLoad ground(_fe, _s, _M.mat(), _tie);
  InitialMotion m =
      initial_motion(_comm, _M.mat(), _K.mat(), _modal->damping, ground,
                     _loads.initial_velocity, _tie, _s.factorization);
  _v0 = std::move(m.v0);
  _a0 = std::move(m.a0);
  return {nullptr, _v0.vec(), _a0.vec()};
}

void LinearSeismicAnalysis::add_recorders(engine::TimeHistory& history)
{
  // Stresses at the stress points (B u, with the static stress if asked),
  // their envelopes (dam only) and faces.
  _s_field = linalg::row_vector(_B.mat());
  _stresses = std::make_unique<StressRecorder>(
      results::StressEnvelope(*_fe.S(),
                              region_cells(_fe.model(), _s.dam_regions)),
      [this]() -> std::span<const double>
      {
        if (_s.stress_total)
          MatMultAdd(_B.mat(), _stepper->u(), _s_static.vec(), _s_field.vec());
        else
          MatMult(_B.mat(), _stepper->u(), _s_field.vec());
        linalg::read_owned_values(_s_field.vec(), _s_values);
        return _s_values;
      });
  const auto model = _fe.model();
  for (const auto& [name, face_tags] : _s.faces)
    _face_points.push_back(results::face_points(
        *_fe.S(), _s.face_tags ? *_s.face_tags : *model.facet_tags, face_tags));
  // Crest and base histories; in 2D the upstream face's displacement
  // envelope; the fields.
  _points = std::make_unique<PointHistories>(*_fe.V(), _s.crest_point,
                                             _s.base_point, _s.steps, *_u);
  if (_fe.dim() == 2 && !_tie)
    _face_u = std::make_unique<FaceDisplacementRecorder>(
        *_fe.V(), *model.facet_tags, tags::upstream_face, _points->base(), *_u);
  _u_static_full = linalg::row_vector(_tie ? _tie : _K.mat());
  VecCopy(_u->full(_u_static.vec()), _u_static_full.vec());
  _u_out = linalg::row_vector(_tie ? _tie : _K.mat());
  _fields = std::make_unique<FieldRecorder>(
      _fe, _folder.dir, _s.output_every,
      [this]
      {
        VecCopy(_u->vec(), _u_out.vec());
        if (_s.stress_total)
          VecAXPY(_u_out.vec(), 1.0, _u_static_full.vec());
        return _u_out.vec();
      },
      *_stresses);

  // Displacement, velocity, acceleration and stress at the named points,
  // means over the named groups.
  _named = std::make_unique<NamedHistories>(_comm, *_fe.V(), _s, *_stepper, *_u,
                                            *_stresses, nullptr);
  for (engine::Observer* o : std::initializer_list<engine::Observer*>{
           _u.get(), _stresses.get(), _points.get()})
    history.observe(*o);
  _named->observe(history);
  if (_face_u)
    history.observe(*_face_u);
  history.observe(*_fields);
}

json LinearSeismicAnalysis::results()
{
  results::set_stage("writing outputs");
  const int dim = _fe.dim();
  const std::filesystem::path& dir = _folder.dir;
  const std::vector<double>& hist = _points->reduce(_comm);
  // Crest history relative to the base point.
  const auto crest_static = _points->crest().value_on_all(_u_static_full.vec());
  const auto base_static = _points->base().value_on_all(_u_static_full.vec());
  const json crest_summary =
      write_crest_history(_comm, hist, dim, _s.steps, _s.scheme.dt,
                          crest_static, base_static, false, dir / "crest.csv");

  const auto& envelope = _stresses->envelope();
  results::write_envelopes(_fe, envelope,
                           region_cells(_fe.model(), _s.dam_regions),
                           dir / "envelopes.xdmf");
  if (_face_u)
    _face_u->write_csv(_comm, dir / "displacement_envelope.csv");
  const json faces = write_faces(_comm, _s, envelope, _face_points, dim, dir);
  json summary = seismic_summary(
      _comm, _fe, _s, *_modal, _added != nullptr, _points->crest().node(),
      envelope, faces, _stepper->solver_name(),
      {_static_seconds, _modal->seconds, _stepper->factor_seconds(),
       _run.loop_seconds, _run.restarted_from_step});
  summary.update(crest_summary);
  _named->write(_comm, dir, summary);
  summary["wall_seconds"] = seconds_since(_wall_start);
  print_summary_line(_comm, summary);
  return summary;
}
} // namespace

std::unique_ptr<SeismicAnalysis>
linear_seismic_analysis(fem::ElasticModel& fe, const SeismicSettings& s,
                        const ModelLoads& loads, const RunFolder& folder,
                        Mat tie)
{
  return std::make_unique<LinearSeismicAnalysis>(fe, s, loads, folder, tie);
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
