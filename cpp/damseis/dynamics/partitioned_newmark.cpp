#include "partitioned_newmark.h"
#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <damseis/linalg/duplicate_matrix.h>
#include <damseis/linalg/initialize_slepc.h>
#include <limits>
#include <slepceps.h>
#include <stdexcept>

namespace damseis::dynamics
{
namespace
{
using Clock = std::chrono::steady_clock;

/// Adds the time since `t0` to `total` and restarts `t0`.
void lap(Clock::time_point& t0, double& total)
{
  const Clock::time_point now = Clock::now();
  total += std::chrono::duration<double>(now - t0).count();
  t0 = now;
}

/// Spectral radius of one step of the partition's explicit group for one
/// degree of freedom of circular frequency omega (unit mass): a_M
/// implicit, b_K omega^2 explicit.
double spectral_radius(double omega, double dt, RayleighDamping c)
{
  const double beta = 0.25, gamma = 0.5;
  const double w2 = omega * omega;
  Eigen::Matrix3d step;
  for (int j = 0; j < 3; ++j)
  {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    x[j] = 1.0;
    const double d = x[0] + dt * x[1] + dt * dt * (0.5 - beta) * x[2];
    const double v = x[1] + (1.0 - gamma) * dt * x[2];
    const double a = (-(c.a_mass + c.b_stiffness * w2) * v - w2 * d) /
                     (1.0 + gamma * dt * c.a_mass);
    step.col(j) << d + beta * dt * dt * a, v + gamma * dt * a, a;
  }
  return step.eigenvalues().cwiseAbs().maxCoeff();
}

/// Whether every frequency up to omega_max is stable at dt (the
/// tolerance above 1 covers the eigenvalues' round-off where two of them
/// meet on the unit circle, of order sqrt(machine epsilon)).
bool stable(double omega_max, double dt, RayleighDamping c)
{
  const int samples = 200;
  for (int i = 1; i <= samples; ++i)
    if (spectral_radius(omega_max * i / samples, dt, c) > 1.0 + 1e-6)
      return false;
  return true;
}
} // namespace

double explicit_stable_step(double omega_max, RayleighDamping damping)
{
  if (omega_max == 0.0) // no explicit group
    return std::numeric_limits<double>::infinity();
  if (!(omega_max > 0.0 && std::isfinite(omega_max)))
    throw std::invalid_argument("explicit_stable_step: omega_max must be "
                                "positive");
  // Bisection between a stable step and an unstable one (undamped 2 /
  // omega_max is the limit; damping lowers it).
  double lo = 0.0, hi = 2.5 / omega_max;
  while (stable(omega_max, hi, damping))
    hi *= 2.0;
  for (int i = 0; i < 60; ++i)
  {
    const double mid = 0.5 * (lo + hi);
    (stable(omega_max, mid, damping) ? lo : hi) = mid;
  }
  return lo;
}

namespace
{
/// The symmetric band operator S K_E S (S = mask / sqrt(D)) of
/// highest_explicit_frequency, applied without forming it.
struct BandOperator
{
  Mat K, K_implicit;
  Vec scale, work, work_implicit;
};

PetscErrorCode band_operator_mult(Mat A, Vec x, Vec y)
{
  BandOperator* op = nullptr;
  MatShellGetContext(A, &op);
  VecPointwiseMult(op->work, x, op->scale);
  MatMult(op->K, op->work, y);
  MatMult(op->K_implicit, op->work, op->work_implicit);
  VecAXPY(y, -1.0, op->work_implicit);
  VecPointwiseMult(y, y, op->scale);
  return 0;
}
} // namespace

double highest_explicit_frequency(Mat K, Mat K_implicit, Vec lumped,
                                  const std::vector<PetscInt>& excluded)
{
  linalg::initialize_slepc();
  // S = 1 / sqrt(D) on the explicit unknowns (D > 0, not excluded), else 0:
  // K_E x = lambda D x and S K_E S z = lambda z (x = S z) share lambda.
  BandOperator op{K, K_implicit, nullptr, nullptr, nullptr};
  VecDuplicate(lumped, &op.scale);
  VecDuplicate(lumped, &op.work);
  VecDuplicate(lumped, &op.work_implicit);
  PetscInt lo = 0, hi = 0;
  VecGetOwnershipRange(lumped, &lo, &hi);
  {
    const double* d = nullptr;
    double* s = nullptr;
    VecGetArrayRead(lumped, &d);
    VecGetArray(op.scale, &s);
    for (PetscInt i = 0; i < hi - lo; ++i)
      s[i] = d[i] > 0.0 ? 1.0 / std::sqrt(d[i]) : 0.0;
    for (PetscInt row : excluded)
      s[row - lo] = 0.0;
    VecRestoreArray(op.scale, &s);
    VecRestoreArrayRead(lumped, &d);
  }
  double largest_scale = 0.0;
  VecMax(op.scale, nullptr, &largest_scale);
  MPI_Comm comm;
  PetscObjectGetComm(reinterpret_cast<PetscObject>(lumped), &comm);
  double lambda = 0.0;
  PetscInt converged = 1;  // without explicit unknowns lambda = 0 stands
  if (largest_scale > 0.0) // else no explicit unknown limits the step
  {
    // The largest eigenvalue by Krylov-Schur to 1e-10: converged, so the
    // same on any partition (a power iteration stopped at a small change
    // depended on its start vector, i.e. on the dof numbering).
    Mat A;
    MatCreateShell(comm, hi - lo, hi - lo, PETSC_DETERMINE, PETSC_DETERMINE,
                   &op, &A);
    MatShellSetOperation(A, MATOP_MULT,
                         reinterpret_cast<void (*)(void)>(band_operator_mult));
    MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE);
    EPS eps;
    EPSCreate(comm, &eps);
    EPSSetOperators(eps, A, nullptr);
    EPSSetProblemType(eps, EPS_HEP);
    EPSSetType(eps, EPSKRYLOVSCHUR);
    EPSSetWhichEigenpairs(eps, EPS_LARGEST_REAL);
    EPSSetDimensions(eps, 1, PETSC_DEFAULT, PETSC_DEFAULT);
    EPSSetTolerances(eps, 1e-10, 10000);
    EPSSolve(eps);
    EPSGetConverged(eps, &converged);
    if (converged > 0)
    {
      double imaginary = 0.0;
      EPSGetEigenvalue(eps, 0, &lambda, &imaginary);
    }
    EPSDestroy(&eps);
    MatDestroy(&A);
  }
  for (Vec* v : {&op.scale, &op.work, &op.work_implicit})
    VecDestroy(v);
  if (converged < 1)
    throw std::runtime_error(
        "the explicit band's highest frequency did not converge");
  return std::sqrt(std::max(lambda, 0.0));
}

