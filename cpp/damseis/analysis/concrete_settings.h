// Case keys of the nonlinear concrete (material.model, [concrete], Newton
// settings) shared by the 2D dam demos, and their reading.
#pragma once

#include <damseis/dynamics/nonlinear_newmark.h>
#include <damseis/input/case.h>
#include <damseis/material/concrete.h>
#include <string>

namespace damseis::analysis
{
/// Which analysis a dam demo runs.
enum class ConcreteModelKind
{
  linear,      ///< linear engine (stress points, one solve per step)
  elastic,     ///< nonlinear engine, elastic material (reproduces linear)
  plastic,     ///< rate-independent HTC plasticity (R = 1)
  viscoplastic ///< rate-dependent HTC consistency viscoplasticity
};

/// "linear", "elastic", "plastic" or "viscoplastic".
std::string to_string(ConcreteModelKind kind);

/// Multipliers of the static E and of the static strengths.
struct DynamicFactors
{
  double E = 1.0, strength = 1.0;
};

struct ConcreteSettings
{
  ConcreteModelKind kind = ConcreteModelKind::linear;
  /// Parameters of the dam concrete for `kind`: the static values times
  /// the factors of that kind (`applied`).
  material::ConcreteParameters params;
  /// The static values of the case (E [Pa], fc and ft [Pa]).
  double static_E = 0.0, static_fc = 0.0, static_ft = 0.0;
  /// The factors of the rate-independent models (linear, elastic, plastic):
  /// the Chinese specification's +30% for dynamic analyses is 1.3 (the
  /// paper's convention); and of the rate-dependent (viscoplastic) model,
  /// whose rate functions give the dynamic strengths: 1.0 unless a user
  /// asks otherwise (else the rate effect is counted twice).
  DynamicFactors rate_independent, viscoplastic;
  /// The factors in `params` (those of `kind`).
  DynamicFactors applied;
  dynamics::NewtonSettings newton;
  int static_increments = 5;
  /// IMPL-EX integration of the dynamic steps (fem::ConcreteModel::
  /// set_implex) instead of the implicit return map in a Newton iteration.
  bool implex = false;
};

/// Adds material.model, concrete.* and the Newton keys.
void add_concrete_keys(input::Schema& schema);

/// The factors of a model: `viscoplastic` for the rate-dependent model,
/// `rate_independent` for the others.
DynamicFactors factors_of(const ConcreteSettings& s, ConcreteModelKind kind);

/// The settings for another model (kind, material mode, E and strengths
/// with that model's factors); everything else as in `s`.
ConcreteSettings with_model(const ConcreteSettings& s, ConcreteModelKind kind);

/// Reads and checks them. `E`, `nu`: the static elastic constants of the
/// concrete; params holds the values of the model of material.model, and
/// every model's parameters are checked (a study runs them all).
ConcreteSettings read_concrete_settings(const input::Case& c, double E,
                                        double nu);
} // namespace damseis::analysis
