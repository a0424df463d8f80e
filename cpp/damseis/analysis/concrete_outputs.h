// The concrete analysis' own outputs: the envelopes of the concrete state
// (strain rate, kappa_t rate, vertical stress) at the dam points, their
// extremes, dam_points.csv, the summary's "concrete" and "newton" entries,
// and the notes on the crack band.
#pragma once

#include "concrete_settings.h"
#include "concrete_stepper.h"
#include "recorders.h"
#include "static_stage.h"
#include <damseis/engine/parts.h>
#include <damseis/fem/concrete_model.h>
#include <damseis/geometry/gmsh_mesh.h>
#include <damseis/results/stress_envelope.h>
#include <nlohmann/json.hpp>
#include <span>
#include <vector>

namespace damseis::analysis
{
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
                                const std::vector<std::int8_t>& flag);

/// Global number of cells of the regions.
std::int64_t region_cell_count(MPI_Comm comm, const geometry::Model& model,
                               const std::vector<int>& regions);

/// The snap-back limit of the cell size, E Gf / (s ft^2) [m], s the
/// snap-back safety factor (1.25; material/README.md).
double concrete_characteristic_length(const ConcreteSettings& c);

/// dam_points.csv on rank 0: one row per owned dam point of every rank.
void write_dam_points(MPI_Comm comm, int dim,
                      const results::StressEnvelope& env,
                      const std::vector<std::int8_t>& in_dam,
                      const std::vector<const std::vector<double>*>& columns,
                      const std::filesystem::path& file);

/// {"value", "x", "y"(, "z")(, "t")} of a scalar extreme, scaled.
nlohmann::json scalar_json(const results::Extreme& e, double scale,
                           bool with_time, int dim);

/// summary.json "concrete": the material of the run.
nlohmann::json concrete_json(const ConcreteSettings& c,
                             const fem::ConcreteModel& cm, int degree);

/// summary.json "newton": the Newton work of the static stage and of every
/// step of the time history (restored at a restart).
nlohmann::json newton_json(const dynamics::NewtonSettings& newton,
                           const StaticStageReport& st, const NewtonTotals& nt,
                           int steps);

/// Says where the crack band is not exact (material/README.md, README
/// "softening studies"): P2 elements, cells above the snap-back limit.
void print_crack_band_notes(MPI_Comm comm, const fem::ElasticModel& fe,
                            const fem::ConcreteModel& cm,
                            const ConcreteSettings& concrete,
                            const std::vector<int>& regions);
} // namespace damseis::analysis
