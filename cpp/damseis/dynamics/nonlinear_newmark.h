// Implicit time integration of nonlinear structural dynamics,
//   M a + C v + f_int(u) = f(t),   C = a_M M + b_K K0 (Rayleigh, initial K0)
//   + C_e (boundary dashpots),
// by the HHT-alpha method with a Newton iteration per step (algorithms.md
// 6.1-6.2), and the quasi-static solution of f_int(u) = F in load
// increments (the static stage, 6.4).
//
// Matrix strategy: the initial (elastic) effective matrix J0 is factorised
// once. While every material point of the trial is elastic, J0 is the exact
// Jacobian and gives the direction. Otherwise the consistent matrix
// J = J0 + w (K_T - K0) is built (the change only where the tangent is not
// elastic) and J du = R solved by GMRES preconditioned with factors already
// made (J0, or a tangent factorised earlier in the step); J is factorised
// only when GMRES would need too many iterations (TangentSolver). A step
// that does not converge is cut in halves (recursively); a step that cannot
// be solved even then throws StepFailure: an unconverged step is never
// accepted.
#pragma once

#include "newmark.h"
#include "newton_constraint.h"
#include "partitioned_newmark.h"
#include "tangent_solver.h"
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>

namespace damseis::dynamics
{
/// Newton settings (algorithms.md 6.1: ||R|| <= 1e-6 ||F||).
struct NewtonSettings
{
  double rtol = 1e-6;      ///< ||R|| <= rtol * ||F_ext||
  int max_iterations = 30; ///< per (sub)step
  /// Give up a (sub)step (and cut it) when the residual has not halved in
  /// this many iterations.
  int stagnation_iterations = 5;
  int max_cuts = 6; ///< halvings of a step (dt / 64)
  /// GMRES tolerance for the Newton direction, relative to ||R|| (an
  /// inexact Newton method: the residual falls by about this factor per
  /// iteration where the tangent is accurate).
  double krylov_rtol = 1e-2;
  /// GMRES iterations before the tangent is factorised instead; 0: always
  /// factorise (exact Newton).
  int krylov_max_iterations = 60;
  /// Start each step's Newton iteration from the IMPL-EX solution of the
  /// step (one solve with the factorised initial matrix, stresses
  /// extrapolated with the last plastic increment) instead of the last
  /// displacement, where the system can extrapolate.
  bool extrapolated_predictor = false;
  /// Called after every residual evaluation of an accepted iterate with the
  /// iteration number and ||R|| / ||F_ext|| (tests, logging).
  std::function<void(int, double)> monitor;
};

/// The nonlinear part of the model, seen by the integrator.
class NonlinearSystem
{
public:
  virtual ~NonlinearSystem() = default;
  /// Material update at the trial displacement u reached from the committed
  /// state over dt (0: a static step). False if a material point failed.
  virtual bool trial(Vec u, double dt) = 0;
  /// Internal force of the last trial (layout of K0's columns, zero at
  /// fixed dofs).
  virtual void internal_force(Vec f) = 0;
  /// Adds scale (K_T - K0) of the last trial to A (assembled, the pattern
  /// of K0; nothing at fixed rows and columns) and finishes the assembly:
  /// every Jacobian is a matrix of K0's pattern plus this change, which is
  /// nonzero only where the tangent is not elastic.
  virtual void add_tangent_change(Mat A, double scale) = 0;
  /// The last trial becomes the committed state. False if that fails (an
  /// IMPL-EX state update at a point): the committed state is unchanged
  /// and the step is cut.
  virtual bool accept() = 0;
  /// True if the tangent of the last trial is the initial stiffness K0
  /// (every point elastic): then the factorised initial matrix is exact.
  virtual bool tangent_is_initial() const { return false; }
  /// Switches extrapolated (IMPL-EX) trials on or off; false if the system
  /// cannot extrapolate (nothing changed).
  virtual bool set_extrapolation(bool) { return false; }
  /// True if the last trial was extrapolated (IMPL-EX): accept() then
  /// replaces its stresses by the implicit ones.
  virtual bool trial_extrapolated() const { return false; }
  /// After accept() of an extrapolated trial: f_int(implicit stresses) -
  /// f_int(extrapolated stresses) (layout of K0's columns, zero at fixed
  /// dofs).
  virtual void extrapolation_change(Vec f) { VecSet(f, 0.0); }
};

/// Work of one (possibly cut) step.
struct StepReport
{
  int iterations = 0;             ///< Newton iterations (all sub-steps)
  int tangent_factorizations = 0; ///< consistent tangents factorised
  int krylov_iterations = 0;      ///< GMRES iterations on the tangent
  int initial_factorizations = 0; ///< effective matrices for cut steps
  int cuts = 0;                   ///< sub-steps beyond the first
  double residual = 0.0;          ///< final ||R|| / ||F_ext||
  /// IMPL-EX steps: the equilibrium error of the implicit stresses at the
  /// step's solution, (1 + alpha) ||f_int(implicit) - f_int(extrapolated)||
  /// / ||F_ext|| (largest over the sub-steps; 0 for implicit steps)
  double extrapolation_error = 0.0;
  // Wall time [s] by part: material update and residual assembly, tangent
  // assembly, factorisations, direction solves (GMRES or triangular).
  double seconds_residual = 0.0, seconds_tangent = 0.0,
         seconds_factorization = 0.0, seconds_solve = 0.0;
};

/// Thrown when a step cannot be solved even after the allowed cuts.
struct StepFailure : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// Thrown by solve_static: `reached` is the load factor of the last
/// converged increment (the displacement and the committed material state
/// are those of that factor).
struct StaticStepFailure : StepFailure
{
  StaticStepFailure(const std::string& what, double reached,
                    const StepReport& report)
      : StepFailure(what), reached(reached), report(report)
  {
  }
  double reached;
  StepReport report; ///< the work done, failed increments included
};

/// A constraint of the static solution (newton_constraint.h) and the
/// shift of its initial matrix, K0 + shift M: a block held by its joints
/// alone makes K0 singular, and the shift makes the modified Newton
/// iteration the proximal-point iteration of joint::static_contact (each
/// elastic mode j converging by shift / (shift + omega_j^2) per iteration).
struct StaticConstraint
{
  NewtonConstraint* constraint = nullptr; ///< null: none
  Mat M = nullptr;
  double shift = 0.0; ///< [1/s^2]
};

/// Quasi-static solution of f_int(u) = F: the load goes from F_from to F_to
/// in `increments` equal steps (static material: dt = 0). u: committed
/// displacement on entry, solution on exit. K0: the initial stiffness (fixed
/// rows identity). An increment that fails after settings.max_cuts halvings
/// throws StaticStepFailure, u then holding the last converged state (and
/// the constraint its committed state).
StepReport solve_static(NonlinearSystem& system, Mat K0, Vec F_from, Vec F_to,
                        int increments, Vec u, const NewtonSettings& settings,
                        linalg::Factorization factorization,
                        const StaticConstraint& constrained = {});

/// The Hughes-Liu implicit-explicit partition (partitioned_newmark.h) in
/// the nonlinear integrator: the explicit elements (the band next to a
/// transmitting boundary, linear elastic, lumped mass in M) see only the
/// predictor d~ = u + dt v + dt^2 (1/2 - beta) a, so their force K_E d~
/// replaces K_E u' in f_int(u'); the Rayleigh damping's stiffness part is
/// b_K K_I (the implicit elements alone); the prescribed unknowns (the
/// boundary's nodes, explicit alone) take their displacements, velocities
/// and accelerations from `prescribed` once per step (linearly in time
/// within a cut step), rows and columns of the effective matrix identity;
/// the explicit elements see d~ = d' - beta dt^2 a', v~ = v' - gamma dt a'
/// there (as PartitionedNewmark). With explicit elements average
/// acceleration only (HHT alpha = 0); without them (the band implicit:
/// only the prescribed unknowns) any HHT alpha.
struct Partition
{
  /// The implicit elements' stiffness (zero rows at explicit-only nodes).
  Mat K_implicit = nullptr;
  /// The explicit elements' stiffness, part of f_int (linear there); null
  /// without explicit elements (the band implicit: K_implicit is K).
  Mat K_explicit = nullptr;
  std::shared_ptr<PrescribedMotion> prescribed;
  /// b_E [s]: the explicit elements' stiffness-proportional damping
  /// b_E K_E v~ on the predicted velocity (PartitionedNewmark).
  double b_explicit = 0.0;
};

class NonlinearNewmark
{
public:
  /// M, K0 (and `extra_damping`) must stay alive while the integrator is
  /// used. `extra_damping`: a damping matrix added to the Rayleigh damping
  /// (boundary dashpots; its pattern within K0's), or null.
  NonlinearNewmark(Mat M, Mat K0, RayleighDamping damping, TimeScheme scheme,
                   NonlinearSystem& system, NewtonSettings settings,
                   linalg::Factorization factorization,
                   Mat extra_damping = nullptr);
  ~NonlinearNewmark();
  NonlinearNewmark(const NonlinearNewmark&) = delete;
  NonlinearNewmark& operator=(const NonlinearNewmark&) = delete;