PartitionedNewmark::PartitionedNewmark(
    Mat M, Mat K, Mat K_implicit, RayleighDamping damping, double dt,
    linalg::Factorization factorization,
    std::shared_ptr<PrescribedMotion> prescribed, double b_explicit)
    : _M(M), _K(K), _K_implicit(K_implicit), _damping(damping),
      _b_explicit(b_explicit), _dt(dt), _prescribed(std::move(prescribed))
{
  if (!(dt > 0.0 && std::isfinite(dt)))
    throw std::invalid_argument("time step must be positive");
  if (!(b_explicit >= 0.0 && std::isfinite(b_explicit)))
    throw std::invalid_argument("the explicit elements' stiffness damping "
                                "must be at least 0");
  // A = (1 + gamma dt a_M) M + (gamma dt b_K + beta dt^2) K_I, the
  // prescribed rows identity.
  _A = linalg::duplicate_matrix(K_implicit, MAT_COPY_VALUES);
  MatScale(_A, _gamma * dt * damping.b_stiffness + _beta * dt * dt);
  MatAXPY(_A, 1.0 + _gamma * dt * damping.a_mass, M, DIFFERENT_NONZERO_PATTERN);
  const std::vector<PetscInt> none;
  const std::vector<PetscInt>& rows = _prescribed ? _prescribed->rows() : none;
  // Prescribed rows of explicit (E-only) nodes are diagonal: their columns
  // are zero too and identity rows keep A symmetric. Coupled ones (an
  // implicit band) have their columns moved to the right-hand side.
  int coupled = 0;
  for (PetscInt row : rows)
  {
    PetscInt n = 0;
    const PetscInt* cols = nullptr;
    const PetscScalar* vals = nullptr;
    MatGetRow(_A, row, &n, &cols, &vals);
    for (PetscInt j = 0; j < n; ++j)
      coupled = coupled || (cols[j] != row && vals[j] != 0.0);
    MatRestoreRow(_A, row, &n, &cols, &vals);
  }
  MPI_Comm comm;
  PetscObjectGetComm(reinterpret_cast<PetscObject>(K), &comm);
  MPI_Allreduce(MPI_IN_PLACE, &coupled, 1, MPI_INT, MPI_MAX, comm);
  if (coupled)
  {
    _A_lift = linalg::duplicate_matrix(_A, MAT_COPY_VALUES);
    MatZeroRowsColumns(_A, static_cast<PetscInt>(rows.size()), rows.data(), 1.0,
                       nullptr, nullptr);
  }
  else
    MatZeroRows(_A, static_cast<PetscInt>(rows.size()), rows.data(), 1.0,
                nullptr, nullptr);
  _values.resize(rows.size());
  _solver = std::make_unique<linalg::DirectSolver>(comm, factorization);
  _solver->factorize(_A);

  for (Vec* x : {&_u,   &_v,   &_a,   &_f,  &_u_prev, &_v_prev, &_a_prev,
                 &_d_p, &_v_p, &_rhs, &_Mv, &_Ku,     &_Ma,     &_Kv,
                 &_Kev, &_w,   &_cv,  &_r,  &_du,     &_mask})
  {
    MatCreateVecs(K, x, nullptr);
    VecSet(*x, 0.0);
  }
  std::vector<PetscScalar> ones(rows.size(), 1.0);
  VecSetValues(_mask, static_cast<PetscInt>(rows.size()), rows.data(),
               ones.data(), INSERT_VALUES);
  VecAssemblyBegin(_mask);
  VecAssemblyEnd(_mask);
}

