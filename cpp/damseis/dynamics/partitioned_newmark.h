// The implicit-explicit partition of Newmark's method (Hughes & Liu 1978;
// algorithms.md 3.5) for M a + C v + K u = f(t): the elements of the
// explicit group E (a band next to a transmitting boundary, with lumped
// mass) see only the predictors
//   d~ = d_n + dt v_n + dt^2 (1/2 - beta) a_n,   v~ = v_n + (1 - gamma) dt a_n,
// the implicit group I (the dam and the interior) the new state:
//   (M + gamma dt C + beta dt^2 K_I) a_{n+1} = f_{n+1} - C v~ - K d~,
//   d_{n+1} = d~ + beta dt^2 a_{n+1},  v_{n+1} = v~ + gamma dt a_{n+1},
// K_I the stiffness of the I elements alone, K that of all. The damping
// is C = a_M M + b_K K_I + b_E K_E: the Rayleigh mass-proportional part on
// all elements (diagonal on E, so implicit there too), its stiffness-
// proportional part on the I elements only (explicit on E it would cut
// the stable step by sqrt(1 + xi^2) - xi, xi = b_K omega_max / 2: about 5x
// for 5 % damping of a dam's first modes and a band of 10 m; the band's
// waves leave through the boundary anyway), and the E elements' own
// stiffness-proportional damping b_E K_E on v~ (explicit), a few percent
// of critical at the band's highest frequency: it damps the band's
// shortest waves, with which Liao's formula is unstable in 3D
// (tests/fem/test_mtf_box.cpp), and leaves the seismic band alone. The
// rows of nodes touched by
// E elements alone are diagonal: explicit. Unknowns with a prescribed
// displacement (the transmitting boundary's nodes, E nodes) get
// their given displacement, velocity and acceleration: the predictors
// there are set to d~ = d' - beta dt^2 a', v~ = v' - gamma dt a' and the
// solution to a', so that the updates land on them; where they are
// coupled to others (the band implicit: no E group) their columns' terms
// move to the right-hand side. beta = 1/4, gamma = 1/2.
//
// Stability: the I group is unconditionally stable; the E group needs
// dt <= explicit_stable_step(omega_max of E, {a_M, b_E}) (2 / omega_max
// undamped).
#pragma once

#include "newmark.h"
#include <memory>
#include <petscmat.h>
#include <span>
#include <string>
#include <vector>

namespace damseis::dynamics
{
/// A state's displacement, velocity and acceleration (global vectors).
struct Kinematics
{
  Vec u = nullptr, v = nullptr, a = nullptr;
};

/// The prescribed unknowns' displacement, velocity and acceleration, in
/// the order of PrescribedMotion::rows().
struct PrescribedValues
{
  std::vector<double> u, v, a;
  void resize(std::size_t n)
  {
    for (auto* x : {&u, &v, &a})
      x->assign(n, 0.0);
  }
  /// The predictors from which Newmark's updates over dt land on these
  /// values: d~ = u - beta dt^2 a, v~ = v - gamma dt a.
  void predictors(double beta, double gamma, double dt, std::vector<double>& d,
                  std::vector<double>& v_p) const
  {
    d.resize(u.size());
    v_p.resize(u.size());
    for (std::size_t i = 0; i < u.size(); ++i)
    {
      d[i] = u[i] - beta * dt * dt * a[i];
      v_p[i] = v[i] - gamma * dt * a[i];
    }
  }
};

/// The motion prescribed at some unknowns at every step (the nodes of a
/// transmitting boundary), found from the last two states. The
/// integrators give these unknowns the prescribed displacement, velocity
/// and acceleration all three (their neighbours' equations see them), not
/// the velocity and acceleration Newmark's relations would derive from the
/// displacements alone: with average acceleration those relations carry
/// an undamped alternating mode (for a fixed displacement v_(n+1) = -v_n),
/// whose acceleration grows linearly with the steps.
class PrescribedMotion
{
public:
  virtual ~PrescribedMotion() = default;
  /// The prescribed unknowns this rank owns (global rows).
  virtual const std::vector<PetscInt>& rows() const = 0;
  /// Their motion at step n + 1 (t = (n + 1) dt) from the state at step n
  /// and at step n - 1 (collective).
  virtual void values(int n_next, const Kinematics& now, const Kinematics& prev,
                      PrescribedValues& out) = 0;
};

/// The largest step for which the explicit group of a partition (mass-
/// proportional damping implicit, stiffness-proportional explicit: zero
/// in PartitionedNewmark) is stable up to its highest circular frequency
/// omega_max [rad/s]: the
/// largest dt with spectral radius <= 1 of the one-degree-of-freedom
/// amplification matrix at every omega in (0, omega_max]. Undamped it is
/// 2 / omega_max (gamma = 1/2, beta 0 or 1/4); infinite for omega_max = 0
/// (no explicit group).
double explicit_stable_step(double omega_max, RayleighDamping damping);

/// The highest circular frequency [rad/s] of the explicit group: the
/// square root of the largest lambda of K_E x = lambda D x (K_E = K -
/// K_implicit, the explicit elements' stiffness; D their lumped mass;
/// unknowns with D = 0 or in `excluded`, global rows this rank owns, left
/// out), by SLEPc's Krylov-Schur on S K_E S (S = D^-1/2) to 1e-10, so the
/// same on any partition; 0 without explicit unknowns. Collective.
double highest_explicit_frequency(Mat K, Mat K_implicit, Vec lumped,
                                  const std::vector<PetscInt>& excluded);

/// Where a partition's steps spent their time [s], summed over the steps
/// (this rank's clock).
struct StepSeconds
{
  /// The transmitting boundary: the formula's motion at the prescribed
  /// rows, their predictors and the lifting of their coupled columns.
  double boundary = 0.0;
  /// The effective matrix's solve (the implicit group; the explicit
  /// rows are diagonal in it).
  double solve = 0.0;
  /// The explicit band's own work: its stiffness damping's products
  /// (b_E K_E v~ and its update). Its elastic forces ride in the product
  /// K d~ of all elements, counted in `rest`.
  double band = 0.0;
  /// Everything else: predictors, the products K d~, M v~, K_I v~, the
  /// new state's images, the energy balance.
  double rest = 0.0;
  int steps = 0;
};

class PartitionedNewmark
{
public:
  /// M: consistent on I, lumped on E; K: all elements; K_implicit: the I
  /// elements' (its rows at E-only nodes zero). Fixed dofs as identity
  /// rows of K and K_implicit and zero rows of M with a zero load.
  /// b_explicit: b_E [s]. The matrices must outlive the integrator.
  PartitionedNewmark(Mat M, Mat K, Mat K_implicit, RayleighDamping damping,
                     double dt, linalg::Factorization factorization,
                     std::shared_ptr<PrescribedMotion> prescribed = nullptr,
                     double b_explicit = 0.0);
  ~PartitionedNewmark();
  PartitionedNewmark(const PartitionedNewmark&) = delete;
  PartitionedNewmark& operator=(const PartitionedNewmark&) = delete;