  /// State at the current time: u, v, a, external load f and the internal
  /// force f_int(u) of the committed material state (all copied).
  void set_state(Vec u, Vec v, Vec a, Vec f, Vec f_int);
  /// Advances one step to the external load f_next = f(t + dt).
  StepReport step(Vec f_next);
  /// A constraint solved in every step (null: none; not owned). The
  /// constraint force joins the effective equation unweighted by HHT's
  /// alpha, as in LinearNewmark.
  void set_constraint(NewtonConstraint* constraint);
  /// The partition of a transmitting boundary (before set_state; the
  /// matrices must outlive the integrator). Throws std::invalid_argument
  /// with HHT alpha != 0 and explicit elements.
  void set_partition(Partition partition);
  /// The state one step back and the step number n of the state (the
  /// prescribed motion's history; set_state sets the state and 0).
  void set_history(const Kinematics& prev, int n);
  Kinematics prev() const { return {_u_prev, _v_prev, _a_prev}; }
  /// Changes the velocity of the last step by dv, the displacement and the
  /// acceleration unchanged (the impact correction of joint pairs that
  /// close; as LinearNewmark::correct_velocity).
  void correct_velocity(Vec dv);

  Vec u() const { return _u; }
  Vec v() const { return _v; }
  Vec a() const { return _a; }
  Vec f_int() const { return _fint; }
  const TimeScheme& scheme() const { return _scheme; }
  /// The factorisation of the initial effective matrix (full step).
  const linalg::DirectSolver& solver() const;

private:
  /// One step of length dt from (u, v, a, f, f_int) to f_next; `level` is
  /// the number of halvings so far.
  void advance(double dt, Vec f_next, int level, StepReport& report);
  /// Newton iterations of one step; true if converged (state not touched
  /// on failure).
  bool solve_step(double dt, Vec f_next, int level, StepReport& report);
  /// The initial effective matrix for a step dt / 2^level, factorised.
  const linalg::DirectSolver& initial_solver(int level, StepReport& report);
  /// The prescribed rows' motion at the end of a (sub)step of length dt
  /// ending at the fraction `theta` of the full step, and the predictors
  /// d~ = d' - beta dt^2 a', v~ = v' - gamma dt a' there (partition only).
  void prescribed_values(double theta, double dt);
  /// x[rows] = values (owned rows).
  void set_prescribed(Vec x, const std::vector<double>& values) const;

