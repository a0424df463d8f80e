// The static stage of a nonlinear dam analysis: dead weight, then the other
// static loads (reservoir, silt, uplift) in load increments, with the
// rate-independent material (dynamics::solve_static).
//
// Under load control a brittle crack can run unstably (at a singular heel,
// for example): past some load factor there is no equilibrium state next to
// the last one, and Newton fails however small the increment. The rest of
// the load is then applied by dynamic relaxation: the same model with its
// mass, a critically damped Rayleigh damping (ratio 1 at the two damping
// frequencies) and the rate-independent material, the load ramped to its
// full value over `ramp_periods` fundamental periods and held for
// `hold_periods` more, so that the crack jumps as it would under a slow
// loading and arrests; a static Newton solve at the full load from the
// relaxed state then gives the equilibrium that the dynamic stage starts
// from. If that fails too, the static loads have no equilibrium. The dead
// weight, applied first in one increment, falls back the same way (a
// monolithic arch dam on a coarse mesh can crack under its own weight).
//
// With contact joints (algorithms.md 2.8) the contact is a constraint of
// every Newton iteration (joint::NonlinearContact) on the initial matrix
// K0 + s M (s = joint::static_shift_factor omega_1^2: a block held by its
// joints alone makes K0 singular; the shifted matrix makes the iteration
// the proximal-point iteration of joint::static_contact). The dead weight
// is carried with the joints active, or by the cantilevers alone (joints
// disconnected; the gaps and slips are then measured from that state).
#pragma once

#include "concrete_system.h"
#include <damseis/dynamics/nonlinear_newmark.h>
#include <damseis/joint/nonlinear_contact.h>
#include <nlohmann/json.hpp>

namespace damseis::analysis
{
struct StaticStageSettings
{
  int increments = 5; ///< of the loads after the dead weight
  dynamics::NewtonSettings newton;
  linalg::Factorization factorization = linalg::Factorization::automatic;
  /// Dynamic relaxation: the two frequencies of the (critical) Rayleigh
  /// damping [Hz] (the fundamental one first), steps per period, ramp and
  /// hold durations in fundamental periods.
  double f1_hz = 1.0, f2_hz = 3.0;
  int steps_per_period = 40;
  double ramp_periods = 4.0, hold_periods = 4.0;
  /// Load factor from which the relaxation takes over even if Newton could
  /// go on (tests: 1 = only where Newton fails).
  double relax_from = 1.0;
  /// Contact joints (null: none; the contact state is the stage's result)
  /// with the shift s of the initial matrix [1/s^2], and whether the dead
  /// weight is carried by the cantilevers alone.
  joint::NonlinearContact* contact = nullptr;
  double contact_shift = 0.0;
  bool cantilever_dead_load = false;
};

struct StaticStageReport
{
  int iterations = 0, cuts = 0; ///< Newton iterations and halvings
  /// Load factor of the loads after the dead weight reached by Newton under
  /// load control (1: no relaxation was needed).
  double load_controlled_factor = 1.0;
  /// The same for the dead weight (applied in one increment).
  double dead_weight_factor = 1.0;
  int relaxation_steps = 0; ///< both loadings
  /// Largest |v| at the end of a hold [m/s] (0 without relaxation).
  double relaxation_final_speed = 0.0;
  nlohmann::json to_json() const;
};

/// Solves f_int(u) = F_static from u = 0 (F_g: the dead weight, applied
/// first in one increment). On return `u` and the committed material state
/// are the static solution. Throws dynamics::StepFailure (with what was
/// tried) if there is none.
StaticStageReport solve_static_stage(ConcreteSystem& system, Mat K, Mat M,
                                     Vec F_g, Vec F_static, Vec u,
                                     const StaticStageSettings& s);
} // namespace damseis::analysis