PartitionedNewmark::~PartitionedNewmark()
{
  for (Vec* x : {&_u,   &_v,   &_a,   &_f,  &_u_prev, &_v_prev, &_a_prev,
                 &_d_p, &_v_p, &_rhs, &_Mv, &_Ku,     &_Ma,     &_Kv,
                 &_Kev, &_w,   &_cv,  &_r,  &_du,     &_mask})
    VecDestroy(x);
  MatDestroy(&_A);
  MatDestroy(&_A_lift);
}

void PartitionedNewmark::set_state(Vec u, Vec v, Vec a, Vec f,
                                   const Kinematics& prev, int n)
{
  VecCopy(u, _u);
  VecCopy(v, _v);
  VecCopy(a, _a);
  VecCopy(f, _f);
  VecCopy(prev.u ? prev.u : u, _u_prev);
  VecCopy(prev.v ? prev.v : v, _v_prev);
  VecCopy(prev.a ? prev.a : a, _a_prev);
  _n = n;
  MatMult(_M, _v, _Mv);
  MatMult(_K_implicit, _v, _Kv);
  if (_b_explicit > 0.0)
  {
    MatMult(_K, _v, _Kev);
    VecAXPY(_Kev, -1.0, _Kv);
  }
  MatMult(_K, _u, _Ku);
  MatMult(_M, _a, _Ma);
  update_images();
  update_energies();
  if (!_energy.started)
  {
    _energy.kinetic0 = _energy.kinetic;
    _energy.strain0 = _energy.strain;
    _energy.started = true;
  }
}

void PartitionedNewmark::update_images()
{
  // C v and the prescribed rows' reaction r = M a + C v + K u - f.
  VecAXPBYPCZ(_cv, _damping.a_mass, _damping.b_stiffness, 0.0, _Mv, _Kv);
  VecAXPY(_cv, _b_explicit, _Kev);
  VecWAXPY(_r, 1.0, _Ma, _cv);
  VecAXPBYPCZ(_r, 1.0, -1.0, 1.0, _Ku, _f);
  VecPointwiseMult(_r, _r, _mask);
}

void PartitionedNewmark::update_energies()
{
  double vMv = 0.0, uKu = 0.0;
  VecDot(_v, _Mv, &vMv);
  VecDot(_u, _Ku, &uKu);
  _energy.kinetic = 0.5 * vMv;
  _energy.strain = 0.5 * uKu;
}

void PartitionedNewmark::set_prescribed_predictors()
{
  const std::vector<PetscInt>& rows = _prescribed->rows();
  const auto n = static_cast<PetscInt>(rows.size());
  std::vector<double> d, v;
  _values.predictors(_beta, _gamma, _dt, d, v);
  VecSetValues(_d_p, n, rows.data(), d.data(), INSERT_VALUES);
  VecSetValues(_v_p, n, rows.data(), v.data(), INSERT_VALUES);
  for (Vec x : {_d_p, _v_p})
  {
    VecAssemblyBegin(x);
    VecAssemblyEnd(x);
  }
}

