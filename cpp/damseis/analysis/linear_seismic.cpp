#include "linear_seismic.h"
#include "contact_joints.h"
#include "energy_recorder.h"
#include "engine_settings.h"
#include "face_direction_recorder.h"
#include "free_field_load.h"
#include "ground_motion_load.h"
#include "initial_motion.h"
#include "modal_stage.h"
#include "recorders.h"
#include "run_outputs.h"
#include "seismic_system.h"
#include "timed_loads.h"
#include "transmitting_foundation.h"
#include "viscous_spring_foundation.h"
#include <chrono>
#include <cmath>
#include <damseis/engine/linear_stepper.h>
#include <damseis/engine/partitioned_stepper.h>
#include <damseis/engine/time_history.h>
#include <damseis/fem/facet_dofs.h>
#include <damseis/fem/prolongation.h>
#include <damseis/fem/tied_dofs.h>
#include <damseis/fem/viscous_boundary.h>
#include <damseis/geometry/ground_surface.h>
#include <damseis/geometry/tags.h>
#include <damseis/joint/contact_stepper.h>
#include <damseis/joint/joint_recorder.h>
#include <damseis/joint/joint_surfaces.h>
#include <damseis/linalg/all_gather.h>
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
#include <numbers>
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
/// stress points. With contact joints: K and M on all dofs, the static stage
/// and the time history with contact (total state), the joint outputs.
class LinearSeismicAnalysis : public SeismicAnalysis
{
public:
  LinearSeismicAnalysis(fem::ElasticModel& fe, const SeismicSettings& s,
                        const ModelLoads& loads, RunFolder folder, Mat tie,
                        const ContactJoints* contact,
                        const WaveFoundation* wave);
  void modal_stage() override;
  void static_stage() override;
  void time_history() override;
  json results() override;

private:
  void add_recorders(engine::TimeHistory& history);

  /// The initial state of a run with an initial velocity.
  engine::InitialState initial_state();
  /// Contact joints: the pairs, the bonded system for the modes, and with
  /// P2 the midside constraints (sys reduced by them).
  void set_up_contact(SeismicSystem& sys);
  /// The modal stage of a model with contact joints: on the joints closed.
  void modal_stage_closed_joints();
  /// A wave foundation: the boundary's springs into K, its dashpots kept
  /// for the damping, the free field of the ground motion.
  void set_up_wave_foundation(Mat K);
  /// The seismic load: the free field's (wave foundation) or the base
  /// acceleration's, with `sustained` held.
  std::unique_ptr<engine::DynamicLoad> seismic_load(Vec sustained) const;
  std::vector<std::vector<std::int8_t>> face_joint_sides() const;

  fem::ElasticModel& _fe;
  const SeismicSettings& _s;
  const ModelLoads _loads;
  RunFolder _folder;
  Mat _tie;
  const ContactJoints* _contact; ///< null: no contact joints
  const WaveFoundation* _wave;   ///< null: massless foundation
  std::unique_ptr<fem::ViscousBoundary> _boundary;
  /// A multi-transmitting boundary (null: none).
  std::unique_ptr<TransmittingFoundation> _mtf;
  std::unique_ptr<geometry::GroundSurface> _ground;
  Matrix _dashpots{nullptr, false};
  std::shared_ptr<const boundary::FreeField> _free_field;
  double _free_field_seconds = 0.0; ///< assembling the free-field load
  Mat _modal_tie = nullptr;         ///< with contact: the joints bonded
  Matrix _K_bonded{nullptr, false}, _M_bonded{nullptr, false};
  Matrix _mpc{nullptr, false}; ///< P2 contact: the midside constraints
  std::optional<joint::PairSet> _pairs;
  std::optional<joint::StaticContactResult> _static_contact;
  MPI_Comm _comm;
  const Clock::time_point _wall_start = Clock::now();
  const fem::Reservoir* _added = nullptr; ///< Westergaard added mass
  Matrix _K{nullptr, false}, _M{nullptr, false}, _B{nullptr, false};
  /// Static load and solution, static stresses (system layout).
  Vector _F{nullptr, false}, _F_g{nullptr, false}, _u_static{nullptr, false},
      _s_static{nullptr, false};
  std::optional<ModalResult> _modal;
  double _static_seconds = 0.0;

