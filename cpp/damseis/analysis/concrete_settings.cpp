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
  s.real("concrete.dynamic_factor_E", "1.0", "-",
         "multiplier of material.E (the +30% convention: 1.3)")
      .between(0.5, 3.0);
  s.real("concrete.dynamic_factor_strength", "1.0", "-",
         "multiplier of fc and ft (the +30% convention: 1.3)")
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
  s.boolean("solver.extrapolated_predictor", "false", "-",
            "implicit integration: start each step's Newton iteration from "
            "the step's IMPL-EX solution (one extra solve with the "
            "factorised initial matrix) instead of the last displacement");
  s.integer("solver.static_increments", "5", "-",
            "load increments of the reservoir in the static stage")
      .between(1, 1000);
}

ConcreteSettings read_concrete_settings(const input::Case& c, double E,
                                        double nu)
{
  ConcreteSettings s;
  const std::string model = c.string("material.model");
  s.kind = model == "elastic"        ? ConcreteModelKind::elastic
           : model == "plastic"      ? ConcreteModelKind::plastic
           : model == "viscoplastic" ? ConcreteModelKind::viscoplastic
                                     : ConcreteModelKind::linear;
  s.factor_E = c.real("concrete.dynamic_factor_E");
  s.factor_strength = c.real("concrete.dynamic_factor_strength");
  auto& p = s.params;
  p.E = E * s.factor_E;
  p.nu = nu;
  p.fc0 = c.real("concrete.fc") * s.factor_strength;
  p.ft0 = c.real("concrete.ft") * s.factor_strength;
  p.fbc_ratio = c.real("concrete.fbc_ratio");
  p.Gf = c.real("concrete.Gf");
  p.Gc = c.real("concrete.Gc");
  p.mode = s.kind == ConcreteModelKind::viscoplastic
               ? material::Mode::viscoplastic
           : s.kind == ConcreteModelKind::plastic ? material::Mode::plastic
                                                  : material::Mode::elastic;
  if (!(p.ft0 < 0.5 * p.fc0))
    c.fail("concrete.ft", "is not below half of concrete.fc",
           "a tensile strength of about 0.05-0.15 fc");
  try
  {
    material::HtcConcrete check(p);
  }
  catch (const std::invalid_argument& e)
  {
    c.fail("concrete.fc",
           std::string("gives no valid HTC surface (") + e.what() + ")",
           "typical concrete values, e.g. fc = 20e6..60e6, ft = 0.1 fc");
  }
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
