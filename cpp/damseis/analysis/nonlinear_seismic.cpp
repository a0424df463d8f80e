#include "nonlinear_seismic.h"
#include "concrete_stepper.h"
#include "concrete_system.h"
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
                   std::int32_t points, int dim)
      : _envelopes{ScalarEnvelope(points), ScalarEnvelope(points),
                   ScalarEnvelope(points, -HUGE_VAL),
                   ScalarEnvelope(points, -HUGE_VAL)},
        _cm(cm), _stresses(stresses), _nc(cm.components()), _vertical(dim - 1),
        _syy(points)
  {
  }
  void record(int, double t) override
  {
    rate().update(_cm.strain_rate(), t);
    kt_rate().update(_cm.kappa_t_rate(), t);
    const auto s = _stresses.stress();
    for (std::size_t i = 0; i < _syy.size(); ++i)
      _syy[i] = s[_nc * i + _vertical];
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
  const ScalarEnvelope& rate() const { return _envelopes[0]; }
  const ScalarEnvelope& kt_rate() const { return _envelopes[1]; }
  const ScalarEnvelope& syy_max() const { return _envelopes[2]; }
  const ScalarEnvelope& syy_min() const { return _envelopes[3]; }

private:
  /// The envelopes and their checkpoint names.
  std::array<ScalarEnvelope, 4> _envelopes;
  static constexpr std::array<const char*, 4> names = {"rate", "kt_rate",
                                                       "syy_hi", "syy_lo"};
  const fem::ConcreteModel& _cm;
  const StressRecorder& _stresses;
  /// Stress components per point; the vertical normal stress' index.
  int _nc, _vertical;
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

/// The concrete of every region of the bulk.
std::map<int, material::ConcreteParameters>
concrete_regions(const ConcreteBulk& bulk)
{
  std::map<int, material::ConcreteParameters> m;
  for (int r : bulk.regions)
    m[r] = bulk.concrete.params;
  return m;
}

/// Global number of cells of the regions.
std::int64_t region_cell_count(MPI_Comm comm, const geometry::Model& model,
                               const std::vector<int>& regions)
{
  const std::int32_t owned = model.mesh->topology()
                                 .index_map(model.mesh->topology().dim())
                                 ->size_local();
  std::int64_t n = 0;
  for (std::int32_t c : region_cells(model, regions))
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
void write_dam_points(MPI_Comm comm, int dim,
                      const results::StressEnvelope& env,
                      const std::vector<std::int8_t>& in_dam,
                      const std::vector<const std::vector<double>*>& columns,
                      const std::filesystem::path& file)
{
  const int nc = dim + 2 + static_cast<int>(columns.size());
  std::vector<double> local;
  for (std::size_t i = 0; i < in_dam.size(); ++i)
  {
    if (!in_dam[i])
      continue;
    const auto& x = env.point(static_cast<std::int32_t>(i));
    local.insert(local.end(), x.begin(), x.begin() + dim);
    local.insert(local.end(), {env.max_principal()[i] * 1e-6,
                               env.min_principal()[i] * 1e-6});
    for (const auto* c : columns)
      local.push_back((*c)[i]);
  }
  // The vertical stress is sigma_yy in 2D, sigma_zz in 3D.
  const std::string v = dim == 2 ? "syy" : "szz";
  write_rows_csv(comm, local, nc,
                 std::string(dim == 2 ? "x_m,y_m," : "x_m,y_m,z_m,") +
                     "max_principal_mpa,min_principal_mpa,kappa_t,kappa_c,"
                     "max_strain_rate_per_s,t_max_strain_rate_s,"
                     "max_kappa_t_rate_per_s,max_" +
                     v + "_mpa,min_" + v + "_mpa",
                 file);
}

/// {"value", "x", "y"(, "z")(, "t")} of a scalar extreme, scaled.
json scalar_json(const results::Extreme& e, double scale, bool with_time,
                 int dim)
{
  json j = {{"value", scale * e.value},
            {"x", coordinate(e.x[0])},
            {"y", coordinate(e.x[1])}};
  if (dim == 3)
    j["z"] = coordinate(e.x[2]);
  if (with_time)
    j["t"] = instant(e.t);
  return j;
}

/// summary.json "concrete": the material of the run.
json concrete_json(const ConcreteSettings& c, const fem::ConcreteModel& cm,
                   int degree)
{
  const auto& p = c.params;
  json j = {
      {"model", to_string(c.kind)},
      {"E_pa", p.E},
      {"fc_mpa", p.fc0 * 1e-6},
      {"ft_mpa", p.ft0 * 1e-6},
      {"Gf_n_per_m", p.Gf},
      {"static_E_pa", c.static_E},
      {"static_fc_mpa", c.static_fc * 1e-6},
      {"static_ft_mpa", c.static_ft * 1e-6},
      {"factor_E", c.applied.E},
      {"factor_strength", c.applied.strength},
      {"material_bins", cm.material_count()},
      {"material_integration", c.implex ? "implex" : "implicit"},
      {"characteristic_length_m", concrete_characteristic_length(c)},
      {"tension_softening", to_string(c.params.tension_softening)},
      {"cells_with_reduced_tensile_strength", cm.cells_with_reduced_strength()},
      {"cells_with_raised_tensile_energy",
       cm.cells_with_raised_tensile_energy()},
      // Energy Gf per unit crack area whatever the mesh: P1 cells no
      // larger than the snap-back limit.
      {"crack_band_exact",
       degree == 1 &&
           p.tension_softening == material::TensionSoftening::crack_band &&
           cm.cells_with_reduced_strength() == 0 &&
           cm.cells_with_raised_tensile_energy() == 0}};
  if (cm.cells_with_reduced_strength() > 0)
  {
    const auto ft_low = cm.reduced_tensile_strength_range();
    j["reduced_tensile_strength_mpa"] = {{"min", ft_low[0] * 1e-6},
                                         {"max", ft_low[1] * 1e-6}};
  }
  return j;
}

/// summary.json "newton": the Newton work of the static stage and of every
/// step of the time history (restored at a restart).
json newton_json(const dynamics::NewtonSettings& newton,
                 const StaticStageReport& st, const NewtonTotals& nt, int steps)
{
  return {{"rtol", newton.rtol},
          {"extrapolated_predictor", newton.extrapolated_predictor},
          {"static_iterations", st.iterations},
          {"static_cuts", st.cuts},
          {"iterations", nt.iterations},
          {"iterations_per_step", nt.iterations / steps},
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
           nt.return_map_seconds > 0.0
               ? nt.returned_points / nt.return_map_seconds
               : 0.0},
          {"seconds",
           {{"residual", nt.seconds_residual},
            {"tangent_assembly", nt.seconds_tangent},
            {"factorization", nt.seconds_factorization},
            {"direction_solves", nt.seconds_solve},
            {"return_maps_core_seconds", nt.return_map_seconds}}},
          {"step_cuts", nt.cuts},
          {"max_inelastic_points", nt.max_inelastic_points}};
}

/// Says where the crack band is not exact (material/README.md, README
/// "softening studies"): P2 elements, cells above the snap-back limit.
void print_crack_band_notes(MPI_Comm comm, const fem::ElasticModel& fe,
                            const fem::ConcreteModel& cm,
                            const ConcreteSettings& concrete,
                            const std::vector<int>& regions)
{
  if (concrete.params.tension_softening == material::TensionSoftening::none)
  {
    results::print(comm, "note: concrete.tension_softening = \"none\": the "
                         "concrete is perfectly plastic in tension (no "
                         "softening, no crack band)");
    return;
  }
  if (fe.degree() > 1)
  {
    results::print(comm,
                   "note: P" + std::to_string(fe.degree()) +
                       " elements: the crack band (energy Gf per unit crack "
                       "area) is exact for P1 only (a P2 cell can localise in "
                       "part of its points: 0.75 Gf in the crack-band test); "
                       "use mesh.order = 1 for softening studies");
  }
  // "note: N of M dam cells are larger than ... (snap-back limit ...): "
  auto large_cells = [&](std::int64_t n)
  {
    std::ostringstream note;
    note.precision(3);
    note << "note: " << n << " of "
         << region_cell_count(comm, fe.model(), regions)
         << " dam cells are larger than E Gf / ("
         << concrete.params.snap_back_safety
         << " ft^2) = " << concrete_characteristic_length(concrete)
         << " m (snap-back limit of the softening): ";
    return note.str();
  };
  if (cm.cells_with_raised_tensile_energy() > 0)
  {
    std::ostringstream note;
    note.precision(3);
    note << large_cells(cm.cells_with_raised_tensile_energy())
         << "their tensile strength is kept (concrete.tension_softening = "
            "\"crack_band_keep_strength\") and a crack in a cell of size h "
            "dissipates "
         << concrete.params.snap_back_safety << " ft^2 h / E per unit area, "
         << "more than Gf = " << concrete.params.Gf << " N/m";
    results::print(comm, note.str());
  }
  if (cm.cells_with_reduced_strength() == 0)
    return;
  const auto ft_low = cm.reduced_tensile_strength_range();
  std::ostringstream note;
  note.precision(3);
  note << large_cells(cm.cells_with_reduced_strength())
       << "their tensile strength is lowered from "
       << concrete.params.ft0 * 1e-6 << " to " << ft_low[0] * 1e-6 << ".."
       << ft_low[1] * 1e-6
       << " MPa (the crack band is not honoured there; summary.json "
          "concrete.cells_with_reduced_tensile_strength); refine the mesh "
          "where the concrete cracks, or see concrete.tension_softening";
  results::print(comm, note.str());
}

/// The analysis with HTC concrete in the dam: the state is total (static
/// included), Newton per step on the concrete system, stresses at the
/// quadrature points.
class ConcreteSeismicAnalysis : public SeismicAnalysis
{
public:
  ConcreteSeismicAnalysis(fem::ElasticModel& fe, const SeismicSettings& s,
                          ConcreteBulk bulk, const ModelLoads& loads,
                          RunFolder folder, Mat tie,
                          const WaveFoundation* wave);
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
  /// Bonded joints: u = P u_r (null: none), and the full stiffness.
  Mat _tie;
  Matrix _K_full{nullptr, false};
  /// A foundation with mass on a viscous-spring boundary (null: none).
  const WaveFoundation* _wave;
  IncidentWaves _waves;
  ViscousSpringParts _vs;
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

ConcreteSeismicAnalysis::ConcreteSeismicAnalysis(fem::ElasticModel& fe,
                                                 const SeismicSettings& s,
                                                 ConcreteBulk bulk,
                                                 const ModelLoads& loads,
                                                 RunFolder folder, Mat tie,
                                                 const WaveFoundation* wave)
    : _fe(fe), _s(s), _bulk(std::move(bulk)), _loads(loads),
      _folder(std::move(folder)), _comm(fe.mesh()->comm()),
      _cm(fe, concrete_regions(_bulk), _bulk.elastic, _bulk.plane), _tie(tie),
      _wave(wave)
{
  results::set_stage("assembly");
  const ConcreteSettings& concrete = _bulk.concrete;
  print_model_line(fe, ", concrete " + to_string(concrete.kind));
  // The system (on the tied unknowns with ties, the full K kept for the
  // tangent changes) and the static loads: the dead weight, then the
  // reservoir (and silt, uplift).
  SeismicSystem sys =
      assemble_seismic_system(fe, s, loads.static_loads, tie, true);
  _added = sys.added;
  _K = std::move(sys.K);
  _M = std::move(sys.M);
  _K_full = std::move(sys.K_full);
  _F_g = std::move(sys.F_g);
  _F_static = std::move(sys.F_static);
  if (tie)
    _system = std::make_unique<TiedConcreteSystem>(_cm, tie, _K_full.mat());
  else
    _system = std::make_unique<ConcreteSystem>(_cm);
  if (_wave)
    set_up_viscous_spring();
  _plastic = concrete.kind != ConcreteModelKind::elastic;
  _cm.set_implex(concrete.implex && _plastic);
  if (_plastic)
    print_crack_band_notes(_comm, fe, _cm, concrete, _bulk.regions);
}

void ConcreteSeismicAnalysis::set_up_viscous_spring()
{
  if (_wave->mtf)
    throw std::invalid_argument("the multi-transmitting boundary is not yet "
                                "available with HTC concrete");
  _waves = incident_waves(_fe, _s, *_wave, _loads.initial_velocity != nullptr);
  _vs = viscous_spring_parts(_fe, _s, *_wave, *_waves.field, _tie);
  // The springs: in K0 (system unknowns) and, as linear supports, in the
  // internal force of the dofs the material sees (all of them with ties).
  MatAXPY(_K.mat(), 1.0, _vs.springs.mat(), SUBSET_NONZERO_PATTERN);
  _system->set_supports(_tie ? _vs.boundary->springs() : _vs.springs.mat());
}

void ConcreteSeismicAnalysis::modal_stage()
{
  // The initial elastic system; Rayleigh damping with K0.
  results::set_stage("modal analysis");
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
  _static_report = solve_static_stage(*_system, _K.mat(), _M.mat(), _F_g.vec(),
                                      _F_static.vec(), _u_static.vec(), stage);
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

void ConcreteSeismicAnalysis::time_history()
{
  // M a + C v + f_int(u) = F_static - M sum_c r_c a_gc(t), u relative to
  // the base, total (static included). (IMPL-EX steps are extrapolated
  // anyway.)
  const ConcreteSettings& concrete = _bulk.concrete;
  _newton = concrete.newton;
  _newton.extrapolated_predictor =
      concrete.newton.extrapolated_predictor && !concrete.implex && _plastic;
  _stepper = std::make_unique<ConcreteStepper>(
      _M.mat(), _K.mat(), _modal->damping, _s.scheme, *_system, _cm, _newton,
      _s.factorization, _u_static.vec(), _f_int_static.vec(),
      _wave ? _vs.dashpots.mat() : nullptr);
  const std::unique_ptr<engine::DynamicLoad> ground = seismic_load();
  // Tractions with their histories on top of the ground motion's load.
  const LoadWithTimedTerms load(*ground, _loads.timed, _tie);

  open_run_folder(_comm, _folder);
  _u = std::make_unique<FullDisplacement>(*_stepper, _tie);
  write_modes(
      _fe, _modal->modes, [&](Vec x) { return _u->full(x); },
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
    summary["foundation"] =
        wave_foundation_summary(*_wave, *_waves.field, _vs.boundary->measure());
    summary["foundation"]["free_field_load_seconds"] = _free_field_seconds;
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

std::unique_ptr<SeismicAnalysis>
concrete_seismic_analysis(fem::ElasticModel& fe, const SeismicSettings& s,
                          const ConcreteBulk& bulk, const ModelLoads& loads,
                          const RunFolder& folder, Mat tie,
                          const WaveFoundation* wave)
{
  return std::make_unique<ConcreteSeismicAnalysis>(fe, s, bulk, loads, folder,
                                                   tie, wave);
}
} // namespace damseis::analysis