  // The time history's parts and its report.
  std::unique_ptr<engine::Stepper> _stepper;
  joint::ContactStepper* _contact_stepper = nullptr; ///< _stepper, if contact
  JointObservers _joints;
  std::unique_ptr<FullDisplacement> _u;
  std::unique_ptr<StressRecorder> _stresses;
  std::unique_ptr<FaceDirectionRecorder> _face_directions; ///< 3D faces
  std::unique_ptr<PointHistories> _points;
  std::unique_ptr<FaceDisplacementRecorder> _face_u;
  std::unique_ptr<FieldRecorder> _fields;
  std::unique_ptr<NamedHistories> _named;
  std::unique_ptr<EnergyRecorder> _energy;
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
                                             RunFolder folder, Mat tie,
                                             const ContactJoints* contact,
                                             const WaveFoundation* wave)
    : _fe(fe), _s(s), _loads(loads), _folder(std::move(folder)),
      _tie(contact ? nullptr : tie), _contact(contact), _wave(wave),
      _modal_tie(contact ? tie : nullptr), _comm(fe.mesh()->comm())
{
  results::set_stage("assembly");
  print_model_line(fe, "");
  // The system (all dofs, or the tied unknowns u_r with u = P u_r) and the
  // static load: dead weight, hydrostatic pressure, the extra loads.
  SeismicSystem sys = assemble_seismic_system(fe, s, loads.static_loads, _tie);
  _added = sys.added;
  if (_wave)
    set_up_wave_foundation(sys.K.mat());
  if (_contact)
    set_up_contact(sys);
  if (_dashpots.mat() && _mpc.mat()) // P2 contact: on the reduced unknowns
    _dashpots = Matrix(fem::reduce_to_tied(_dashpots.mat(), _mpc.mat()), false);
  _K = std::move(sys.K);
  _M = std::move(sys.M);
  _F = std::move(sys.F_static);
  _F_g = std::move(sys.F_g);
  _u_static = linalg::column_vector(_K.mat());
  _static_seconds = seconds_since(_wall_start);
}

void LinearSeismicAnalysis::set_up_wave_foundation(Mat K)
{
  IncidentWaves waves =
      incident_waves(_fe, _s, *_wave, _loads.initial_velocity != nullptr);
  _ground = std::move(waves.ground);
  _free_field = std::move(waves.field);
  if (_wave->mtf)
  {
    if (_contact)
      throw std::invalid_argument("a multi-transmitting boundary does not "
                                  "yet take contact joints");
    _mtf = std::make_unique<TransmittingFoundation>(
        _fe, *_wave, _added, _free_field, *_ground, _s.scheme.dt, _tie);
    return;
  }
  ViscousSpringParts vs =
      viscous_spring_parts(_fe, _s, *_wave, *_free_field, _tie);
  _boundary = std::move(vs.boundary);
  _dashpots = std::move(vs.dashpots);
  MatAXPY(K, 1.0, vs.springs.mat(), SUBSET_NONZERO_PATTERN);
}

std::unique_ptr<engine::DynamicLoad>
LinearSeismicAnalysis::seismic_load(Vec sustained) const
{
  if (_mtf)
    return _mtf->load(_modal->damping, _s.scheme.dt);
  if (_wave)
    return std::make_unique<FreeFieldLoad>(
        _fe, _boundary.get(), *_ground, _free_field, _M.mat(), _K.mat(),
        _modal->damping, _s.scheme.dt, _tie, sustained);
  return std::make_unique<GroundMotionLoad>(_fe, _s, _M.mat(), _tie, sustained);
}

void LinearSeismicAnalysis::set_up_contact(SeismicSystem& sys)
{
  // The modes of the joints bonded (the natural frequencies and the
  // Rayleigh damping of the closed dam).
  _K_bonded = Matrix(fem::reduce_to_tied(sys.K.mat(), _modal_tie), false);
  _M_bonded = Matrix(fem::reduce_to_tied(sys.M.mat(), _modal_tie), false);
  JointPairs jp = set_up_joint_pairs(_fe, _s, *_contact, sys);
  _pairs = std::move(jp.pairs);
  _mpc = std::move(jp.mpc);
  _tie = _mpc.mat();
}

void LinearSeismicAnalysis::modal_stage()
{
  results::set_stage("static stage and modal analysis");
  if (_contact)
    return modal_stage_closed_joints();
  Matrix M0 = dry_mass(_fe, _added, _tie);
  // K u = F is solved with the modal analysis' factors of K.
  _modal = modal_and_damping(
      _K.mat(), _M.mat(), _added ? M0.mat() : nullptr, _s,
      [&](KSP ksp) { KSPSolve(ksp, _F.vec(), _u_static.vec()); });
  _static_seconds += _modal->with_K_factors_seconds;
}

