#include "newmark.h"
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace damseis::dynamics
{
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
                             fem::Factorization factorization)
    : _M(M), _K(K), _damping(damping), _scheme(scheme)
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
  MatDuplicate(K, MAT_COPY_VALUES, &_Keff);
  MatScale(_Keff, (1.0 + alpha) * (1.0 + a1 * damping.b_stiffness));
  MatAXPY(_Keff, a0 + (1.0 + alpha) * a1 * damping.a_mass, M,
          SUBSET_NONZERO_PATTERN);
  MPI_Comm comm;
  PetscObjectGetComm(reinterpret_cast<PetscObject>(K), &comm);
  _solver = std::make_unique<fem::DirectSolver>(comm, factorization);
  _solver->factorize(_Keff);

  for (Vec* x : {&_u, &_v, &_a, &_f, &_x1, &_x2, &_w, &_rhs, &_u_next})
    MatCreateVecs(K, x, nullptr);
  for (Vec x : {_u, _v, _a, _f, _x1, _x2, _w, _rhs, _u_next})
    VecSet(x, 0.0); // the AXPBYPCZ updates below read their target
}

LinearNewmark::~LinearNewmark()
{
  for (Vec* x : {&_u, &_v, &_a, &_f, &_x1, &_x2, &_w, &_rhs, &_u_next})
    VecDestroy(x);
  MatDestroy(&_Keff);
}

void LinearNewmark::set_state(Vec u, Vec v, Vec a, Vec f)
{
  VecCopy(u, _u);
  VecCopy(v, _v);
  VecCopy(a, _a);
  VecCopy(f, _f);
}

void LinearNewmark::step(Vec f_next)
{
  const double dt = _scheme.dt, beta = _scheme.beta(), gamma = _scheme.gamma();
  const double alpha = _scheme.alpha;
  const double a0 = 1.0 / (beta * dt * dt), a1 = gamma / (beta * dt),
               a2 = 1.0 / (beta * dt), a3 = 0.5 / beta - 1.0,
               a4 = gamma / beta - 1.0, a5 = dt * (0.5 * gamma / beta - 1.0);
  const double aM = _damping.a_mass, bK = _damping.b_stiffness;

  // w = a1 u + a4 v + a5 a (velocity-like part of the damping term)
  VecAXPBYPCZ(_w, a1, a4, 0.0, _u, _v);
  VecAXPY(_w, a5, _a);
  // x1 = a0 u + a2 v + a3 a + (1 + alpha) a_M w + alpha a_M v
  VecAXPBYPCZ(_x1, a0, a2, 0.0, _u, _v);
  VecAXPBYPCZ(_x1, a3, (1.0 + alpha) * aM, 1.0, _a, _w);
  VecAXPY(_x1, alpha * aM, _v);
  // x2 = (1 + alpha) b_K w + alpha b_K v + alpha u
  VecAXPBYPCZ(_x2, (1.0 + alpha) * bK, alpha * bK, 0.0, _w, _v);
  VecAXPY(_x2, alpha, _u);
  // rhs = (1 + alpha) f_{n+1} - alpha f_n + M x1 + K x2
  MatMult(_M, _x1, _rhs);
  MatMultAdd(_K, _x2, _rhs, _rhs);
  VecAXPBYPCZ(_rhs, 1.0 + alpha, -alpha, 1.0, f_next, _f);

  _solver->solve(_rhs, _u_next);

  // a_{n+1} = a0 (u_{n+1} - u_n) - a2 v_n - a3 a_n  (stored in _w)
  VecWAXPY(_w, -1.0, _u, _u_next);
  VecScale(_w, a0);
  VecAXPBYPCZ(_w, -a2, -a3, 1.0, _v, _a);
  // v_{n+1} = v_n + dt ((1 - gamma) a_n + gamma a_{n+1})
  VecAXPBYPCZ(_v, dt * (1.0 - gamma), dt * gamma, 1.0, _a, _w);
  std::swap(_a, _w);
  std::swap(_u, _u_next);
  VecCopy(f_next, _f);
}
} // namespace damseis::dynamics
