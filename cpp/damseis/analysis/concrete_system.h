// The nonlinear concrete model as the integrators see it
// (dynamics::NonlinearSystem): PETSc vectors in, the material update through
// a ghosted Function, the counts of the last trial and of the last accepted
// state.
#pragma once

#include "run_support.h"
#include <damseis/dynamics/nonlinear_newmark.h>
#include <damseis/fem/concrete_model.h>

namespace damseis::analysis
{
class ConcreteSystem : public dynamics::NonlinearSystem
{
public:
  explicit ConcreteSystem(fem::ConcreteModel& m)
      : _m(m), _u(m.elastic_model().V())
  {
  }
  bool trial(Vec u, double dt) override
  {
    to_function(u, _u);
    last = _m.update(_u, dt);
    substepped += last.substepped;
    return_maps += last.return_maps;
    local_iterations += last.local_iterations;
    return last.failed == 0;
  }
  void internal_force(Vec f) override { _m.assemble_internal_force(f); }
  void tangent(Mat A) override { _m.assemble_tangent(A); }
  bool tangent_is_initial() const override
  {
    return last.inelastic == 0 || _m.trial_extrapolated();
  }
  void accept() override
  {
    _m.accept();
    accepted = last;
  }
  fem::MaterialUpdateStats last;     ///< of the last trial
  fem::MaterialUpdateStats accepted; ///< of the last accepted trial
  std::int64_t substepped = 0;       ///< sub-stepped point updates, all trials
  /// return maps and local Newton iterations, all trials
  std::int64_t return_maps = 0, local_iterations = 0;

private:
  fem::ConcreteModel& _m;
  dolfinx::fem::Function<double> _u;
};
} // namespace damseis::analysis
