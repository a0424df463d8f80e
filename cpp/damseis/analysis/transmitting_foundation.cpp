#include "transmitting_foundation.h"
#include "free_field_load.h"
#include "run_outputs.h"
#include <damseis/dynamics/partitioned_newmark.h>
#include <damseis/engine/partitioned_stepper.h>
#include <damseis/fem/tied_dofs.h>
#include <damseis/input/case.h>
#include <damseis/linalg/duplicate_matrix.h>
#include <damseis/linalg/petsc_vectors.h>
#include <damseis/results/progress.h>
#include <numbers>
#include <sstream>

namespace damseis::analysis
{
using dolfinx::la::petsc::Matrix;
using dolfinx::la::petsc::Vector;

namespace
{
/// A prescribed motion of all dofs on the tied unknowns u_r (u = P u_r):
/// its values from P u_r (and P v_r, P a_r), its rows the unknowns its
/// dofs alone give (untied dofs: P's column is theirs alone).
class TiedPrescribed : public dynamics::PrescribedMotion
{
public:
  TiedPrescribed(std::shared_ptr<dynamics::PrescribedMotion> inner, Mat P)
      : _inner(std::move(inner)), _P(P)
  {
    MatCreateVecs(P, &_reduced, &_scratch);
    for (Vec& x : _full)
      VecDuplicate(_scratch, &x);
    // The number of prescribed dofs each tied unknown takes.
    _inner_values.resize(_inner->rows().size());
    _inner_values.u.assign(_inner->rows().size(), 1.0);
    to_reduced(_inner_values.u);
    PetscInt r0 = 0, r1 = 0;
    VecGetOwnershipRange(_reduced, &r0, &r1);
    const double* r = nullptr;
    VecGetArrayRead(_reduced, &r);
    for (PetscInt i = r0; i < r1; ++i)
    {
      if (r[i - r0] > 1.5)
        throw std::invalid_argument("a transmitting boundary's node is tied "
                                    "(a joint reaches the boundary)");
      if (r[i - r0] > 0.5)
        _rows.push_back(i);
    }
    VecRestoreArrayRead(_reduced, &r);
  }
  ~TiedPrescribed() override
  {
    VecDestroy(&_reduced);
    VecDestroy(&_scratch);
    for (Vec& x : _full)
      VecDestroy(&x);
  }
  TiedPrescribed(const TiedPrescribed&) = delete;
  TiedPrescribed& operator=(const TiedPrescribed&) = delete;
  const std::vector<PetscInt>& rows() const override { return _rows; }
  void values(int n_next, const dynamics::Kinematics& now,
              const dynamics::Kinematics& prev,
              dynamics::PrescribedValues& out) override
  {
    const std::array<Vec, 6> reduced = {now.u,  now.v,  now.a,
                                        prev.u, prev.v, prev.a};
    for (int f = 0; f < 6; ++f)
      MatMult(_P, reduced[f], _full[f]);
    _inner->values(n_next, {_full[0], _full[1], _full[2]},
                   {_full[3], _full[4], _full[5]}, _inner_values);
    const auto n = static_cast<PetscInt>(_rows.size());
    for (auto [from, to] : {std::pair{&_inner_values.u, &out.u},
                            std::pair{&_inner_values.v, &out.v},
                            std::pair{&_inner_values.a, &out.a}})
    {
      to_reduced(*from);
      VecGetValues(_reduced, n, _rows.data(), to->data());
    }
  }

private:
  /// _reduced = P^T x, x the values on the inner rows (full layout), zero
  /// elsewhere.
  void to_reduced(const std::vector<double>& values)
  {
    const std::vector<PetscInt>& rows = _inner->rows();
    VecSet(_scratch, 0.0);
    VecSetValues(_scratch, static_cast<PetscInt>(rows.size()), rows.data(),
                 values.data(), INSERT_VALUES);
    VecAssemblyBegin(_scratch);
    VecAssemblyEnd(_scratch);
    MatMultTranspose(_P, _scratch, _reduced);
  }

