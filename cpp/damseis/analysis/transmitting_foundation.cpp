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

namespace
{
/// The formula on the motion from a static displacement u_s: the values
/// of u - u_s, plus u_s (the nonlinear engine's state is total).
class FromStatic : public dynamics::PrescribedDisplacement
{
public:
  FromStatic(std::shared_ptr<fem::MtfBoundary> mtf, Vec u_static)
      : _mtf(std::move(mtf))
  {
    for (Vec* x : {&_us, &_now, &_prev})
      VecDuplicate(u_static, x);
    VecCopy(u_static, _us);
    const std::vector<PetscInt>& rows = _mtf->rows();
    _static.resize(rows.size());
    VecGetValues(_us, static_cast<PetscInt>(rows.size()), rows.data(),
                 _static.data());
  }
  ~FromStatic() override
  {
    for (Vec* x : {&_us, &_now, &_prev})
      VecDestroy(x);
  }
  FromStatic(const FromStatic&) = delete;
  FromStatic& operator=(const FromStatic&) = delete;
  const std::vector<PetscInt>& rows() const override { return _mtf->rows(); }
  void values(int n_next, Vec u_n, Vec u_prev, std::span<double> out) override
  {
    VecWAXPY(_now, -1.0, _us, u_n);
    VecWAXPY(_prev, -1.0, _us, u_prev);
    _mtf->values(n_next, _now, _prev, out);
    for (std::size_t i = 0; i < out.size(); ++i)
      out[i] += _static[i];
  }

private:
  std::shared_ptr<fem::MtfBoundary> _mtf;
  Vec _us = nullptr, _now = nullptr, _prev = nullptr;
  std::vector<double> _static;
};
} // namespace

void TransmittingFoundation::check_time_step(dynamics::RayleighDamping damping,
                                             const dynamics::TimeScheme& scheme)
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
}

std::unique_ptr<engine::Stepper>
TransmittingFoundation::stepper(dynamics::RayleighDamping damping,
                                const dynamics::TimeScheme& scheme,
                                linalg::Factorization factorization)
{
  check_time_step(damping, scheme);
  return std::make_unique<engine::PartitionedStepper>(
      _M.mat(), _K.mat(), _K_implicit.mat(), damping, scheme.dt, factorization,
      _mtf);
}

dynamics::Partition TransmittingFoundation::partition(Vec u_static)
{
  if (!_K_explicit.mat())
  {
    Mat K_E;
    MatDuplicate(_K.mat(), MAT_COPY_VALUES, &K_E);
    MatAXPY(K_E, -1.0, _K_implicit.mat(), SUBSET_NONZERO_PATTERN);
    _K_explicit = Matrix(K_E, false);
  }
  return {_K_implicit.mat(), _K_explicit.mat(),
          std::make_shared<FromStatic>(_mtf, u_static)};
}

std::unique_ptr<engine::DynamicLoad>
TransmittingFoundation::load(dynamics::RayleighDamping damping, double dt,
                             Vec sustained) const
{
  return std::make_unique<FreeFieldLoad>(_fe, nullptr, _ground, _field,
                                         _M.mat(), _K_implicit.mat(), damping,
                                         dt, nullptr, sustained);
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