void PartitionedNewmark::step(Vec f_next)
{
  const double dt = _dt, bdt2 = _beta * dt * dt, gdt = _gamma * dt;
  Clock::time_point t0 = Clock::now();
  // The prescribed motion at n + 1 from steps n and n - 1.
  if (_prescribed)
    _prescribed->values(_n + 1, {_u, _v, _a}, prev(), _values);
  lap(t0, _seconds.boundary);
  // The predictors; at the prescribed rows those the updates take to the
  // prescribed motion.
  VecWAXPY(_d_p, dt, _v, _u);
  VecAXPY(_d_p, (0.5 - _beta) * dt * dt, _a);
  VecWAXPY(_v_p, (1.0 - _gamma) * dt, _a, _v);
  lap(t0, _seconds.rest);
  if (_prescribed)
    set_prescribed_predictors();
  lap(t0, _seconds.boundary);
  VecCopy(_u, _u_prev);
  VecCopy(_v, _v_prev);
  VecCopy(_a, _a_prev);
  VecCopy(_u, _du); // the step's start, for the energy balance

  // rhs = f' - a_M M v~ - b_K K_I v~ - b_E K_E v~ - K d~ (M v~, K_I v~,
  // K_E v~, K d~ kept: the new images follow from them).
  MatMult(_M, _v_p, _Mv);
  MatMult(_K_implicit, _v_p, _Kv);
  MatMult(_K, _d_p, _Ku);
  VecWAXPY(_rhs, -_damping.a_mass, _Mv, f_next);
  VecAXPBYPCZ(_rhs, -_damping.b_stiffness, -1.0, 1.0, _Kv, _Ku);
  lap(t0, _seconds.rest);
  if (_b_explicit > 0.0)
  {
    MatMult(_K, _v_p, _Kev);
    VecAXPY(_Kev, -1.0, _Kv);
    VecAXPY(_rhs, -_b_explicit, _Kev);
  }
  lap(t0, _seconds.band);
  if (_prescribed)
  {
    const std::vector<PetscInt>& rows = _prescribed->rows();
    const std::vector<double>& b = _values.a;
    if (_A_lift)
    {
      // rhs -= A x, x the prescribed accelerations (zero elsewhere).
      VecSet(_w, 0.0);
      VecSetValues(_w, static_cast<PetscInt>(rows.size()), rows.data(),
                   b.data(), INSERT_VALUES);
      VecAssemblyBegin(_w);
      VecAssemblyEnd(_w);
      MatMult(_A_lift, _w, _Ma);
      VecAXPY(_rhs, -1.0, _Ma);
    }
    VecSetValues(_rhs, static_cast<PetscInt>(rows.size()), rows.data(),
                 b.data(), INSERT_VALUES);
    VecAssemblyBegin(_rhs);
    VecAssemblyEnd(_rhs);
  }
  lap(t0, _seconds.boundary);
  _solver->solve(_rhs, _a);
  lap(t0, _seconds.solve);

  // The new state and its images: M a', K a' by products, the rest by the
  // same updates as the state.
  VecWAXPY(_u, bdt2, _a, _d_p);
  VecWAXPY(_v, gdt, _a, _v_p);
  MatMult(_M, _a, _Ma);
  MatMult(_K, _a, _w);
  VecAXPY(_Ku, bdt2, _w);
  lap(t0, _seconds.rest);
  if (_b_explicit > 0.0)
    VecAXPY(_Kev, gdt, _w);
  lap(t0, _seconds.band);
  MatMult(_K_implicit, _a, _w);
  VecAXPY(_Mv, gdt, _Ma);
  VecAXPY(_Kv, gdt, _w);
  lap(t0, _seconds.rest);
  if (_b_explicit > 0.0)
    VecAXPY(_Kev, -gdt, _w);
  lap(t0, _seconds.band);
  ++_n;

  // The energy balance: du times the mean load, damping force and
  // reaction over the step (trapezoidal rule); the step's start's
  // forces (C v_n, r_n, f_n) first, then the new state's.
  VecAYPX(_du, -1.0, _u);
  const Vec old[3] = {_f, _cv, _r};
  double w_old[3] = {}, w_new[3] = {};
  VecMDot(_du, 3, old, w_old);
  VecCopy(f_next, _f);
  update_images();
  VecMDot(_du, 3, old, w_new);
  _energy.external_work += 0.5 * (w_old[0] + w_new[0]);
  _energy.damping += 0.5 * (w_old[1] + w_new[1]);
  _energy.constraint_work += 0.5 * (w_old[2] + w_new[2]);
  update_energies();
  lap(t0, _seconds.rest);
  ++_seconds.steps;
}
} // namespace damseis::dynamics