  Mat _M, _K0;
  Mat _Ce = nullptr; ///< extra damping (not owned), or null
  RayleighDamping _damping;
  TimeScheme _scheme;
  NonlinearSystem& _system;
  NewtonConstraint* _constraint = nullptr;
  int _constraint_level = -1; ///< the level the constraint was factorised for
  NewtonSettings _settings;
  linalg::Factorization _factorization;
  /// Per step length dt / 2^level: J0 and its factors.
  struct Level
  {
    Mat J0 = nullptr;
    std::unique_ptr<linalg::DirectSolver> solver;
  };
  std::map<int, Level> _initial;
  /// The level whose matrices the last initial_solver() call returned.
  const Level* _level = nullptr;
  Mat _J = nullptr; ///< consistent effective matrix
  std::unique_ptr<TangentSolver> _tangent_solver;
  Vec _u = nullptr, _v = nullptr, _a = nullptr, _f = nullptr, _fint = nullptr;
  Partition _partition;
  /// The partition's history: the state one step back, the step number,
  /// the state at the start of the full step, the explicit elements'
  /// predictor, the time of the full step done (cut steps), the prescribed
  /// rows' motion at its start and end, and of the (sub)step being solved
  /// with its predictors d~ and v~.
  Vec _u_prev = nullptr, _v_prev = nullptr, _a_prev = nullptr;
  Vec _u_start = nullptr, _v_start = nullptr, _a_start = nullptr;
  Vec _d_p = nullptr;
  int _n = 0;
  double _elapsed = 0.0;
  PrescribedValues _start_values, _end_values, _values;
  std::vector<double> _predicted_d, _predicted_v;
  // Work vectors.
  Vec _ut = nullptr, _vt = nullptr, _at = nullptr, _fint_t = nullptr,
      _r = nullptr, _g = nullptr, _w1 = nullptr, _w2 = nullptr, _du = nullptr,
      _tmp = nullptr, _fmid = nullptr;
};
} // namespace damseis::dynamics
