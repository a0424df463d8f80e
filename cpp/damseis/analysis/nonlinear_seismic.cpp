#include "nonlinear_seismic.h"
#include "concrete_outputs.h"
#include "concrete_stepper.h"
#include "concrete_system.h"
#include "contact_joints.h"
#include "engine_settings.h"
#include "free_field_load.h"
#include "ground_motion_load.h"
#include "initial_motion.h"
#include "modal_stage.h"
#include "recorders.h"
#include "run_outputs.h"
#include "seismic_system.h"
#include "static_stage.h"
#include "tied_concrete_system.h"
#include "timed_loads.h"
#include "transmitting_foundation.h"
#include "viscous_spring_foundation.h"
#include <chrono>
#include <cmath>
#include <damseis/engine/time_history.h>
#include <damseis/fem/concrete_model.h>
#include <damseis/fem/tied_dofs.h>
#include <damseis/geometry/tags.h>
#include <damseis/linalg/petsc_vectors.h>
#include <damseis/results/displacement_envelope.h>
#include <damseis/results/face_points.h>
#include <damseis/results/field_writer.h>
#include <damseis/results/gather.h>
#include <damseis/results/point_probe.h>
#include <damseis/results/principal.h>
#include <damseis/results/progress.h>
#include <damseis/results/singular_points.h>
#include <damseis/results/stress_envelope.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/la/petsc.h>
#include <dolfinx/mesh/Mesh.h>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>

namespace damseis::analysis
{
namespace
{
using dolfinx::la::petsc::Matrix;
using dolfinx::la::petsc::Vector;
using nlohmann::json;
using Clock = std::chrono::steady_clock;

/// The concrete of every region of the bulk.
std::map<int, material::ConcreteParameters>
concrete_regions(const ConcreteBulk& bulk)
{
  std::map<int, material::ConcreteParameters> m;
  for (int r : bulk.regions)
    m[r] = bulk.concrete.params;
  return m;
}

/// The analysis with HTC concrete in the dam: the state is total (static
/// included), Newton per step on the concrete system, stresses at the
/// quadrature points.
class ConcreteSeismicAnalysis : public SeismicAnalysis
{
public:
  ConcreteSeismicAnalysis(fem::ElasticModel& fe, const SeismicSettings& s,
                          ConcreteBulk bulk, const ModelLoads& loads,
                          RunFolder folder, Mat tie, const WaveFoundation* wave,
                          const ContactJoints* contact);
  void modal_stage() override;
  void static_stage() override;
  void time_history() override;
  json results() override;

private:
  void add_recorders(engine::TimeHistory& history);
  void write_concrete_outputs(json& summary) const;
  void write_concrete_faces(const results::StressEnvelope& envelope,
                            const ConcreteRecorder& state,
                            const std::vector<double>& kappa_t) const;
  /// The viscous-spring boundary's springs (K0 and the system's supports),
  /// dashpots and the record's free field.
  void set_up_viscous_spring();
  /// Liao's multi-transmitting boundary: the partition's operators, the
  /// formula and the record's free field (the boundary's nodes fixed in
  /// the modal and static stages).
  void set_up_transmitting();
  /// Contact joints: the bonded system of the modal stage, the pairs, and
  /// with P2 the midside constraints (sys reduced by them, as by a tie).
  void set_up_contact(SeismicSystem& sys, Mat joint_tie);
  /// The static stage's contact settings (and its contact constraint).
  void set_up_static_contact(StaticStageSettings& stage);
  /// joint_static.csv's state and the summary entries of the static stage.
  void keep_static_contact();
  /// The seismic load: the free field's (wave foundation) or the base
  /// acceleration's, the static loads held.
  std::unique_ptr<engine::DynamicLoad> seismic_load() const;

