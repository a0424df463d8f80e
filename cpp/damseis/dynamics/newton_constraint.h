// Constraints solved inside the Newton iteration of the nonlinear
// integrators (nonlinear_newmark.h): joint contact on a nonlinear bulk
// (in place of algorithms.md 2.6's monolithic Newton on (u, p), which
// would factorise the unsymmetric coupled matrix at every iteration). The
// constraint force r (layout of the unknowns) joins
// the residual, R(u) = R_bulk(u) - r, and each Newton iterate of the bulk,
//   z = u_k - J^-1 R_k   (J the consistent matrix, or the initial J0),
// is corrected on the initial matrix J0, on which the constraint problem is
// condensed (its flexibility computed once per factorisation of J0):
//   u_k+1 = z + J0^-1 (r_k+1 - r_k),   r_k+1 solving the constraint problem
// at u_k+1. Where J0 is the exact Jacobian (an elastic bulk in a time
// step) this is the exact Newton step of the constrained system: a linear
// bulk converges in one iteration, as with the constraint condensed on the
// linear engine's effective matrix. Where it is not (a yielding bulk; the
// static stage's shifted K0 + s M), the constraint's coupling uses J0 in
// place of J: the iteration still converges to the constrained solution
// (the residual and the constraint problem are exact), more slowly.
// The step is accepted only with a constraint force that solves the
// constraint problem at the accepted displacement (consistent()).
#pragma once

#include <petscmat.h>
#include <petscvec.h>

namespace damseis::dynamics
{
class NewtonConstraint
{
public:
  virtual ~NewtonConstraint() = default;
  /// Factorises the initial matrix J0 of a step length (or of the static
  /// stage) and condenses the constraint on it (collective).
  virtual void factorize(Mat J0) = 0;
  /// Starts a step (or static increment): the trial state is the committed
  /// one.
  virtual void begin() = 0;
  /// The trial constraint force r (layout of the unknowns).
  virtual Vec force() const = 0;
  /// Marks the start of a Newton iteration: the trial state is the base
  /// that correct() and blend() start from.
  virtual void start_iteration() = 0;
  /// Corrects the bulk's iterate z in place to u_k+1 (see above), with J0
  /// the matrix factorize() was given; the new trial force in force().
  /// Throws StepFailure (nonlinear_newmark.h) if the constraint problem
  /// cannot be solved.
  virtual void correct(Mat J0, Vec z) = 0;
  /// The trial state base + eta (corrected - base) (the line search along
  /// u_k + eta (u_k+1 - u_k)).
  virtual void blend(double eta) = 0;
  /// Whether the trial force solves the constraint problem at the trial
  /// displacement: after a correct() of this step, blended with eta = 1.
  virtual bool consistent() const = 0;
  /// The trial state becomes the committed one.
  virtual void accept() = 0;
  /// Back to the committed state (a step that is cut).
  virtual void reject() = 0;
};
} // namespace damseis::dynamics
