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
  /// Changes the velocity of the last step by dv, with the acceleration
  /// kept consistent with the Newmark velocity update (a += dv / (gamma
  /// dt)) and the displacement unchanged: the impact correction of joint
  /// pairs that close.
  void correct_velocity(Vec dv);
  /// The constraint force r of the last step (zero without constraints).
  Vec constraint_force() const { return _r; }

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
};
} // namespace damseis::dynamics
