// Implicit time integration of linear structural dynamics,
//   M a + C v + K u = f(t),   C = a_M M + b_K K (Rayleigh) + C_e,
// by the HHT-alpha method (alpha = 0: Newmark average acceleration). The
// effective matrix is factorised once and reused at every step.
#pragma once

#include <array>
#include <damseis/linalg/direct_solver.h>
#include <memory>
#include <petscmat.h>
#include <string>
#include <vector>

namespace damseis::dynamics
{
/// Rayleigh damping C = a_mass M + b_stiffness K.
struct RayleighDamping
{
  double a_mass = 0.0;      ///< [1/s]
  double b_stiffness = 0.0; ///< [s]
  /// Damping ratio `zeta` at the two frequencies f1, f2 [Hz] (f1 != f2).
  static RayleighDamping from_ratio(double zeta, double f1_hz, double f2_hz);
  /// Damping ratio this damping gives at frequency f [Hz].
  double ratio_at(double f_hz) const;
};

/// HHT-alpha parameters; alpha in [-1/3, 0].
struct TimeScheme
{
  double dt = 0.01;   ///< time step [s]
  double alpha = 0.0; ///< 0: Newmark average acceleration (beta 1/4, gamma 1/2)
  double beta() const { return 0.25 * (1.0 - alpha) * (1.0 - alpha); }
  double gamma() const { return 0.5 - alpha; }
};

/// A solve of the effective system whose constraints add a force: finds u
/// and r with K_eff u = rhs + r (the contact of joint pairs: r = G p). It
/// replaces the integrator's own factorisation of K_eff.
class ConstrainedSolve
{
public:
  virtual ~ConstrainedSolve() = default;
  /// Factorises K_eff (collective; K_eff outlives the use).
  virtual void factorize(Mat K_eff) = 0;
  /// u and the constraint force r (collective); throws StepFailure
  /// (nonlinear_newmark.h) if the constraints cannot be solved.
  virtual void solve(Vec rhs, Vec u, Vec r) = 0;
  virtual std::string name() const = 0;
  virtual double factor_seconds() const = 0;
};

/// The energy balance of a run since its start [J] (the relative
/// formulation's energies where the load is the base acceleration's; Uang
/// and Bertero 1990): kinetic 1/2 v.Mv and strain 1/2 u.Ku now and at the
/// start; summed over the steps with the trapezoidal rule, the work of the
/// loads (du.(f_n + f_n+1)/2), the energy dissipated by damping
/// (du.(Cv_n + Cv_n+1)/2), the work of the constraint forces (joint
/// contact: du.(r_n + r_n+1)/2, negative where friction and impacts
/// dissipate), and the energy the impact corrections changed (the kinetic
/// energy at once, and in the next step the work of the damping force the
/// velocity jump leaves out of balance). The
/// balance error is zero to round-off for Newmark's average acceleration
/// (alpha = 0: du = dt (v_n + v_n+1)/2 and du.M(a_n + a_n+1)/2 is the
/// change of kinetic energy); HHT's alpha < 0 makes it negative, the energy
/// its damping of the high frequencies removed.
struct EnergyBalance
{
  double kinetic = 0.0, strain = 0.0;
  double kinetic0 = 0.0, strain0 = 0.0;
  double external_work = 0.0, damping = 0.0, constraint_work = 0.0;
  double impact = 0.0;
  bool started = false;
  /// Energy now less energy in: the start's, the loads', the
  /// constraints' and the impacts' (positive: energy created).
  double error() const
  {
    return kinetic + strain - kinetic0 - strain0 + damping - external_work -
           constraint_work - impact;
  }
};

/// The integrator. State vectors have the layout of K's columns.
///
/// Besides (u, v, a) it carries their images M u, M v, M a and K u, K v,
/// K a (and C_e u, ... with extra damping), which obey the same Newmark
/// recurrences. A step then costs one triangular solve and one product with
/// M (and one with C_e): K u_{n+1} follows from the solved equation,
/// K_eff u_{n+1} = rhs with K_eff = c_M M + c_K K + c_C C_e.
class LinearNewmark
{
public:
  /// M and K must stay alive while the integrator is used. Fixed dofs are
  /// expected as identity rows of K and zero rows of M with a zero load.
  /// `extra_damping`: damping matrices added to the Rayleigh damping (such
  /// as boundary dashpots), with the layout of K; they are copied (summed)
  /// here. `constrained`: a solve with constraint forces in place of the
  /// plain factorisation of K_eff (kept alive by the integrator).
  LinearNewmark(
      Mat M, Mat K, RayleighDamping damping, TimeScheme scheme,
      linalg::Factorization factorization = linalg::Factorization::automatic,
      const std::vector<Mat>& extra_damping = {},
      std::shared_ptr<ConstrainedSolve> constrained = nullptr);
  ~LinearNewmark();
  LinearNewmark(const LinearNewmark&) = delete;
  LinearNewmark& operator=(const LinearNewmark&) = delete;