  std::shared_ptr<dynamics::PrescribedMotion> _inner;
  Mat _P;
  Vec _reduced = nullptr, _scratch = nullptr;
  std::array<Vec, 6> _full{}; ///< the full layout's u, v, a at n and n - 1
  std::vector<PetscInt> _rows;
  dynamics::PrescribedValues _inner_values;
};
} // namespace

TransmittingFoundation::TransmittingFoundation(
    const fem::ElasticModel& fe, const WaveFoundation& wave,
    const fem::Reservoir* reservoir,
    std::shared_ptr<const boundary::FreeField> field,
    const geometry::GroundSurface& ground, double dt, Mat tie)
    : _fe(fe), _wave(wave), _field(std::move(field)), _ground(ground), _tie(tie)
{
  const Transmitting& t = *wave.mtf;
  // The band's cells are the explicit group (none if it is implicit).
  const std::vector<std::int32_t> band =
      region_cells(fe.model(), t.band_regions);
  fem::ElasticModel::Partitioned p = fe.assemble_partitioned(
      t.band_explicit ? t.band_regions : std::vector<int>{}, reservoir);
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
  _prescribed = _mtf;
  if (tie)
  {
    // The tied unknowns: P^T A P, the band's lumped mass P^T m.
    for (Matrix* A : {&_K, &_K_implicit, &_M})
      *A = Matrix(fem::reduce_to_tied(A->mat(), tie), false);
    Vector mass = linalg::column_vector(_K.mat());
    MatMultTranspose(tie, _band_mass.vec(), mass.vec());
    _band_mass = std::move(mass);
    _prescribed = std::make_shared<TiedPrescribed>(_mtf, tie);
  }
  if (t.band_explicit)
  {
    _omega = dynamics::highest_explicit_frequency(
        _K.mat(), _K_implicit.mat(), _band_mass.vec(), _prescribed->rows());
    // The band's own stiffness damping: band_damping of critical at its
    // highest frequency.
    _b_explicit = _omega > 0.0 ? 2.0 * t.band_damping / _omega : 0.0;
    Mat K_E = linalg::duplicate_matrix(_K.mat(), MAT_COPY_VALUES);
    MatAXPY(K_E, -1.0, _K_implicit.mat(), SUBSET_NONZERO_PATTERN);
    _K_explicit = Matrix(K_E, false);
  }
  const auto nodes = _mtf->node_counts();
  std::ostringstream line;
  line << "foundation with mass, multi-transmitting boundary (order " << t.order
       << ", drift " << t.drift << ", s = c_p dt / dx = " << m.courant() << ", "
       << nodes[0] << " nodes, " << nodes[1] << " on the bottom), ";
  if (t.band_explicit)
    line << "the band explicit (highest frequency "
         << _omega / (2.0 * std::numbers::pi) << " Hz, damped "
         << 100.0 * t.band_damping << "% there: b_E = " << _b_explicit << " s)";
  else
    line << "the band implicit";
  line << ", vertically incident waves: the surface moves with the record "
       << _field->surface_delay() << " s late";
  results::print(fe.mesh()->comm(), line.str());
}

namespace
{
/// The formula on the motion from a static displacement u_s: the values
/// of u - u_s, plus u_s (the nonlinear engine's state is total; u_s has
/// no velocity or acceleration).
class FromStatic : public dynamics::PrescribedMotion
{
public:
  FromStatic(std::shared_ptr<dynamics::PrescribedMotion> mtf, Vec u_static)
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
  void values(int n_next, const dynamics::Kinematics& now,
              const dynamics::Kinematics& prev,
              dynamics::PrescribedValues& out) override
  {
    VecWAXPY(_now, -1.0, _us, now.u);
    VecWAXPY(_prev, -1.0, _us, prev.u);
    _mtf->values(n_next, {_now, now.v, now.a}, {_prev, prev.v, prev.a}, out);
    for (std::size_t i = 0; i < out.u.size(); ++i)
      out.u[i] += _static[i];
  }

private:
  std::shared_ptr<dynamics::PrescribedMotion> _mtf;
  Vec _us = nullptr, _now = nullptr, _prev = nullptr;
  std::vector<double> _static;
};
} // namespace

void TransmittingFoundation::check_time_step(dynamics::RayleighDamping damping,
                                             const dynamics::TimeScheme& scheme)
{
  // 2 % above the band's highest frequency (a margin; it is converged to
  // 1e-10); the band takes the mass-proportional damping
  // implicitly and its own stiffness damping b_E explicitly.
  _stable_dt = dynamics::explicit_stable_step(1.02 * _omega,
                                              {damping.a_mass, _b_explicit});
  if (_wave.mtf->band_explicit)
  {
    std::ostringstream line;
    line << "explicit band: stable time step " << _stable_dt
         << " s (Hughes-Liu partition); time.dt = " << scheme.dt << " s";
    results::print(_fe.mesh()->comm(), line.str());
  }
  if (scheme.dt > _stable_dt)
  {
    std::ostringstream m;
    m << "time.dt = " << scheme.dt
      << " s is above the stable step of the transmitting boundary's "
         "explicit band, "
      << _stable_dt
      << " s: a smaller time.dt, a band of larger cells "
         "(foundation.band_size; in dam_model the mesh's band), or "
         "foundation.band_integration = \"implicit\"";
    throw input::InputError(m.str());
  }
  if (scheme.alpha != 0.0 && _wave.mtf->band_explicit)
    throw input::InputError("time.hht_alpha must be 0 with a multi-"
                            "transmitting boundary's explicit band (the "
                            "partition is Newmark's average acceleration)");
}

std::unique_ptr<engine::Stepper>
TransmittingFoundation::stepper(dynamics::RayleighDamping damping,
                                const dynamics::TimeScheme& scheme,
                                linalg::Factorization factorization)
{
  check_time_step(damping, scheme);
  if (scheme.alpha != 0.0)
    throw input::InputError("time.hht_alpha must be 0 with a multi-"
                            "transmitting boundary in the linear engine "
                            "(PartitionedNewmark is average acceleration)");
  return std::make_unique<engine::PartitionedStepper>(
      _M.mat(), _K.mat(), _K_implicit.mat(), damping, scheme.dt, factorization,
      _prescribed, _b_explicit);
}

dynamics::Partition TransmittingFoundation::partition(Vec u_static)
{
  return {_K_implicit.mat(), _K_explicit.mat(),
          std::make_shared<FromStatic>(_prescribed, u_static), _b_explicit};
}

std::unique_ptr<engine::DynamicLoad>
TransmittingFoundation::load(dynamics::RayleighDamping damping, double dt,
                             Vec sustained) const
{
  auto load = std::make_unique<FreeFieldLoad>(_fe, nullptr, _ground, _field,
                                              _M.mat(), _K_implicit.mat(),
                                              damping, dt, _tie, sustained);
  load->add_stiffness_damping(_K_explicit.mat(), _b_explicit);
  return load;
}

nlohmann::json TransmittingFoundation::summary() const
{
  const auto nodes = _mtf->node_counts();
  return {
      {"order", _wave.mtf->order},
      {"drift", _wave.mtf->drift},
      {"band_integration", _wave.mtf->band_explicit ? "explicit" : "implicit"},
      {"band_damping", _wave.mtf->band_damping},
      {"band_stiffness_damping_s", _b_explicit},
      {"spacing_m", _wave.mtf->spacing},
      {"artificial_speeds_m_s", {_wave.rock.cp(), _wave.rock.cs()}},
      {"courant_s", _mtf->settings().courant()},
      {"boundary_nodes", nodes[0]},
      {"bottom_nodes", nodes[1]},
      {"band_highest_frequency_hz", _omega / (2.0 * std::numbers::pi)},
      {"stable_dt_s", _stable_dt}};
}
} // namespace damseis::analysis
