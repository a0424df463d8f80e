#include "static_stage.h"
#include <cmath>
#include <damseis/joint/static_contact.h>
#include <damseis/results/progress.h>
#include <dolfinx/la/petsc.h>
#include <sstream>

namespace damseis::analysis
{
namespace
{
using dolfinx::la::petsc::Vector;

/// F = (1 - lambda) F_a + lambda F_b.
void load_at(double lambda, Vec F_a, Vec F_b, Vec F)
{
  VecAXPBYPCZ(F, 1.0 - lambda, lambda, 0.0, F_a, F_b);
}

/// Dynamic relaxation from the committed state at load factor `from` of
/// the loading F_a -> F_b to its full load (see static_stage.h); returns
/// the steps taken and the final largest speed. u: the state at `from` on
/// entry, the relaxed one on exit.
std::pair<int, double> relax(ConcreteSystem& system, Mat K, Mat M, Vec F_a,
                             Vec F_b, double from, Vec u,
                             const StaticStageSettings& s)
{
  MPI_Comm comm;
  PetscObjectGetComm(reinterpret_cast<PetscObject>(K), &comm);
  const double period = 1.0 / s.f1_hz;
  dynamics::TimeScheme scheme;
  scheme.dt = period / s.steps_per_period;
  const int ramp =
      static_cast<int>(std::ceil(s.ramp_periods * s.steps_per_period));
  const int hold =
      static_cast<int>(std::ceil(s.hold_periods * s.steps_per_period));
  dynamics::NewtonSettings newton = s.newton;
  newton.extrapolated_predictor = false;
  // The rate-independent material: material updates as static steps.
  system.quasi_static = true;
  dynamics::NonlinearNewmark integrator(
      M, K, dynamics::RayleighDamping::from_ratio(1.0, s.f1_hz, s.f2_hz),
      scheme, system, newton, s.factorization);
  integrator.set_constraint(s.contact);
  Vector zero = linalg::column_vector(K), F = linalg::column_vector(K),
         fint = linalg::column_vector(K);
  load_at(from, F_a, F_b, F.vec());
  system.internal_force(fint.vec());
  integrator.set_state(u, zero.vec(), zero.vec(), F.vec(), fint.vec());
  results::Progress progress(comm, ramp + hold);
  for (int k = 1; k <= ramp + hold; ++k)
  {
    const double lambda =
        from + (1.0 - from) * std::min(1.0, static_cast<double>(k) / ramp);
    load_at(lambda, F_a, F_b, F.vec());
    try
    {
      integrator.step(F.vec());
    }
    catch (const dynamics::StepFailure& e)
    {
      system.quasi_static = false;
      throw dynamics::StepFailure("static stage: dynamic relaxation step " +
                                  std::to_string(k) + " (load factor " +
                                  std::to_string(lambda) + "): " + e.what());
    }
    progress.report(k, k * scheme.dt, "  (static stage, dynamic relaxation)");
  }
  system.quasi_static = false;
  double speed = 0.0;
  VecNorm(integrator.v(), NORM_INFINITY, &speed);
  VecCopy(integrator.u(), u);
  return {ramp + hold, speed};
}
} // namespace

nlohmann::json StaticStageReport::to_json() const
{
  return {{"newton_iterations", iterations},
          {"cuts", cuts},
          {"load_controlled_factor", load_controlled_factor},
          {"dead_weight_load_controlled_factor", dead_weight_factor},
          {"dynamic_relaxation_steps", relaxation_steps},
          {"dynamic_relaxation_final_speed_m_per_s", relaxation_final_speed}};
}

namespace
{
/// One loading of the static stage: from F_a (committed, u) to F_b in
/// `increments` under load control up to `relax_from`, then, if Newton
/// stops or at relax_from, dynamic relaxation and a Newton solve at F_b.
/// Returns the load factor reached under load control.
double load_stage(ConcreteSystem& system, Mat K, Mat M, Vec F_a, Vec F_b,
                  int increments, double relax_from, const std::string& what,
                  Vec u, const StaticStageSettings& s,
                  StaticStageReport& report)
{
  MPI_Comm comm;
  PetscObjectGetComm(reinterpret_cast<PetscObject>(K), &comm);
  auto add = [&](const dynamics::StepReport& r)
  {
    report.iterations += r.iterations;
    report.cuts += r.cuts;
  };
  // Load control up to relax_from.
  Vector F_part = linalg::column_vector(K);
  Vec F_to = F_b;
  if (relax_from < 1.0)
  {
    load_at(relax_from, F_a, F_b, F_part.vec());
    F_to = F_part.vec();
  }
  double reached = 1.0;
  const dynamics::StaticConstraint constraint{s.contact, M, s.contact_shift};
  try
  {
    add(dynamics::solve_static(system, K, F_a, F_to, increments, u, s.newton,
                               s.factorization, constraint));
    if (relax_from >= 1.0)
      return 1.0;
    reached = relax_from;
  }
  catch (const dynamics::StaticStepFailure& e)
  {
    add(e.report);
    reached = e.reached * std::min(1.0, relax_from);
    std::ostringstream line;
    line.precision(4);
    line << "static stage: under load control Newton stops at " << reached
         << " of " << what << " (" << e.what()
         << "); the rest is applied by dynamic relaxation (critically "
            "damped, ramp "
         << s.ramp_periods << " and hold " << s.hold_periods
         << " fundamental periods)";
    results::print(comm, line.str());
  }
  const auto [steps, speed] = relax(system, K, M, F_a, F_b, reached, u, s);
  report.relaxation_steps += steps;
  report.relaxation_final_speed =
      std::max(report.relaxation_final_speed, speed);
  // The equilibrium at the full load from the relaxed state (solve_static
  // needs distinct start and end loads).
  Vector start = linalg::column_vector(K);
  VecCopy(F_b, start.vec());
  try
  {
    add(dynamics::solve_static(system, K, start.vec(), F_b, 1, u, s.newton,
                               s.factorization, constraint));
  }
  catch (const dynamics::StepFailure& e)
  {
    throw dynamics::StepFailure("static stage: no equilibrium under " + what +
                                " after dynamic relaxation (" + e.what() + ")");
  }
  std::ostringstream line;
  line.precision(3);
  line << "static stage: " << what << " relaxed in " << steps
       << " steps (largest speed at the end " << speed
       << " m/s), equilibrium at the full load found";
  results::print(comm, line.str());
  return reached;
}
} // namespace

StaticStageReport solve_static_stage(ConcreteSystem& system, Mat K, Mat M,
                                     Vec F_g, Vec F_static, Vec u,
                                     const StaticStageSettings& s)
{
  StaticStageReport report;
  Vector zero = linalg::column_vector(K);
  VecSet(u, 0.0);
  if (s.contact && s.cantilever_dead_load)
  {
    // The cantilevers carry their own weight (joints disconnected); the
    // joints close in that state, with no force, or stay open by their
    // initial gap: the gaps and slips are measured from it.
    struct Disconnected // the pairs reconnected however the block ends
    {
      joint::NonlinearContact& c;
      explicit Disconnected(joint::NonlinearContact& c) : c(c)
      {
        c.set_disconnected(true);
      }
      ~Disconnected() { c.set_disconnected(false); }
    };
    {
      const Disconnected disconnected(*s.contact);
      try
      {
        report.dead_weight_factor =
            load_stage(system, K, M, zero.vec(), F_g, 1, 1.0,
                       "the dead weight on the cantilevers", u, s, report);
      }
      catch (const dynamics::StepFailure& e)
      {
        throw dynamics::StepFailure(
            std::string(e.what()) +
            "; if a block has no support but its joints, use "
            "joints.dead_load = \"joints_active\"");
      }
    }
    joint::close_joints_at(s.contact->contact(), u);
  }
  else
    report.dead_weight_factor = load_stage(
        system, K, M, zero.vec(), F_g, 1, 1.0, "the dead weight", u, s, report);
  report.load_controlled_factor =
      load_stage(system, K, M, F_g, F_static, s.increments, s.relax_from,
                 "the loads after the dead weight", u, s, report);
  return report;
}
} // namespace damseis::analysis