  /// Sets the state at the current time: displacement, velocity,
  /// acceleration and load (all copied).
  void set_state(Vec u, Vec v, Vec a, Vec f);
  /// Advances one step to the load f_next = f(t + dt).
  void step(Vec f_next);
  /// Changes the velocity of the last step by dv (an impulse M dv), the
  /// displacement and the acceleration unchanged (the acceleration still
  /// satisfies the equation of motion but for the damping force C dv, which
  /// the energy balance counts): the impact correction of joint pairs that
  /// close.
  void correct_velocity(Vec dv);
  /// The constraint force r of the last step (zero without constraints).
  Vec constraint_force() const { return _r; }
  /// The energy balance since the start (every rank).
  const EnergyBalance& energy() const { return _energy; }
  /// Takes the sums of a checkpoint (before set_state on restart).
  void set_energy(const EnergyBalance& e) { _energy = e; }
  /// The damping force a velocity correction left out of balance (C dv),
  /// for the next step's energy balance.
  Vec impulse() const { return _impulse; }
  /// Puts back the constraint force and the impulse of a checkpoint
  /// (after set_state on restart; the HHT-weighted force of the last step
  /// is not the state's residual).
  void set_forces(Vec r, Vec impulse);

  Vec u() const { return _x[0]; }
  Vec v() const { return _x[1]; }
  Vec a() const { return _x[2]; }
  const TimeScheme& scheme() const { return _scheme; }
  /// The factorisation in use and its wall time [s].
  std::string solver_name() const;
  double factor_seconds() const;

private:
  Mat _M, _K;
  Mat _Ce = nullptr; ///< sum of the extra damping matrices (owned), or null
  RayleighDamping _damping;
  TimeScheme _scheme;
  double _cM = 0.0, _cK = 0.0, _cC = 0.0; ///< K_eff = c_M M + c_K K + c_C C_e
  Mat _Keff = nullptr;
  std::unique_ptr<linalg::DirectSolver> _solver; ///< without constraints
  std::shared_ptr<ConstrainedSolve> _constrained;
  /// (u, v, a), their M images and K images; f is the current load.
  std::array<Vec, 3> _x{}, _Mx{}, _Kx{}, _Cx{};
  Vec _f = nullptr, _rhs = nullptr, _u_next = nullptr, _image_next = nullptr;
  Vec _r = nullptr; ///< the constraint force of the last step
  /// The energy balance; the last step's start: u, C v and the
  /// constraint force.
  EnergyBalance _energy;
  Vec _u_old = nullptr, _cv_old = nullptr, _r_old = nullptr;
  /// C dv of the last velocity correction: the force out of balance
  /// in the equation of motion at the next step's start.
  Vec _impulse = nullptr;
  /// C v of the current state (from the images) into `out`.
  void damping_force(Vec out) const;
  /// Kinetic and strain energy of the current state.
  void update_energies();
};
} // namespace damseis::dynamics