void LinearSeismicAnalysis::modal_stage_closed_joints()
{
  Matrix M0 = dry_mass(_fe, _added, _modal_tie);
  _modal = modal_and_damping(_K_bonded.mat(), _M_bonded.mat(),
                             _added ? M0.mat() : nullptr, _s, nullptr);
  _K_bonded = Matrix(nullptr, false);
  _M_bonded = Matrix(nullptr, false);
}

void LinearSeismicAnalysis::static_stage()
{
  if (_contact)
  {
    // Dead weight (with the joints active, or on the cantilevers alone),
    // then the rest of the static load in increments, with contact.
    const auto t0 = Clock::now();
    const double omega_1 =
        2.0 * std::numbers::pi * _modal->modes.frequencies_hz.front();
    _static_contact =
        joint::static_contact(_K.mat(), _M.mat(), omega_1, _F_g.vec(), _F.vec(),
                              *_pairs, _contact->statics, _contact->ncp);
    VecCopy(_static_contact->u.vec(), _u_static.vec());
    _static_seconds += seconds_since(t0);
  }
  else if (!_modal)
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
  // M a + C v + K u = -M sum_c r_c a_gc(t) (the added mass multiplies the
  // total acceleration, so it is part of M here); with a wave foundation
  // the absolute displacement under the free field's loads.
  // With contact the state is total: the static solution is the initial
  // displacement and the static load is sustained.
  if (_contact)
  {
    auto contact =
        std::make_shared<joint::CondensedContact>(*_pairs, _contact->ncp);
    const joint::StaticContactResult& st = *_static_contact;
    contact->set_state(st.g0, st.w, st.p, st.states, st.broken);
    std::vector<Mat> dashpots;
    if (_dashpots.mat())
      dashpots.push_back(_dashpots.mat());
    auto stepper = std::make_unique<joint::ContactStepper>(
        _M.mat(), _K.mat(), _modal->damping, _s.scheme, contact,
        _u_static.vec(), _contact->restitution, dashpots);
    _contact_stepper = stepper.get();
    _stepper = std::move(stepper);
  }
  else if (_mtf)
    _stepper = _mtf->stepper(_modal->damping, _s.scheme, _s.factorization);
  else
  {
    std::vector<Mat> dashpots;
    if (_dashpots.mat())
      dashpots.push_back(_dashpots.mat());
    _stepper = std::make_unique<engine::LinearStepper>(
        _M.mat(), _K.mat(), _modal->damping, _s.scheme, _s.factorization,
        dashpots);
  }
  const std::unique_ptr<engine::DynamicLoad> ground =
      seismic_load(_contact ? _F.vec() : nullptr);
  auto* free_field = dynamic_cast<const FreeFieldLoad*>(ground.get());
  // Tractions with their histories on top of the ground motion's load.
  const LoadWithTimedTerms load(*ground, _loads.timed, _tie);

  // Outputs: every input check has passed by now.
  open_run_folder(_comm, _folder);
  _u = std::make_unique<FullDisplacement>(*_stepper, _tie);
  Vector mode = linalg::row_vector(_modal_tie ? _modal_tie : _K.mat());
  write_modes(
      _fe, _modal->modes,
      [&](Vec x)
      {
        if (!_modal_tie)
          return _u->full(x);
        MatMult(_modal_tie, x, mode.vec());
        return mode.vec();
      },
      _folder.dir / "modes.xdmf");

  engine::TimeHistory history(
      _comm, time_history_settings(_s, _fe, _folder.dir, _folder.case_text),
      *_stepper, load);
  add_recorders(history);
  // (A restart takes its state from the checkpoint.)
  _run = history.run(_s.restart ? engine::InitialState{} : initial_state());
  if (free_field)
    _free_field_seconds = free_field->seconds();
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
        // The state is dynamic (relative to the static one), or total with
        // contact; the output is what stress_total asks for.
        const bool total_state = _contact != nullptr;
        MatMult(_B.mat(), _stepper->u(), _s_field.vec());
        if (_s.stress_total != total_state)
          VecAXPY(_s_field.vec(), total_state ? -1.0 : 1.0, _s_static.vec());
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
        const bool total_state = _contact != nullptr;
        VecCopy(_u->vec(), _u_out.vec());
        if (_s.stress_total != total_state)
          VecAXPY(_u_out.vec(), total_state ? -1.0 : 1.0, _u_static_full.vec());
        return _u_out.vec();
      },
      *_stresses);

  // Displacement, velocity, acceleration and stress at the named points,
  // means over the named groups.
  // (With contact the state is total: the static displacement is taken off
  // so that the histories are the seismic ones, as in every analysis.)
  _named = std::make_unique<NamedHistories>(
      _comm, _fe, _s, *_stepper, *_u, *_stresses,
      _contact ? _u_static_full.vec() : nullptr);
  for (engine::Observer* o : std::initializer_list<engine::Observer*>{
           _u.get(), _stresses.get(), _points.get()})
    history.observe(*o);
  // The arch and cantilever stresses on the faces (3D).
  if (_fe.dim() == 3 && !_s.faces.empty())
  {
    _face_directions = std::make_unique<FaceDirectionRecorder>(
        *_fe.S(), _s.face_tags ? *_s.face_tags : *model.facet_tags, _s,
        _face_points, *_stresses);
    history.observe(*_face_directions);
  }
  _named->observe(history);
  _energy = std::make_unique<EnergyRecorder>(*_stepper);
  history.observe(*_energy);
  if (_face_u)
    history.observe(*_face_u);
  history.observe(*_fields);
  if (_contact_stepper)
    _joints.observe(history, _fe, *_contact, *_contact_stepper,
                    _static_contact->w, _folder.dir, _s.output_every);
}

