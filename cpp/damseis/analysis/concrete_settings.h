// Case keys of the nonlinear concrete (material.model, [concrete], Newton
// settings) shared by the 2D dam demos, and their reading.
#pragma once

#include <damseis/case/case.h>
#include <damseis/dynamics/nonlinear_newmark.h>
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

struct ConcreteSettings
{
  ConcreteModelKind kind = ConcreteModelKind::linear;
  /// Parameters of the dam concrete (E and nu filled in by the caller from
  /// the elastic material; strengths after the dynamic factor).
  material::ConcreteParameters params;
  /// Multipliers of the static E and of the strengths (the Chinese
  /// specification's +30% for dynamic analyses: 1.3).
  double factor_E = 1.0, factor_strength = 1.0;
  dynamics::NewtonSettings newton;
  int static_increments = 5;
  /// IMPL-EX integration of the dynamic steps (fem::ConcreteModel::
  /// set_implex) instead of the implicit return map in a Newton iteration.
  bool implex = false;
};

/// Adds material.model, concrete.* and the Newton keys.
void add_concrete_keys(input::Schema& schema);

/// Reads and checks them. `E`, `nu`: the static elastic constants of the
/// concrete (the caller multiplies its E by factor_E).
ConcreteSettings read_concrete_settings(const input::Case& c, double E,
                                        double nu);
} // namespace damseis::analysis