  fem::ElasticModel& _fe;
  const SeismicSettings& _s;
  const ConcreteBulk _bulk;
  const ModelLoads _loads;
  RunFolder _folder;
  MPI_Comm _comm;
  const Clock::time_point _wall_start = Clock::now();
  const fem::Reservoir* _added = nullptr; ///< Westergaard added mass
  /// An elastic material has no plastic strain to extrapolate: no IMPL-EX
  /// steps, no extrapolated predictor.
  bool _plastic = false;
  Matrix _K{nullptr, false}, _M{nullptr, false};
  fem::ConcreteModel _cm;
  /// Bonded joints (or P2 contact's midside constraints): u = P u_r
  /// (null: none).
  Mat _tie;
  /// A foundation with mass on a viscous-spring boundary (null: none).
  const WaveFoundation* _wave;
  /// Contact joints (null: none): the modal stage's bonded system (u =
  /// P_modal u_b), the pairs (P2: the midside constraints in _tie), the
  /// contact state through the stages and its constraint.
  const ContactJoints* _contact;
  Mat _modal_tie = nullptr;
  Matrix _K_bonded{nullptr, false}, _M_bonded{nullptr, false};
  Matrix _mpc{nullptr, false};
  std::optional<joint::PairSet> _pairs;
  std::shared_ptr<joint::CondensedContact> _pair_contact;
  std::unique_ptr<joint::NonlinearContact> _static_constraint;
  std::shared_ptr<joint::NonlinearContact> _dynamic_contact;
  joint::StaticContactResult _static_contact;
  JointObservers _joints;
  IncidentWaves _waves;
  ViscousSpringParts _vs;
  std::unique_ptr<TransmittingFoundation> _mtf;
  double _free_field_seconds = 0.0;
  /// The concrete system (on the tied unknowns with ties).
  std::unique_ptr<ConcreteSystem> _system;
  /// Dead weight alone, and all static loads.
  Vector _F_g{nullptr, false}, _F_static{nullptr, false};
  /// The static solution and its internal force and stresses.
  Vector _u_static{nullptr, false}, _f_int_static{nullptr, false};
  /// The static displacement of all dofs (= _u_static without ties).
  Vector _u_static_full{nullptr, false};
  std::vector<double> _sig_static;
  std::optional<ModalResult> _modal;
  StaticStageReport _static_report;
  double _static_seconds = 0.0;