/// Per face, per point: -1 at a vertex of side 1 of a contact joint, 1 at
/// a vertex of side 2 (the split mesh's copy), 0 elsewhere (none without
/// contact joints). The stress points of P2 models sit at the cells'
/// vertices, one per cell: each takes its vertex's side, so that cells
/// touching a joint along an edge or at a vertex count too. (P1 models'
/// points are cell centres, off the joints: 0.)
std::vector<std::vector<std::int8_t>>
LinearSeismicAnalysis::face_joint_sides() const
{
  if (!_contact)
    return {};
  const auto& S = *_fe.S();
  auto mesh = S.mesh();
  const int tdim = mesh->topology().dim();
  auto& topology = mesh->topology_mutable();
  topology.create_connectivity(tdim - 1, 0);
  topology.create_connectivity(tdim, 0);
  auto f_to_v = topology.connectivity(tdim - 1, 0);
  auto c_to_v = topology.connectivity(tdim, 0);
  const auto& vmap = *topology.index_map(0);
  std::vector<std::int8_t> vertex_side(vmap.size_local() + vmap.num_ghosts(),
                                       0);
  const auto& joint_tags = *_contact->facet_tags;
  for (std::size_t i = 0; i < joint_tags.indices().size(); ++i)
  {
    const int tag = joint_tags.values()[i];
    for (const joint::JointSpec& j : _contact->joints)
    {
      if (tag != j.tag_side1 && tag != j.tag_side2)
        continue;
      for (std::int32_t v : f_to_v->links(joint_tags.indices()[i]))
        vertex_side[v] = tag == j.tag_side1 ? -1 : 1;
    }
  }
  const auto& map = *S.dofmap()->index_map;
  std::vector<std::int8_t> side(map.size_local() + map.num_ghosts(), 0);
  const auto& tags = _s.face_tags ? *_s.face_tags : *_fe.model().facet_tags;
  for (const auto& [name, face_tags] : _s.faces)
    results::for_each_face_point(
        S, tags, face_tags, true,
        [&](std::int32_t, std::int32_t c, std::int32_t p)
        {
          auto dofs = S.dofmap()->cell_dofs(c);
          auto cv = c_to_v->links(c);
          if (dofs.size() != cv.size())
            return; // a point per cell (P1): inside the cell
          for (std::size_t k = 0; k < dofs.size(); ++k)
            if (dofs[k] == p)
              side[p] = vertex_side[cv[k]];
        });
  std::vector<std::vector<std::int8_t>> sides;
  for (const auto& points : _face_points)
  {
    std::vector<std::int8_t>& s = sides.emplace_back();
    for (std::int32_t p : points)
      s.push_back(side[p]);
  }
  return sides;
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
  const json crest_summary = write_crest_history(
      _comm, hist, dim, _s.steps, _s.scheme.dt, crest_static, base_static,
      _contact != nullptr, dir / "crest.csv");

  const auto& envelope = _stresses->envelope();
  results::write_envelopes(_fe, envelope,
                           region_cells(_fe.model(), _s.dam_regions),
                           dir / "envelopes.xdmf");
  if (_face_u)
    _face_u->write_csv(_comm, dir / "displacement_envelope.csv");
  const auto sides = face_joint_sides();
  json faces = write_faces(_comm, _s, envelope, _face_points, dim, dir, sides);
  if (_face_directions)
  {
    const json d = _face_directions->write(_comm, _s, dir, sides);
    for (const auto& [name, v] : d.items())
      faces[name]["arch_cantilever_away_from_singular_points"] = v;
  }
  json summary = seismic_summary(
      _comm, _fe, _s, *_modal, _added != nullptr, _points->crest().node(),
      envelope, faces, _stepper->solver_name(),
      {_static_seconds, _modal->seconds, _stepper->factor_seconds(),
       _run.loop_seconds, _run.restarted_from_step});
  summary.update(crest_summary);
  _named->write(_comm, dir, summary);
  summary["energy"] = _energy->write(_comm, dir / "energy.csv");
  if (_joints.table)
  {
    summary["joints"] = _joints.write(
        _comm, dir, joint_pair_faces(_fe, _s, _mpc.mat()), *_contact, *_pairs,
        *_static_contact,
        {{"mass_shift_per_s2", _static_contact->shift},
         {"iterations", _static_contact->iterations},
         {"ncp_iterations", _static_contact->totals.ncp_iterations}});
  }
  if (_wave)
  {
    summary["foundation"] = wave_foundation_summary(
        *_wave, *_free_field, _boundary ? _boundary->measure() : 0.0);
    summary["foundation"]["free_field_load_seconds"] = _free_field_seconds;
    if (_mtf)
      summary["foundation"]["mtf"] = _mtf->summary();
    if (const auto* p =
            dynamic_cast<const engine::PartitionedStepper*>(_stepper.get()))
    {
      // Rank 0's clock: the partition's step split.
      const dynamics::StepSeconds& t = p->step_seconds();
      summary["foundation"]["step_seconds"] = {{"boundary", t.boundary},
                                               {"solve", t.solve},
                                               {"band", t.band},
                                               {"rest", t.rest},
                                               {"steps", t.steps}};
    }
  }
  summary["wall_seconds"] = seconds_since(_wall_start);
  print_summary_line(_comm, summary);
  return summary;
}
} // namespace