  /// The state at the current step n (copied): u, v, a, the load f, the
  /// state of step n - 1 (null members: step n's), and the step number n.
  void set_state(Vec u, Vec v, Vec a, Vec f, const Kinematics& prev, int n);
  /// Advances one step to the load f_next = f(t + dt).
  void step(Vec f_next);

  Vec u() const { return _u; }
  Vec v() const { return _v; }
  Vec a() const { return _a; }
  /// The state one step back (the transmitting boundary's history).
  Kinematics prev() const { return {_u_prev, _v_prev, _a_prev}; }
  /// The energy balance since the start; constraint_work is the work of
  /// the prescribed unknowns' reactions (the energy the boundary let in,
  /// negative where it radiates energy out).
  const EnergyBalance& energy() const { return _energy; }
  void set_energy(const EnergyBalance& e) { _energy = e; }
  std::string solver_name() const { return _solver->name(); }
  double factor_seconds() const { return _solver->factor_seconds(); }
  /// The steps' time, split by part.
  const StepSeconds& step_seconds() const { return _seconds; }

private:
  /// M x, K x and the reaction at the prescribed rows for the state.
  void update_images();
  /// d~ = d' - beta dt^2 a', v~ = v' - gamma dt a' at the prescribed rows.
  void set_prescribed_predictors();
  void update_energies();

  Mat _M, _K, _K_implicit;
  RayleighDamping _damping;
  double _b_explicit; ///< b_E: stiffness damping of the E elements [s]
  double _dt;
  static constexpr double _beta = 0.25, _gamma = 0.5;
  Mat _A = nullptr; ///< the effective matrix (prescribed rows identity)
  /// A before its prescribed rows and columns were zeroed, where they are
  /// coupled to others (null: none are).
  Mat _A_lift = nullptr;
  std::unique_ptr<linalg::DirectSolver> _solver;
  std::shared_ptr<PrescribedMotion> _prescribed;
  PrescribedValues _values;
  int _n = 0;
  Vec _u = nullptr, _v = nullptr, _a = nullptr, _f = nullptr;
  Vec _u_prev = nullptr, _v_prev = nullptr, _a_prev = nullptr;
  /// Work: predictors, right-hand side, images M v, K u, M a, K_I v,
  /// K_E v.
  Vec _d_p = nullptr, _v_p = nullptr, _rhs = nullptr, _Mv = nullptr,
      _Ku = nullptr, _Ma = nullptr, _Kv = nullptr, _Kev = nullptr, _w = nullptr;
  /// The state's damping force C v and reaction r (prescribed rows).
  Vec _cv = nullptr, _r = nullptr, _du = nullptr;
  Vec _mask = nullptr; ///< 1 at the prescribed rows
  EnergyBalance _energy;
  StepSeconds _seconds;
};
} // namespace damseis::dynamics
