// The observers every seismic analysis plugs into the engine: the
// full-space displacement of a step, the stress envelopes, the crest and
// base histories, the displacement envelope along a face and the XDMF
// fields. Each saves and restores its recording in checkpoints.
#pragma once

#include "seismic_settings.h"
#include <damseis/engine/parts.h>
#include <damseis/engine/time_history.h>
#include <damseis/fem/elastic_model.h>
#include <damseis/results/displacement_envelope.h>
#include <damseis/results/field_writer.h>
#include <damseis/results/point_probe.h>
#include <damseis/results/stress_envelope.h>
#include <dolfinx/fem/Function.h>
#include <dolfinx/la/petsc.h>
#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>

namespace damseis::analysis
{
/// The displacement of all dofs at the step, u = P u_r with tied joints (P
/// = `tie`) or the stepper's u: computed once per step for the recorders
/// added after it.
class FullDisplacement : public engine::Observer
{
public:
  FullDisplacement(const engine::Stepper& stepper, Mat tie);
  void record(int, double) override;
  /// The current full-space displacement.
  Vec vec() const;
  /// The full-space image of a system vector (a work vector with ties).
  Vec full(Vec x) const;

private:
  const engine::Stepper& _stepper;
  Mat _tie;
  dolfinx::la::petsc::Vector _u{nullptr, false}, _work{nullptr, false};
};

/// Envelopes of the principal stresses at every stress point: `stress`
/// gives the stress of the step (owned points first, the envelope's
/// layout), computed once per step and kept for later recorders.
class StressRecorder : public engine::Observer
{
public:
  StressRecorder(results::StressEnvelope envelope,
                 std::function<std::span<const double>()> stress);
  void record(int k, double t) override;
  void save(engine::Arrays& arrays) const override;
  void restore(const engine::CheckpointData& data) override;
  /// The stress of the last recorded step.
  std::span<const double> stress() const { return _last; }
  const results::StressEnvelope& envelope() const { return _envelope; }

private:
  results::StressEnvelope _envelope;
  std::function<std::span<const double>()> _stress;
  std::span<const double> _last;
};

/// Displacement histories at the crest and base points (the nodes nearest
/// to them), per step: crest then base components, on the owning rank
/// until reduce().
class PointHistories : public engine::Observer
{
public:
  PointHistories(const dolfinx::fem::FunctionSpace& V,
                 const std::array<double, 3>& crest_point,
                 const std::array<double, 3>& base_point, int steps,
                 const FullDisplacement& u);
  void record(int k, double t) override;
  void save(engine::Arrays& arrays) const override;
  void restore(const engine::CheckpointData& data) override;
  /// The histories on every rank (collective; after the loop).
  const std::vector<double>& reduce(MPI_Comm comm);
  const results::PointProbe& crest() const { return _crest; }
  const results::PointProbe& base() const { return _base; }

private:
  results::PointProbe _crest, _base;
  int _dim;
  const FullDisplacement& _u;
  std::vector<double> _hist;
};

/// Displacement, velocity and acceleration relative to the supports, and
/// the absolute acceleration (with the ground's), at named points (the
/// nearest nodes), per step; on the owning rank until written.
class PointStates : public engine::Observer
{
public:
  using NamedPoint = std::pair<std::string, std::array<double, 3>>;
  /// `ground(k, c)`: the ground acceleration of component c at step k;
  /// `static_u` (full space, may be null): the static displacement, taken
  /// off where the state is total (the displacements are then the seismic
  /// ones in every analysis).
  PointStates(const dolfinx::fem::FunctionSpace& V,
              const std::vector<NamedPoint>& points, int steps,
              const engine::Stepper& stepper, const FullDisplacement& full,
              std::function<double(int, int)> ground, Vec static_u = nullptr);
  void record(int k, double t) override;
  void save(engine::Arrays& arrays) const override;
  void restore(const engine::CheckpointData& data) override;
  /// histories.csv on rank 0 (t, then per point u, v, a, a_abs by
  /// component) and the summary's peaks per point. Collective.
  nlohmann::json write_csv(MPI_Comm comm, double dt,
                           const std::filesystem::path& file);

private:
  std::vector<std::string> _names;
  std::vector<results::PointProbe> _probes;
  int _dim;
  const engine::Stepper& _stepper;
  const FullDisplacement& _full;
  std::function<double(int, int)> _ground;
  /// Per point: the static displacement taken off (owner rank).
  std::vector<std::array<double, 3>> _static;
  std::vector<double> _hist; ///< per step, point, quantity, component
};

/// The stress components at named points (the nearest stress point of the
/// envelope's, in the stress of the envelopes: total or seismic), per step;
/// on the owning rank until written.
class PointStresses : public engine::Observer
{
public:
  PointStresses(MPI_Comm comm,
                const std::vector<PointStates::NamedPoint>& points, int steps,
                const StressRecorder& stresses);
  void record(int k, double t) override;
  void save(engine::Arrays& arrays) const override;
  void restore(const engine::CheckpointData& data) override;
  /// stress_histories.csv on rank 0 [MPa] and, per point, where its stress
  /// point is and the peaks of the components. Collective.
  nlohmann::json write_csv(MPI_Comm comm, double dt,
                           const std::filesystem::path& file);

private:
  std::vector<std::string> _names;
  std::vector<std::int32_t> _local;          ///< owned point, -1 elsewhere
  std::vector<std::array<double, 3>> _where; ///< the stress points
  int _nc;
  const StressRecorder& _stresses;
  std::vector<double> _hist; ///< per step, point, component
};

/// Displacement, velocity and acceleration (relative to the supports,
/// static part taken off where the state is total) and the absolute
/// acceleration, averaged over the volume or area of named groups of
/// cells or facets (fem::group_weights: for a uniform density a cell
/// group's mean velocity is its momentum over its mass), per step (the
/// same on every rank: one reduction per step).
class GroupStates : public engine::Observer
{
public:
  GroupStates(const fem::ElasticModel& fe,
              const std::vector<SeismicSettings::HistoryGroup>& groups,
              int steps, const engine::Stepper& stepper,
              const FullDisplacement& full,
              std::function<double(int, int)> ground, Vec static_u = nullptr);
  void record(int k, double t) override;
  void save(engine::Arrays& arrays) const override;
  void restore(const engine::CheckpointData& data) override;
  /// group_histories.csv on rank 0 and the summary's peaks per group.
  nlohmann::json write_csv(MPI_Comm comm, double dt,
                           const std::filesystem::path& file) const;

private:
  /// Per group: the weighted sums of the components of x over the owned
  /// dofs, added into `out` (dim values per group).
  void local_sums(Vec x, std::vector<double>& out) const;
  std::vector<std::string> _names;
  /// Per group: the weights of its owned dofs (0 outside it).
  std::vector<std::vector<double>> _weights;
  std::vector<double> _total; ///< per group, component: sum of the weights
  int _dim;
  MPI_Comm _comm;
  const engine::Stepper& _stepper;
  const FullDisplacement& _full;
  std::function<double(int, int)> _ground;
  std::vector<double> _static; ///< per group, component: static mean
  std::vector<double> _hist;   ///< per step, group, quantity, component
};

/// The histories a case asks for by name (output.history_points,
/// output.history_groups): states and stresses at points, means over
/// groups; written as histories.csv, stress_histories.csv and
/// group_histories.csv with their summary entries.
class NamedHistories
{
public:
  /// `static_u` (full space, may be null): the static displacement, taken
  /// off where the state is total.
  NamedHistories(MPI_Comm comm, const fem::ElasticModel& fe,
                 const SeismicSettings& s, const engine::Stepper& stepper,
                 const FullDisplacement& full, const StressRecorder& stresses,
                 Vec static_u);
  /// Adds the recorders (after `stresses`).
  void observe(engine::TimeHistory& history);
  /// The files and the summary entries. Collective.
  void write(MPI_Comm comm, const std::filesystem::path& dir,
             nlohmann::json& summary);

private:
  const SeismicSettings& _s;
  PointStates _points;
  GroupStates _groups;
  PointStresses _stresses;
};

/// Envelope of the horizontal displacement along a tagged face relative to
/// the base point: u - `reference` (may be null) minus the base's
/// displacement less `base_reference`.
class FaceDisplacementRecorder : public engine::Observer
{
public:
  FaceDisplacementRecorder(
      const dolfinx::fem::FunctionSpace& V,
      const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags, int tag,
      const results::PointProbe& base, const FullDisplacement& u,
      Vec reference = nullptr, double base_reference = 0.0);
  void record(int k, double t) override;
  void save(engine::Arrays& arrays) const override;
  void restore(const engine::CheckpointData& data) override;
  void write_csv(MPI_Comm comm, const std::filesystem::path& file) const
  {
    _envelope.write_csv(comm, file);
  }

private:
  results::DisplacementEnvelope _envelope;
  const results::PointProbe& _base;
  const FullDisplacement& _u;
  Vec _reference;
  double _base_reference;
};

/// The time series fields.xdmf (fields_from_step<k>.xdmf after a restart
/// from step k), every `every` steps: the displacement `displacement()`,
/// the stresses of `stresses` and the named extra point scalars.
class FieldRecorder : public engine::Observer
{
public:
  struct Extras
  {
    std::shared_ptr<const dolfinx::fem::FunctionSpace> stress_space;
    std::vector<std::string> names;
    std::function<std::vector<std::span<const double>>()> values;
  };
  FieldRecorder(fem::ElasticModel& fe, std::filesystem::path out_dir, int every,
                std::function<Vec()> displacement,
                const StressRecorder& stresses, Extras extras = {});
  void begin(int first_step) override;
  void record(int k, double t) override;

private:
  fem::ElasticModel& _fe;
  std::filesystem::path _dir;
  int _every;
  std::function<Vec()> _displacement;
  const StressRecorder& _stresses;
  Extras _extras;
  std::optional<results::FieldWriter> _writer;
  dolfinx::fem::Function<double> _u;
};
} // namespace damseis::analysis