std::unique_ptr<SeismicAnalysis>
linear_seismic_analysis(fem::ElasticModel& fe, const SeismicSettings& s,
                        const ModelLoads& loads, const RunFolder& folder,
                        Mat tie, const ContactJoints* contact,
                        const WaveFoundation* wave)
{
  if (contact && !tie)
    throw std::invalid_argument("contact joints need the tie of the same "
                                "joints for the modal stage");
  return std::make_unique<LinearSeismicAnalysis>(fe, s, loads, folder, tie,
                                                 contact, wave);
}

nlohmann::json wave_foundation_summary(const WaveFoundation& wave,
                                       const boundary::FreeField& f,
                                       double boundary_measure)
{
  nlohmann::json corrected = nlohmann::json::array();
  for (int i = 0; i < 3; ++i)
    corrected.push_back(f.baseline_corrected(i));
  nlohmann::json s = {{"scattering_centre_m", wave.centre},
                      {"rock",
                       {{"E_pa", wave.rock.E},
                        {"nu", wave.rock.nu},
                        {"rho_kg_m3", wave.rock.rho},
                        {"cp_m_s", wave.rock.cp()},
                        {"cs_m_s", wave.rock.cs()}}},
                      {"z_base_m", wave.z_base},
                      {"z_surface_m", wave.z_surface},
                      {"surface_delay_s", f.surface_delay()},
                      {"record_baseline_corrected", corrected}};
  if (wave.mtf)
  {
    s["model"] =
        std::string("mass, multi-transmitting boundary (Liao), ") +
        (wave.mtf->band_explicit ? "explicit band (Hughes-Liu partition), "
                                 : "implicit band, ") +
        f.description();
    return s;
  }
  s["model"] = "mass, viscous-spring boundary, " + f.description();
  s["boundary_measure"] = boundary_measure;
  s["boundary_measure_unit"] = "m2 in 3D, m in 2D (per unit thickness)";
  s["spring_factors"] = {wave.factors.normal, wave.factors.tangential};
  return s;
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
    run_plot_script(plot_script, out_dir);
}

void run_plot_script(const std::string& script,
                     const std::filesystem::path& dir)
{
  const std::string cmd = std::string(DAMSEIS_PYTHON) + " " +
                          DAMSEIS_SOURCE_DIR + "/scripts/" + script + " \"" +
                          dir.string() + "\"";
  if (std::system(cmd.c_str()) != 0)
    std::fprintf(stderr, "warning: plotting failed: %s\n", cmd.c_str());
}
} // namespace damseis::analysis
