#include "newmark.h"
#include <cmath>
#include <damseis/linalg/duplicate_matrix.h>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace damseis::dynamics
{
namespace
{
/// y = A x for a symmetric A and an x with few nonzeros (an impact
/// correction: the closing pairs' nodes): row i of A times x_i, for the
/// owned nonzeros x_i, added into y. Collective; reads a few rows instead
/// of the whole matrix.
void sparse_symmetric_product(Mat A, Vec x, Vec y)
{
  VecSet(y, 0.0);
  PetscInt lo = 0, hi = 0;
  VecGetOwnershipRange(x, &lo, &hi);
  const PetscScalar* a = nullptr;
  VecGetArrayRead(x, &a);
  std::vector<PetscScalar> scaled;
  for (PetscInt i = lo; i < hi; ++i)
  {
    const PetscScalar xi = a[i - lo];
    if (xi == 0.0)
      continue;
    PetscInt ncols = 0;
    const PetscInt* cols = nullptr;
    const PetscScalar* vals = nullptr;
    MatGetRow(A, i, &ncols, &cols, &vals);
    scaled.assign(vals, vals + ncols);
    for (PetscScalar& v : scaled)
      v *= xi;
    VecSetValues(y, ncols, cols, scaled.data(), ADD_VALUES);
    MatRestoreRow(A, i, &ncols, &cols, &vals);
  }
  VecRestoreArrayRead(x, &a);
  VecAssemblyBegin(y);
  VecAssemblyEnd(y);
}
} // namespace

RayleighDamping RayleighDamping::from_ratio(double zeta, double f1_hz,
                                            double f2_hz)
{
  if (!(f1_hz > 0.0 && f2_hz > 0.0) || f1_hz == f2_hz)
  {
    throw std::invalid_argument(
        "Rayleigh damping needs two distinct positive frequencies");
  }
  const double w1 = 2.0 * std::numbers::pi * f1_hz;
  const double w2 = 2.0 * std::numbers::pi * f2_hz;
  return {2.0 * zeta * w1 * w2 / (w1 + w2), 2.0 * zeta / (w1 + w2)};
}

double RayleighDamping::ratio_at(double f_hz) const
{
  const double w = 2.0 * std::numbers::pi * f_hz;
  return 0.5 * (a_mass / w + b_stiffness * w);
}

LinearNewmark::LinearNewmark(Mat M, Mat K, RayleighDamping damping,
                             TimeScheme scheme,
                             linalg::Factorization factorization,
                             const std::vector<Mat>& extra_damping,
                             std::shared_ptr<ConstrainedSolve> constrained)
    : _M(M), _K(K), _damping(damping), _scheme(scheme),
      _constrained(std::move(constrained))
{
  if (!(scheme.dt > 0.0 && std::isfinite(scheme.dt)))
    throw std::invalid_argument("time step must be positive");
  if (!(scheme.alpha >= -1.0 / 3.0 - 1e-14 && scheme.alpha <= 0.0))
    throw std::invalid_argument("HHT alpha must lie in [-1/3, 0]");
  const double dt = scheme.dt, beta = scheme.beta(), gamma = scheme.gamma();
  const double alpha = scheme.alpha;
  const double a0 = 1.0 / (beta * dt * dt), a1 = gamma / (beta * dt);

  // K_eff = a0 M + (1 + alpha)(a1 C + K)
  //       = (a0 + (1 + alpha) a1 a_M) M + (1 + alpha)(1 + a1 b_K) K.
  _cM = a0 + (1.0 + alpha) * a1 * damping.a_mass;
  _cK = (1.0 + alpha) * (1.0 + a1 * damping.b_stiffness);
  _Keff = linalg::duplicate_matrix(K, MAT_COPY_VALUES);
  MatScale(_Keff, _cK);
  MatAXPY(_Keff, _cM, M, SUBSET_NONZERO_PATTERN);
  // Extra damping C_e (summed once): K_eff += (1 + alpha) a1 C_e.
  for (Mat C : extra_damping)
  {
    if (!_Ce)
      _Ce = linalg::duplicate_matrix(C, MAT_COPY_VALUES);
    else
      MatAXPY(_Ce, 1.0, C, DIFFERENT_NONZERO_PATTERN);
  }
  if (_Ce)
  {
    _cC = (1.0 + alpha) * a1;
    MatAXPY(_Keff, _cC, _Ce, DIFFERENT_NONZERO_PATTERN);
  }
  if (_constrained)
    _constrained->factorize(_Keff);
  else
  {
    MPI_Comm comm;
    PetscObjectGetComm(reinterpret_cast<PetscObject>(K), &comm);
    _solver = std::make_unique<linalg::DirectSolver>(comm, factorization);
    _solver->factorize(_Keff);
  }

  for (std::array<Vec, 3>* set : {&_x, &_Mx, &_Kx, &_Cx})
  {
    for (Vec& x : *set)
      MatCreateVecs(K, &x, nullptr);
  }
  for (Vec* x : {&_f, &_rhs, &_u_next, &_image_next, &_r, &_u_old, &_cv_old,
                 &_r_old, &_impulse})
    MatCreateVecs(K, x, nullptr);
  for (std::array<Vec, 3>* set : {&_x, &_Mx, &_Kx, &_Cx})
  {
    for (Vec x : *set)
      VecSet(x, 0.0);
  }
  for (Vec x :
       {_f, _rhs, _u_next, _image_next, _r, _u_old, _cv_old, _r_old, _impulse})
    VecSet(x, 0.0);
}

LinearNewmark::~LinearNewmark()
{
  for (std::array<Vec, 3>* set : {&_x, &_Mx, &_Kx, &_Cx})
  {
    for (Vec& x : *set)
      VecDestroy(&x);
  }
  for (Vec* x : {&_f, &_rhs, &_u_next, &_image_next, &_r, &_u_old, &_cv_old,
                 &_r_old, &_impulse})
    VecDestroy(x);
  MatDestroy(&_Keff);
  MatDestroy(&_Ce);
}

void LinearNewmark::set_state(Vec u, Vec v, Vec a, Vec f)
{
  const std::array<Vec, 3> in = {u, v, a};
  for (int i = 0; i < 3; ++i)
  {
    VecCopy(in[i], _x[i]);
    MatMult(_M, _x[i], _Mx[i]);
    MatMult(_K, _x[i], _Kx[i]);
    if (_Ce)
      MatMult(_Ce, _x[i], _Cx[i]);
  }
  VecCopy(f, _f);
  // The constraint force the state holds: r = M a + C v + K u - f (the
  // static contact forces of a run in total state); none without
  // constraints. (A restart puts back the saved forces: set_forces.)
  if (_constrained)
  {
    damping_force(_r_old);
    VecAXPBYPCZ(_r_old, 1.0, 1.0, 1.0, _Mx[2], _Kx[0]);
    VecAXPY(_r_old, -1.0, _f);
  }
  else
    VecSet(_r_old, 0.0);
  VecCopy(_r_old, _r);
  VecSet(_impulse, 0.0);
  update_energies();
  if (!_energy.started)
  {
    _energy.kinetic0 = _energy.kinetic;
    _energy.strain0 = _energy.strain;
    _energy.started = true;
  }
}

void LinearNewmark::set_forces(Vec r, Vec impulse)
{
  VecCopy(r, _r);
  VecCopy(r, _r_old);
  VecCopy(impulse, _impulse);
}

void LinearNewmark::damping_force(Vec out) const
{
  VecAXPBY(out, _damping.a_mass, 0.0, _Mx[1]);
  VecAXPY(out, _damping.b_stiffness, _Kx[1]);
  if (_Ce)
    VecAXPY(out, 1.0, _Cx[1]);
}

void LinearNewmark::update_energies()
{
  double vMv = 0.0, uKu = 0.0;
  VecDot(_x[1], _Mx[1], &vMv);
  VecDot(_x[0], _Kx[0], &uKu);
  _energy.kinetic = 0.5 * vMv;
  _energy.strain = 0.5 * uKu;
}

namespace
{
/// Newmark update of one (u, v, a) triple to the new u, in one pass:
/// a' = a0 (u' - u) - a2 v - a3 a,  v' = v + dt ((1 - gamma) a + gamma a'),
/// u <- u'.
void advance(std::array<Vec, 3>& x, Vec u_next, double a0, double a2, double a3,
             double dt, double gamma)
{
  PetscInt n = 0;
  VecGetLocalSize(u_next, &n);
  const double* un = nullptr;
  double *u = nullptr, *v = nullptr, *a = nullptr;
  VecGetArrayRead(u_next, &un);
  VecGetArray(x[0], &u);
  VecGetArray(x[1], &v);
  VecGetArray(x[2], &a);
  const double c1 = dt * (1.0 - gamma), c2 = dt * gamma;
  for (PetscInt i = 0; i < n; ++i)
  {
    const double an = a0 * (un[i] - u[i]) - a2 * v[i] - a3 * a[i];
    v[i] += c1 * a[i] + c2 * an;
    a[i] = an;
    u[i] = un[i];
  }
  VecRestoreArray(x[2], &a);
  VecRestoreArray(x[1], &v);
  VecRestoreArray(x[0], &u);
  VecRestoreArrayRead(u_next, &un);
}
} // namespace

void LinearNewmark::step(Vec f_next)
{
  const double dt = _scheme.dt, beta = _scheme.beta(), gamma = _scheme.gamma();
  const double alpha = _scheme.alpha;
  const double a0 = 1.0 / (beta * dt * dt), a1 = gamma / (beta * dt),
               a2 = 1.0 / (beta * dt), a3 = 0.5 / beta - 1.0,
               a4 = gamma / beta - 1.0, a5 = dt * (0.5 * gamma / beta - 1.0);
  const double aM = _damping.a_mass, bK = _damping.b_stiffness;
  // The step's start for the energy balance (r_old: the constraint force
  // of the last step, or of the state set).
  VecCopy(_x[0], _u_old);
  damping_force(_cv_old);

  // HHT: M a' + (1 + alpha)(C v' + K u') - alpha (C v + K u)
  //        = (1 + alpha) f' - alpha f,
  // with a', v' expressed by u' gives K_eff u' = rhs, where
  // rhs = (1 + alpha) f' - alpha f + M (a0 u + a2 v + a3 a)
  //       + (1 + alpha) C (a1 u + a4 v + a5 a) + alpha (C v + K u).
  const double w = 1.0 + alpha;
  const PetscScalar coef[8] = {w,
                               -alpha,
                               a0 + w * a1 * aM,
                               a2 + w * a4 * aM + alpha * aM,
                               a3 + w * a5 * aM,
                               w * a1 * bK + alpha,
                               w * a4 * bK + alpha * bK,
                               w * a5 * bK};
  Vec terms[8] = {f_next, _f, _Mx[0], _Mx[1], _Mx[2], _Kx[0], _Kx[1], _Kx[2]};
  VecSet(_rhs, 0.0);
  VecMAXPY(_rhs, 8, coef, terms);
  if (_Ce)
  {
    // The extra damping's share, C_e in place of a_M M + b_K K above.
    const PetscScalar c[3] = {w * a1, w * a4 + alpha, w * a5};
    Vec cx[3] = {_Cx[0], _Cx[1], _Cx[2]};
    VecMAXPY(_rhs, 3, c, cx);
  }

  if (_constrained)
  {
    // K_eff u' = rhs + r: the constraint force joins the right-hand side
    // from which K u' follows below.
    _constrained->solve(_rhs, _u_next, _r);
    VecAXPY(_rhs, 1.0, _r);
  }
  else
    _solver->solve(_rhs, _u_next);

  // Images of the new displacement: M u' (and C_e u') by a product, K u'
  // from the solved equation (exact up to the solver's residual).
  MatMult(_M, _u_next, _image_next);
  advance(_Mx, _image_next, a0, a2, a3, dt, gamma);
  if (_Ce)
  {
    MatMult(_Ce, _u_next, _image_next);
    advance(_Cx, _image_next, a0, a2, a3, dt, gamma);
  }
  VecWAXPY(_image_next, -_cM, _Mx[0], _rhs);
  if (_Ce)
    VecAXPY(_image_next, -_cC, _Cx[0]);
  VecScale(_image_next, 1.0 / _cK);
  advance(_Kx, _image_next, a0, a2, a3, dt, gamma);
  advance(_x, _u_next, a0, a2, a3, dt, gamma);

  // The energy balance: du times the mean load, damping force and
  // constraint force over the step (trapezoidal rule).
  VecAYPX(_u_old, -1.0, _x[0]); // du
  double work[7] = {};
  damping_force(_image_next);
  const std::array<Vec, 7> forces = {_f,     f_next, _cv_old, _image_next,
                                     _r_old, _r,     _impulse};
  VecMDot(_u_old, 7, forces.data(), work);
  _energy.external_work += 0.5 * (work[0] + work[1]);
  _energy.damping += 0.5 * (work[2] + work[3]);
  _energy.constraint_work += 0.5 * (work[4] + work[5]);
  _energy.impact += 0.5 * work[6];
  VecSet(_impulse, 0.0);
  update_energies();
  VecCopy(_r, _r_old);
  VecCopy(f_next, _f);
}
void LinearNewmark::correct_velocity(Vec dv)
{
  const double before = _energy.kinetic;
  // v += dv, and the images M v, K v, C_e v by products with dv (symmetric
  // matrices, dv nonzero at the closing pairs' nodes only). The
  // acceleration stays: it satisfies the equation of motion, but for the
  // damping force C dv the jump adds (the impulse is M dv, at once). (Making
  // a follow the Newmark update instead, a += dv / (gamma dt), turns the
  // impulse into a force M dv / (gamma dt) over the next step that does
  // work: two bars meeting gained 3x their energy with restitution 0.)
  VecAXPY(_x[1], 1.0, dv);
  const std::array<std::pair<Mat, std::array<Vec, 3>*>, 3> images = {
      std::make_pair(_M, &_Mx), std::make_pair(_K, &_Kx),
      std::make_pair(_Ce, &_Cx)};
  const std::array<double, 3> damping = {_damping.a_mass, _damping.b_stiffness,
                                         1.0};
  for (int i = 0; i < 3; ++i)
  {
    auto [A, x] = images[i];
    if (!A)
      continue;
    sparse_symmetric_product(A, dv, _image_next);
    VecAXPY((*x)[1], 1.0, _image_next);
    VecAXPY(_impulse, damping[i], _image_next);
  }
  update_energies();
  _energy.impact += _energy.kinetic - before;
}

std::string LinearNewmark::solver_name() const
{
  return _constrained ? _constrained->name() : _solver->name();
}

double LinearNewmark::factor_seconds() const
{
  return _constrained ? _constrained->factor_seconds()
                      : _solver->factor_seconds();
}
} // namespace damseis::dynamics
