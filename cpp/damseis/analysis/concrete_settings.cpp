#include "concrete_settings.h"
#include <stdexcept>

namespace damseis::analysis
{
std::string to_string(ConcreteModelKind kind)
{
  switch (kind)
  {
  case ConcreteModelKind::elastic:
    return "elastic";
  case ConcreteModelKind::plastic:
    return "plastic";
  case ConcreteModelKind::viscoplastic:
    return "viscoplastic";
  default:
    return "linear";
  }
}

void add_concrete_keys(input::Schema& s)
{
  s.string("material.model", "linear", "-",
           "dam concrete: linear (linear engine), elastic, plastic "
           "(rate-independent HTC) or viscoplastic (rate-dependent HTC)",
           {"linear", "elastic", "plastic", "viscoplastic"});
  s.real("concrete.fc", "24.1e6", "Pa", "static uniaxial compressive strength")
      .above(0);
  s.real("concrete.ft", "2.45e6", "Pa", "static uniaxial tensile strength")
      .above(0);
  s.real("concrete.fbc_ratio", "1.15", "-",
         "equibiaxial / uniaxial compressive strength")
      .between_exclusive(1.0, 2.0);
  s.real("concrete.Gf", "200", "N/m", "tensile fracture energy").above(0);
  s.real("concrete.Gc", "20000", "N/m", "compressive fracture energy").above(0);
  s.string("concrete.tension_softening", "crack_band", "-",
           "crack_band: exponential softening dissipating Gf per unit crack "
           "area (Bazant & Oh), ft lowered in cells larger than the "
           "snap-back limit E Gf / (1.25 ft^2); crack_band_keep_strength: "
           "those cells keep ft and soften as steeply as the limit allows "
           "(1.25 ft^2 h / E > Gf per unit area); none: perfectly plastic "
           "in tension (no softening, no mesh size in the law: coarse 3D "
           "dam meshes such as the paper's 450-element arch dam)",
           {"crack_band", "crack_band_keep_strength", "none"});
  s.real("concrete.dynamic_factor_E", "1.0", "-",
         "multiplier of material.E in the rate-independent models (linear, "
         "elastic, plastic; the +30% convention of the Chinese code: 1.3); "
         "not applied to the viscoplastic model")
      .between(0.5, 3.0);
  s.real("concrete.dynamic_factor_strength", "1.0", "-",
         "multiplier of fc and ft in the rate-independent models (plastic; "
         "the +30% convention: 1.3); not applied to the viscoplastic model")
      .between(0.5, 3.0);
  s.real("concrete.viscoplastic_factor_E", "1.0", "-",
         "multiplier of material.E in the viscoplastic model (1: static E, "
         "the paper's convention: the rate-dependent model takes static "
         "values)")
      .between(0.5, 3.0);
  s.real("concrete.viscoplastic_factor_strength", "1.0", "-",
         "multiplier of fc and ft in the viscoplastic model (1: static "
         "strengths; its rate functions give the dynamic increase, so a "
         "factor above 1 counts the rate effect twice)")
      .between(0.5, 3.0);
  s.real("solver.newton_rtol", "1e-6", "-",
         "Newton tolerance: residual norm / external load norm")
      .above(0);
  s.integer("solver.newton_max_iterations", "30", "-",
            "Newton iterations per (sub)step")
      .between(1, 1000);
  s.integer("solver.newton_stagnation", "5", "-",
            "give a step up (and cut it) when the residual has not halved "
            "in this many iterations")
      .between(1, 1000);
  s.integer("solver.max_cuts", "6", "-",
            "halvings of a step that does not converge")
      .between(0, 12);
  s.real("solver.krylov_rtol", "1e-2", "-",
         "GMRES tolerance of a Newton direction, relative to the residual")
      .between_exclusive(0.0, 1.0);
  s.integer("solver.krylov_max_iterations", "60", "-",
            "GMRES iterations on reused factors before the tangent is "
            "factorised; 0 factorises every tangent (exact Newton)")
      .between(0, 1000);
  s.string("solver.material_integration", "implicit", "-",
           "implicit: backward-Euler return map inside a Newton iteration "
           "per step; implex: IMPL-EX (Oliver, Huespe & Cante 2008), the "
           "stress of each dynamic step extrapolated from the last step's "
           "plastic strain increment, so a step is one linear solve with "
           "the initial matrix (first-order accurate in dt; check with a "
           "smaller time.dt)",
           {"implicit", "implex"});
  s.boolean(
      "solver.extrapolated_predictor", "false", "-",
      "implicit integration: start each step's Newton iteration from "
      "the step's IMPL-EX solution (one extra solve with the "
      "factorised initial matrix) instead of Newmark's predictor u + dt v "
      "+ dt^2 (1/2 - beta) a");
  s.integer("solver.static_increments", "5", "-",
            "load increments of the reservoir in the static stage")
      .between(1, 1000);
}

DynamicFactors factors_of(const ConcreteSettings& s, ConcreteModelKind kind)
{
  return kind == ConcreteModelKind::viscoplastic ? s.viscoplastic
                                                 : s.rate_independent;
}

ConcreteSettings with_model(const ConcreteSettings& s, ConcreteModelKind kind)
{
  ConcreteSettings m = s;
  m.kind = kind;
  m.applied = factors_of(s, kind);
  auto& p = m.params;
  p.E = s.static_E * m.applied.E;
  p.fc0 = s.static_fc * m.applied.strength;
  p.ft0 = s.static_ft * m.applied.strength;
  p.mode = kind == ConcreteModelKind::viscoplastic
               ? material::Mode::viscoplastic
           : kind == ConcreteModelKind::plastic ? material::Mode::plastic
                                                : material::Mode::elastic;
  return m;
}

ConcreteSettings read_concrete_settings(const input::Case& c, double E,
                                        double nu)
{
  ConcreteSettings s;
  const std::string model = c.string("material.model");
  const ConcreteModelKind kind =
      model == "elastic"        ? ConcreteModelKind::elastic
      : model == "plastic"      ? ConcreteModelKind::plastic
      : model == "viscoplastic" ? ConcreteModelKind::viscoplastic
                                : ConcreteModelKind::linear;
  s.static_E = E;
  s.static_fc = c.real("concrete.fc");
  s.static_ft = c.real("concrete.ft");
  s.rate_independent = {c.real("concrete.dynamic_factor_E"),
                        c.real("concrete.dynamic_factor_strength")};
  s.viscoplastic = {c.real("concrete.viscoplastic_factor_E"),
                    c.real("concrete.viscoplastic_factor_strength")};
  auto& p = s.params;
  p.nu = nu;
  p.fbc_ratio = c.real("concrete.fbc_ratio");
  p.Gf = c.real("concrete.Gf");
  p.Gc = c.real("concrete.Gc");
  const std::string softening = c.string("concrete.tension_softening");
  p.tension_softening =
      softening == "none" ? material::TensionSoftening::none
      : softening == "crack_band_keep_strength"
          ? material::TensionSoftening::crack_band_keep_strength
          : material::TensionSoftening::crack_band;
  // Every model's strengths must give a valid surface (a study runs all).
  for (ConcreteModelKind k :
       {ConcreteModelKind::plastic, ConcreteModelKind::viscoplastic})
  {
    const auto q = with_model(s, k).params;
    const std::string factor = k == ConcreteModelKind::viscoplastic
                                   ? "concrete.viscoplastic_factor_strength"
                                   : "concrete.dynamic_factor_strength";
    if (!(q.ft0 < 0.5 * q.fc0))
      c.fail("concrete.ft", "is not below half of concrete.fc",
             "a tensile strength of about 0.05-0.15 fc");
    try
    {
      material::HtcConcrete check(q);
    }
    catch (const std::invalid_argument& e)
    {
      c.fail("concrete.fc",
             std::string("gives no valid HTC surface with ") + factor + " (" +
                 e.what() + ")",
             "typical concrete values, e.g. fc = 20e6..60e6, ft = 0.1 fc");
    }
  }
  s = with_model(s, kind);
  s.newton.rtol = c.real("solver.newton_rtol");
  s.newton.max_iterations =
      static_cast<int>(c.integer("solver.newton_max_iterations"));
  s.newton.max_cuts = static_cast<int>(c.integer("solver.max_cuts"));
  s.newton.stagnation_iterations =
      static_cast<int>(c.integer("solver.newton_stagnation"));
  s.newton.krylov_rtol = c.real("solver.krylov_rtol");
  s.newton.krylov_max_iterations =
      static_cast<int>(c.integer("solver.krylov_max_iterations"));
  s.static_increments = static_cast<int>(c.integer("solver.static_increments"));
  s.implex = c.string("solver.material_integration") == "implex";
  // (Used only where there is plastic strain to extrapolate and the steps
  // are implicit: run_nonlinear_seismic decides, per model of a study.)
  s.newton.extrapolated_predictor = c.boolean("solver.extrapolated_predictor");
  return s;
}
} // namespace damseis::analysis