  // The time history's parts and its report.
  dynamics::NewtonSettings _newton;
  std::unique_ptr<ConcreteStepper> _stepper;
  std::unique_ptr<FullDisplacement> _u;
  std::unique_ptr<StressRecorder> _stresses;
  std::unique_ptr<ConcreteRecorder> _concrete_state;
  std::unique_ptr<PointHistories> _points;
  std::unique_ptr<FaceDisplacementRecorder> _face_u;
  std::unique_ptr<FieldRecorder> _fields;
  std::unique_ptr<NamedHistories> _named;
  InitialMotion _initial;
  std::vector<double> _s_field;
  std::vector<std::int8_t> _in_dam;
  std::vector<std::vector<std::int32_t>> _face_points;
  std::vector<std::vector<std::int64_t>> _face_point_cells;
  std::array<double, 3> _base_static = {0, 0, 0};
  engine::TimeHistoryReport _run;
};

ConcreteSeismicAnalysis::ConcreteSeismicAnalysis(
    fem::ElasticModel& fe, const SeismicSettings& s, ConcreteBulk bulk,
    const ModelLoads& loads, RunFolder folder, Mat tie,
    const WaveFoundation* wave, const ContactJoints* contact)
    : _fe(fe), _s(s), _bulk(std::move(bulk)), _loads(loads),
      _folder(std::move(folder)), _comm(fe.mesh()->comm()),
      _cm(fe, concrete_regions(_bulk), _bulk.elastic, _bulk.plane),
      _tie(contact ? nullptr : tie), _wave(wave), _contact(contact),
      _modal_tie(contact ? tie : nullptr)
{
  results::set_stage("assembly");
  const ConcreteSettings& concrete = _bulk.concrete;
  print_model_line(fe, ", concrete " + to_string(concrete.kind));
  // The system (on the tied unknowns with ties) and the static loads: the dead
  // weight, then the reservoir (and silt, uplift).
  SeismicSystem sys = assemble_seismic_system(fe, s, loads.static_loads, _tie);
  if (_contact)
    set_up_contact(sys, tie);
  _added = sys.added;
  _K = std::move(sys.K);
  _M = std::move(sys.M);
  _F_g = std::move(sys.F_g);
  _F_static = std::move(sys.F_static);
  if (_tie)
    _system = std::make_unique<TiedConcreteSystem>(_cm, _tie);
  else
    _system = std::make_unique<ConcreteSystem>(_cm);
  if (_wave && _wave->mtf)
    set_up_transmitting();
  else if (_wave)
    set_up_viscous_spring();
  _plastic = concrete.kind != ConcreteModelKind::elastic;
  _cm.set_implex(concrete.implex && _plastic);
  if (_plastic)
    print_crack_band_notes(_comm, fe, _cm, concrete, _bulk.regions);
}

void ConcreteSeismicAnalysis::set_up_transmitting()
{
  if (_loads.initial_velocity)
    throw std::invalid_argument("an initial velocity is not available with "
                                "a multi-transmitting boundary");
  _waves = incident_waves(_fe, _s, *_wave, false);
  _mtf = std::make_unique<TransmittingFoundation>(
      _fe, *_wave, _added, _waves.field, *_waves.ground, _s.scheme.dt, _tie);
}

void ConcreteSeismicAnalysis::set_up_viscous_spring()
{
  _waves = incident_waves(_fe, _s, *_wave, _loads.initial_velocity != nullptr);
  _vs = viscous_spring_parts(_fe, _s, *_wave, *_waves.field, _tie);
  // The springs: in K0 (system unknowns) and, as linear supports, in the
  // internal force of the dofs the material sees (all of them with ties).
  MatAXPY(_K.mat(), 1.0, _vs.springs.mat(), SUBSET_NONZERO_PATTERN);
  _system->set_supports(_tie ? _vs.boundary->springs() : _vs.springs.mat());
  if (_K_bonded.mat()) // contact joints: the modal stage's bonded system too
  {
    Matrix springs(fem::reduce_to_tied(_vs.boundary->springs(), _modal_tie),
                   false);
    MatAXPY(_K_bonded.mat(), 1.0, springs.mat(), DIFFERENT_NONZERO_PATTERN);
  }
}

void ConcreteSeismicAnalysis::set_up_contact(SeismicSystem& sys, Mat joint_tie)
{
  if (!joint_tie)
    throw std::invalid_argument("contact joints need the tie of the same "
                                "joints for the modal stage");
  // The modes of the joints bonded (the natural frequencies and the
  // Rayleigh damping of the closed dam).
  _K_bonded = Matrix(fem::reduce_to_tied(sys.K.mat(), joint_tie), false);
  _M_bonded = Matrix(fem::reduce_to_tied(sys.M.mat(), joint_tie), false);
  JointPairs jp = set_up_joint_pairs(_fe, _s, *_contact, sys);
  _pairs = std::move(jp.pairs);
  _mpc = std::move(jp.mpc);
  _tie = _mpc.mat();
}

void ConcreteSeismicAnalysis::modal_stage()
{
  // The initial elastic system; Rayleigh damping with K0.
  results::set_stage("modal analysis");
  if (_contact)
  {
    // On the joints closed (bonded).
    Matrix M0 = dry_mass(_fe, _added, _modal_tie);
    _modal = modal_and_damping(_K_bonded.mat(), _M_bonded.mat(),
                               _added ? M0.mat() : nullptr, _s);
    _K_bonded = Matrix(nullptr, false);
    _M_bonded = Matrix(nullptr, false);
    return;
  }
  Matrix M0 = dry_mass(_fe, _added, _tie);
  _modal =
      modal_and_damping(_K.mat(), _M.mat(), _added ? M0.mat() : nullptr, _s);
}

void ConcreteSeismicAnalysis::static_stage()
{
  if (!_modal)
    throw std::logic_error("the static stage relaxes with the damping of the "
                           "modal stage: call modal_stage() first");
  // Dead weight, then the other loads in increments, with the
  // rate-independent material.
  results::set_stage("static stage");
  const ConcreteSettings& concrete = _bulk.concrete;
  _u_static = linalg::column_vector(_K.mat());
  StaticStageSettings stage;
  stage.increments = concrete.static_increments;
  stage.newton = concrete.newton;
  stage.factorization = _s.factorization;
  stage.f1_hz = _modal->f1;
  stage.f2_hz = _modal->f2;
  if (_contact)
    set_up_static_contact(stage);
  _static_report = solve_static_stage(*_system, _K.mat(), _M.mat(), _F_g.vec(),
                                      _F_static.vec(), _u_static.vec(), stage);
  if (_contact)
    keep_static_contact();
  _sig_static.assign(_cm.stress().begin(), _cm.stress().end());
  _f_int_static = linalg::column_vector(_K.mat());
  _system->internal_force(_f_int_static.vec());
  _u_static_full = linalg::row_vector(_tie ? _tie : _K.mat());
  if (_tie)
    MatMult(_tie, _u_static.vec(), _u_static_full.vec());
  else
    VecCopy(_u_static.vec(), _u_static_full.vec());
  _static_seconds = seconds_since(_wall_start) - _modal->seconds;
  results::print(_comm,
                 "static stage: " + std::to_string(_static_report.iterations) +
                     " Newton iterations, " +
                     std::to_string(_system->accepted.inelastic) +
                     " inelastic points");
}

void ConcreteSeismicAnalysis::set_up_static_contact(StaticStageSettings& stage)
{
  // The pairs' problem polished by at least one Newton step (see
  // joint::static_contact: under the small shift a start within the
  // tolerance may still be off).
  contact::NcpSettings ncp = _contact->ncp;
  ncp.min_iterations = std::max(ncp.min_iterations, 1);
  _pair_contact = std::make_shared<joint::CondensedContact>(*_pairs, ncp);
  _static_constraint =
      std::make_unique<joint::NonlinearContact>(_pair_contact, nullptr, -1.0);
  const double omega_1 =
      2.0 * std::numbers::pi * _modal->modes.frequencies_hz.front();
  stage.contact = _static_constraint.get();
  stage.contact_shift = joint::static_shift_factor * omega_1 * omega_1;
  stage.cantilever_dead_load = _contact->statics.cantilever_dead_load;
  stage.increments = std::max(stage.increments, _contact->statics.increments);
  _static_contact.shift = stage.contact_shift;
}

void ConcreteSeismicAnalysis::keep_static_contact()
{
  const double shift = _static_contact.shift;
  _static_contact = joint::contact_state(*_pair_contact);
  _static_contact.shift = shift;
  _static_contact.iterations = _static_report.iterations;
  _static_constraint.reset();
  _pair_contact->set_ncp(_contact->ncp);
  _pair_contact->totals() = {}; // count the time history only
}

void ConcreteSeismicAnalysis::time_history()
{
  // M a + C v + f_int(u) = F_static - M sum_c r_c a_gc(t), u relative to
  // the base, total (static included). (IMPL-EX steps are extrapolated
  // anyway.)
  const ConcreteSettings& concrete = _bulk.concrete;
  _newton = concrete.newton;
  _newton.extrapolated_predictor =
      concrete.newton.extrapolated_predictor && !concrete.implex && _plastic;
  if (_mtf)
    _mtf->check_time_step(_modal->damping, _s.scheme);
  _stepper = std::make_unique<ConcreteStepper>(
      _mtf ? _mtf->mass() : _M.mat(), _K.mat(), _modal->damping, _s.scheme,
      *_system, _cm, _newton, _s.factorization, _u_static.vec(),
      _f_int_static.vec(), _wave && !_mtf ? _vs.dashpots.mat() : nullptr);
  if (_mtf)
    _stepper->set_partition(_mtf->partition(_u_static.vec()));
  if (_contact)
  {
    _dynamic_contact = std::make_shared<joint::NonlinearContact>(
        _pair_contact, _M.mat(), _contact->restitution);
    _stepper->set_contact(_dynamic_contact);
  }
  const std::unique_ptr<engine::DynamicLoad> ground = seismic_load();
  // Tractions with their histories on top of the ground motion's load.
  const LoadWithTimedTerms load(*ground, _loads.timed, _tie);

  open_run_folder(_comm, _folder);
  _u = std::make_unique<FullDisplacement>(*_stepper, _tie);
  Vector mode = linalg::row_vector(_modal_tie ? _modal_tie : _K.mat());
  write_modes(
      _fe, _modal->modes,
      [&](Vec x)
      {
        if (!_modal_tie)
          return _u->full(x);
        MatMult(_modal_tie, x, mode.vec()); // the bonded modes
        return mode.vec();
      },
      _folder.dir / "modes.xdmf");

  engine::TimeHistory history(
      _comm, time_history_settings(_s, _fe, _folder.dir, _folder.case_text),
      *_stepper, load);
  add_recorders(history);
  // An initial velocity (fresh runs; a restart takes the checkpoint's
  // state): the state starts from the static displacement.
  engine::InitialState initial;
  if (_loads.initial_velocity && !_s.restart)
  {
    _initial = initial_motion(_comm, _M.mat(), _K.mat(), _modal->damping, load,
                              _loads.initial_velocity, _tie, _s.factorization);
    initial = {nullptr, _initial.v0.vec(), _initial.a0.vec()};
  }
  _run = history.run(initial);
  if (auto* f = dynamic_cast<const FreeFieldLoad*>(ground.get()))
    _free_field_seconds = f->seconds();
}

std::unique_ptr<engine::DynamicLoad>
ConcreteSeismicAnalysis::seismic_load() const
{
  if (_mtf)
    return _mtf->load(_modal->damping, _s.scheme.dt, _F_static.vec());
  if (_wave)
    return std::make_unique<FreeFieldLoad>(
        _fe, _vs.boundary.get(), *_waves.ground, _waves.field, _M.mat(),
        _K.mat(), _modal->damping, _s.scheme.dt, _tie, _F_static.vec());
  return std::make_unique<GroundMotionLoad>(_fe, _s, _M.mat(), _tie,
                                            _F_static.vec());
}

void ConcreteSeismicAnalysis::add_recorders(engine::TimeHistory& history)
{
  // Points: the quadrature points of the owned cells.
  const auto model = _fe.model();
  auto Sq = _cm.stress_space();
  const std::int32_t n_pts = Sq->dofmap()->index_map->size_local();
  _in_dam.assign(n_pts, 0);
  for (std::int32_t c : region_cells(model, _bulk.regions))
  {
    for (std::int32_t d : Sq->dofmap()->cell_dofs(c))
    {
      if (d < n_pts)
        _in_dam[d] = 1;
    }
  }
  // The stresses (seismic: less the static ones, unless total asked).
  _s_field.resize(_cm.stress().size());
  _stresses = std::make_unique<StressRecorder>(
      results::StressEnvelope(_cm.components(), _cm.coordinates(), _in_dam),
      [this]() -> std::span<const double>
      {
        auto sig = _cm.stress();
        for (std::size_t i = 0; i < _s_field.size(); ++i)
          _s_field[i] = _s.stress_total ? sig[i] : sig[i] - _sig_static[i];
        return _s_field;
      });
  _concrete_state =
      std::make_unique<ConcreteRecorder>(_cm, *_stresses, n_pts, _fe.dim());
  // The faces' points: those of the cells on them (quadrature points), and
  // the cell of each (the face maps draw a cell's points as one value).
  for (const auto& [name, face_tags] : _s.faces)
  {
    const auto& ft = _s.face_tags ? *_s.face_tags : *model.facet_tags;
    _face_points.push_back(results::face_points(*Sq, ft, face_tags, false));
    _face_point_cells.push_back(
        results::face_point_cells(*Sq, ft, face_tags, _face_points.back()));
  }
  _points = std::make_unique<PointHistories>(*_fe.V(), _s.crest_point,
                                             _s.base_point, _s.steps, *_u);
  // Envelope of the seismic horizontal displacement along the upstream
  // face.
  _base_static = _points->base().value_on_all(_u_static_full.vec());
  _face_u = std::make_unique<FaceDisplacementRecorder>(
      *_fe.V(), *model.facet_tags, tags::upstream_face, _points->base(), *_u,
      _u_static_full.vec(), _base_static[0]);
  _fields = std::make_unique<FieldRecorder>(
      _fe, _folder.dir, _s.output_every, [this] { return _u->vec(); },
      *_stresses,
      FieldRecorder::Extras{
          Sq,
          {"kappa_t", "kappa_c", "strain_rate_per_s"},
          [this]() -> std::vector<std::span<const double>> {
            return {_cm.kappa_t(), _cm.kappa_c(), _cm.strain_rate()};
          }});
  _named = std::make_unique<NamedHistories>(_comm, _fe, _s, *_stepper, *_u,
                                            *_stresses, _u_static_full.vec());
  for (engine::Observer* o : std::initializer_list<engine::Observer*>{
           _u.get(), _stresses.get(), _concrete_state.get(), _points.get(),
           _face_u.get(), _fields.get()})
    history.observe(*o);
  _named->observe(history);
  if (_contact)
    _joints.observe(history, _fe, *_contact, *_dynamic_contact,
                    _static_contact.w, _folder.dir, _s.output_every);
}

json ConcreteSeismicAnalysis::results()
{
  results::set_stage("writing outputs");
  const int dim = _fe.dim();
  const std::filesystem::path& dir = _folder.dir;
  const std::vector<double>& hist = _points->reduce(_comm);
  const auto crest_static = _points->crest().value_on_all(_u_static_full.vec());
  const json crest_summary =
      write_crest_history(_comm, hist, dim, _s.steps, _s.scheme.dt,
                          crest_static, _base_static, true, dir / "crest.csv");
  const auto& envelope = _stresses->envelope();
  const json faces = write_faces(_comm, _s, envelope, _face_points, dim, dir,
                                 {}, _face_point_cells);
  _face_u->write_csv(_comm, dir / "displacement_envelope.csv");

  json summary = seismic_summary(
      _comm, _fe, _s, *_modal, _added != nullptr, _points->crest().node(),
      envelope, faces, _stepper->solver_name(),
      {_static_seconds, _modal->seconds, _stepper->factor_seconds(),
       _run.loop_seconds, _run.restarted_from_step});
  summary.update(crest_summary);
  _named->write(_comm, dir, summary);
  write_concrete_outputs(summary);
  // The Newton statistics cover every step (restored at a restart).
  const int steps_all = std::max(1, _s.steps);
  const NewtonTotals& nt = _stepper->totals();
  summary["static_stage"] = _static_report.to_json();
  if (_contact)
  {
    summary["joints"] = _joints.write(
        _comm, dir, joint_pair_faces(_fe, _s, _mpc.mat()), *_contact, *_pairs,
        _static_contact,
        {{"mass_shift_per_s2", _static_contact.shift},
         {"newton_iterations", _static_contact.iterations},
         {"ncp_iterations", _static_contact.totals.ncp_iterations}});
    summary["joints"]["coupling"] =
        "contact as a constraint of the Newton iteration, condensed on the "
        "initial effective matrix";
  }
  summary["newton"] = newton_json(_newton, _static_report, nt, steps_all);
  if (_bulk.concrete.implex)
  {
    // How far the implicit stresses of the IMPL-EX steps are from
    // equilibrium, in the units of the Newton tolerance (README).
    summary["implex_equilibrium_error"] = {
        {"rms", std::sqrt(nt.implex_error_squares / steps_all)},
        {"max", nt.implex_error_max},
        {"t_of_max", nt.implex_error_time}};
  }
  if (_wave)
  {
    summary["foundation"] = wave_foundation_summary(
        *_wave, *_waves.field, _mtf ? 0.0 : _vs.boundary->measure());
    summary["foundation"]["free_field_load_seconds"] = _free_field_seconds;
    if (_mtf)
      summary["foundation"]["mtf"] = _mtf->summary();
  }
  summary["wall_seconds"] = seconds_since(_wall_start);
  print_summary_line(_comm, summary,
                     ", Newton iterations per step " +
                         std::to_string(nt.iterations / steps_all));
  return summary;
}

/// face_<name>_concrete.csv per face of a 3D dam: the envelope of the
/// strain rate and the final kappa_t at the face's points (the maps of
/// plot_arch_dam.py).
void ConcreteSeismicAnalysis::write_concrete_faces(
    const results::StressEnvelope& envelope, const ConcreteRecorder& state,
    const std::vector<double>& kappa_t) const
{
  for (std::size_t i = 0; i < _s.faces.size(); ++i)
  {
    std::vector<double> local;
    for (std::size_t k = 0; k < _face_points[i].size(); ++k)
    {
      const std::int32_t p = _face_points[i][k];
      const auto& x = envelope.point(p);
      local.insert(local.end(),
                   {x[0], x[1], x[2], state.rate().max[p], state.rate().t[p],
                    kappa_t[p], results::distance_to(x, _s.singular_points),
                    static_cast<double>(_face_point_cells[i][k])});
    }
    write_rows_csv(_comm, local, 8,
                   "x_m,y_m,z_m,max_strain_rate_per_s,t_max_strain_rate_s,"
                   "kappa_t,distance_to_singular_m,cell",
                   _folder.dir /
                       ("face_" + _s.faces[i].first + "_concrete.csv"));
  }
}

/// envelopes.xdmf with the state variables as cell maxima, dam_points.csv,
/// and the summary's concrete entries.
void ConcreteSeismicAnalysis::write_concrete_outputs(json& summary) const
{
  const std::filesystem::path& dir = _folder.dir;
  const auto& envelope = _stresses->envelope();
  const ConcreteRecorder& state = *_concrete_state;
  const std::size_t n_pts = _in_dam.size();
  std::vector<double> rate_all(_cm.strain_rate().size(), 0.0),
      kt_rate_all(rate_all.size(), 0.0);
  std::copy(state.rate().max.begin(), state.rate().max.end(), rate_all.begin());
  std::copy(state.kt_rate().max.begin(), state.kt_rate().max.end(),
            kt_rate_all.begin());
  results::write_envelopes(_fe, envelope,
                           region_cells(_fe.model(), _bulk.regions),
                           dir / "envelopes.xdmf", _cm.stress_space(), false,
                           {{"kappa_t", _cm.kappa_t()},
                            {"kappa_c", _cm.kappa_c()},
                            {"max_strain_rate_per_s", rate_all},
                            {"max_kappa_t_rate_per_s", kt_rate_all}});
  std::vector<double> kt(_cm.kappa_t().begin(), _cm.kappa_t().begin() + n_pts),
      kc(_cm.kappa_c().begin(), _cm.kappa_c().begin() + n_pts);
  if (_fe.dim() == 3)
    write_concrete_faces(envelope, state, kt);
  std::vector<double> syy_hi(n_pts), syy_lo(n_pts);
  for (std::size_t i = 0; i < n_pts; ++i)
  {
    syy_hi[i] = 1e-6 * state.syy_max().max[i];
    syy_lo[i] = -1e-6 * state.syy_min().max[i];
  }
  write_dam_points(_comm, _fe.dim(), envelope, _in_dam,
                   {&kt, &kc, &state.rate().max, &state.rate().t,
                    &state.kt_rate().max, &syy_hi, &syy_lo},
                   dir / "dam_points.csv");

  ScalarEnvelope kt_final(n_pts);
  kt_final.update(_cm.kappa_t(), _s.steps * _s.scheme.dt);
  const auto x = _cm.coordinates();
  summary["concrete"] = concrete_json(_bulk.concrete, _cm, _fe.degree());
  summary["max_kappa_t"] = scalar_json(
      scalar_extreme(_comm, kt_final, x, _in_dam), 1.0, false, _fe.dim());
  summary["max_strain_rate_per_s"] = scalar_json(
      scalar_extreme(_comm, state.rate(), x, _in_dam), 1.0, true, _fe.dim());
  summary["max_vertical_stress_mpa"] =
      scalar_json(scalar_extreme(_comm, state.syy_max(), x, _in_dam), 1e-6,
                  true, _fe.dim());
  summary["min_vertical_stress_mpa"] =
      scalar_json(scalar_extreme(_comm, state.syy_min(), x, _in_dam), -1e-6,
                  true, _fe.dim());
}
} // namespace

std::unique_ptr<SeismicAnalysis> concrete_seismic_analysis(
    fem::ElasticModel& fe, const SeismicSettings& s, const ConcreteBulk& bulk,
    const ModelLoads& loads, const RunFolder& folder, Mat tie,
    const WaveFoundation* wave, const ContactJoints* contact)
{
  return std::make_unique<ConcreteSeismicAnalysis>(fe, s, bulk, loads, folder,
                                                   tie, wave, contact);
}
} // namespace damseis::analysis
