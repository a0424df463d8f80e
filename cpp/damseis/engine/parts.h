// The parts that plug into the time-history engine (time_history.h):
//  - a Stepper advances the state of the model by one step: the integrator
//    with the bulk behind it (linear elastic, or Newton on nonlinear
//    concrete) and the constraints (tied joints, later contact);
//  - a DynamicLoad gives the load at each step (the seismic input: the
//    base-acceleration formulation today, free-field boundary forces next)
//    and the acceleration the run starts with;
//  - Observers record what a step produced (histories, envelopes, fields).
// Each part saves what it needs in a checkpoint and restores it from one.
#pragma once

#include "checkpoint.h"
#include <damseis/dynamics/nonlinear_newmark.h>
#include <petscvec.h>
#include <string>

namespace damseis::engine
{
using Arrays = std::map<std::string, std::vector<double>>;

/// The integrator of M a + C v + f_int(u) = f(t) with its bulk and
/// constraints. Vectors have the layout of the system's unknowns.
class Stepper
{
public:
  virtual ~Stepper() = default;
  /// A vector with the layout of the unknowns (zero).
  virtual Vec create_vector() const = 0;
  /// Starts a run at step 0 from displacement u0 (the stepper's own initial
  /// displacement if null: zero, or the static solution where the state is
  /// total), velocity v0 (zero if null), acceleration a0 and load f0.
  virtual void start(Vec u0, Vec v0, Vec a0, Vec f0) = 0;
  /// Advances one step to the load f = f(t + dt); throws
  /// dynamics::StepFailure if the step cannot be solved.
  virtual dynamics::StepReport step(Vec f) = 0;
  virtual Vec u() const = 0;
  virtual Vec v() const = 0;
  virtual Vec a() const = 0;
  /// The state (and the run statistics the stepper keeps) into `arrays`.
  virtual void save(Arrays& arrays) const = 0;
  /// The state from a checkpoint, at the current load f (collective: called
  /// inside engine::restore_collectively's check).
  virtual void restore(const CheckpointData& data) = 0;
  /// Takes the restored state with the current load f (collective).
  virtual void resume(Vec f) = 0;
  /// Text appended to the progress line of a step (Newton iterations...).
  virtual std::string progress_note(const dynamics::StepReport&) const
  {
    return {};
  }
  /// The factorisation in use (log and summary).
  virtual std::string solver_name() const = 0;
  /// Seconds spent factorising so far.
  virtual double factor_seconds() const = 0;
  /// The energy balance since the start, where the stepper keeps one
  /// (linear steppers), else null.
  virtual const dynamics::EnergyBalance* energy() const { return nullptr; }
};

/// The external load of the time history.
class DynamicLoad
{
public:
  virtual ~DynamicLoad() = default;
  /// f = f(t_k) (layout of the unknowns).
  virtual void assemble(int k, Vec f) const = 0;
  /// The acceleration of the model at rest under the load at t = 0.
  virtual void initial_acceleration(Vec a) const = 0;
};

/// Something recorded after every step (and at step 0 of a fresh run).
class Observer
{
public:
  virtual ~Observer() = default;
  /// Called once before the loop with its first step (0, or the step of
  /// the checkpoint a restart resumes from).
  virtual void begin(int /*first_step*/) {}
  /// Records the state after step k, at time t.
  virtual void record(int k, double t) = 0;
  /// What the observer has recorded so far, into a checkpoint.
  virtual void save(Arrays&) const {}
  /// The recording from a checkpoint (throws std::runtime_error if an
  /// array is missing or of the wrong size).
  virtual void restore(const CheckpointData&) {}
};
} // namespace damseis::engine
