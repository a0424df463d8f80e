#include "transmitting_foundation.h"
#include "free_field_load.h"
#include "run_outputs.h"
#include <damseis/dynamics/partitioned_newmark.h>
#include <damseis/engine/partitioned_stepper.h>
#include <damseis/input/case.h>
#include <damseis/results/progress.h>
#include <numbers>
#include <sstream>

namespace damseis::analysis
{
using dolfinx::la::petsc::Matrix;
using dolfinx::la::petsc::Vector;

TransmittingFoundation::TransmittingFoundation(
    const fem::ElasticModel& fe, const WaveFoundation& wave,
    const fem::Reservoir* reservoir,
    std::shared_ptr<const boundary::FreeField> field,
    const geometry::GroundSurface& ground, double dt)
    : _fe(fe), _wave(wave), _field(std::move(field)), _ground(ground)
{
  const Transmitting& t = *wave.mtf;
  // The band's cells are the explicit group.
  const std::vector<std::int32_t> band =
      region_cells(fe.model(), t.band_region);
  fem::ElasticModel::Partitioned p =
      fe.assemble_partitioned({t.band_region}, reservoir);
  _K = Matrix(p.K, false);
  _K_implicit = Matrix(p.K_implicit, false);
  _M = Matrix(p.M, false);
  _band_mass = Vector(p.M_explicit, false);
  fem::MtfSettings m;
  m.order = t.order;
  m.drift = t.drift;
  m.spacing = t.spacing;
  m.speed_normal = wave.rock.cp();
  m.speed_tangential = wave.rock.cs();
  m.dt = dt;
  _mtf = std::make_shared<fem::MtfBoundary>(
      *fe.V(), *fe.model().facet_tags, wave.boundary_tags, band, m,
      separated_field(_field, ground, dt));
  _omega = dynamics::highest_explicit_frequency(_K.mat(), _K_implicit.mat(),
                                                _band_mass.vec(), _mtf->rows());
  const auto nodes = _mtf->node_counts();
  std::ostringstream line;
  line << "foundation with mass, multi-transmitting boundary (order " << t.order
       << ", drift " << t.drift << ", s = c_p dt / dx = " << m.courant() << ", "
       << nodes[0] << " nodes, " << nodes[1]
       << " on the bottom), the band explicit (highest frequency "
       << _omega / (2.0 * std::numbers::pi)
       << " Hz), vertically incident waves: the surface moves with the "
          "record "
       << _field->surface_delay() << " s late";
  results::print(fe.mesh()->comm(), line.str());
}

std::unique_ptr<engine::Stepper>
TransmittingFoundation::stepper(dynamics::RayleighDamping damping,
                                const dynamics::TimeScheme& scheme,
                                linalg::Factorization factorization)
{
  // 2 % above the power iteration's estimate (it approaches the highest
  // frequency from below); the band takes the mass-proportional damping
  // alone, implicitly.
  _stable_dt =
      dynamics::explicit_stable_step(1.02 * _omega, {damping.a_mass, 0.0});
  std::ostringstream line;
  line << "explicit band: stable time step " << _stable_dt
       << " s (Hughes-Liu partition); time.dt = " << scheme.dt << " s";
  results::print(_fe.mesh()->comm(), line.str());
  if (scheme.dt > _stable_dt)
  {
    std::ostringstream m;
    m << "time.dt = " << scheme.dt
      << " s is above the stable step of the transmitting boundary's "
         "explicit band, "
      << _stable_dt
      << " s: a smaller time.dt (or a coarser "
         "foundation.band_size)";
    throw input::InputError(m.str());
  }
  if (scheme.alpha != 0.0)
    throw input::InputError("time.hht_alpha must be 0 with a multi-"
                            "transmitting boundary (the partition is "
                            "Newmark's average acceleration)");
  return std::make_unique<engine::PartitionedStepper>(
      _M.mat(), _K.mat(), _K_implicit.mat(), damping, scheme.dt, factorization,
      _mtf);
}

std::unique_ptr<engine::DynamicLoad>
TransmittingFoundation::load(dynamics::RayleighDamping damping, double dt) const
{
  return std::make_unique<FreeFieldLoad>(
      _fe, nullptr, _ground, _field, _M.mat(), _K_implicit.mat(), damping, dt);
}

nlohmann::json TransmittingFoundation::summary() const
{
  const auto nodes = _mtf->node_counts();
  return {{"order", _wave.mtf->order},
          {"drift", _wave.mtf->drift},
          {"spacing_m", _wave.mtf->spacing},
          {"artificial_speeds_m_s", {_wave.rock.cp(), _wave.rock.cs()}},
          {"courant_s", _mtf->settings().courant()},
          {"boundary_nodes", nodes[0]},
          {"bottom_nodes", nodes[1]},
          {"band_highest_frequency_hz", _omega / (2.0 * std::numbers::pi)},
          {"stable_dt_s", _stable_dt}};
}
} // namespace damseis::analysis
