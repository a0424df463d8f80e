// The nonlinear concrete model as the integrators see it
// (dynamics::NonlinearSystem): PETSc vectors in, the material update through
// a ghosted Function, the counts of the last trial and of the last accepted
// state.
#pragma once

#include <damseis/dynamics/nonlinear_newmark.h>
#include <damseis/fem/concrete_model.h>
#include <damseis/linalg/petsc_vectors.h>

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
    linalg::to_function(u, _u);
    last = _m.update(_u, quasi_static ? 0.0 : dt);
    count(last);
    keep_trial(u);
    return last.failed == 0;
  }
  void internal_force(Vec f) override
  {
    _m.assemble_internal_force(f);
    add_supports(f);
  }
  /// Linear supports on the system's unknowns (the springs of a viscous-
  /// spring boundary, in K0 too): their force K_s u joins the internal
  /// force. K_s must outlive the system.
  void set_supports(Mat K_s)
  {
    _supports = K_s;
    _u_trial = linalg::column_vector(K_s);
  }
  void add_tangent_change(Mat A, double scale) override
  {
    _m.add_tangent_change(A, scale);
  }
  bool tangent_is_initial() const override
  {
    return last.inelastic == 0 || _m.trial_extrapolated();
  }
  bool trial_extrapolated() const override { return _m.trial_extrapolated(); }
  void extrapolation_change(Vec f) override
  {
    _m.assemble_extrapolation_change(f);
  }
  bool set_extrapolation(bool on) override
  {
    _m.set_implex(on);
    return true;
  }
  bool accept() override
  {
    // After an IMPL-EX trial the implicit return map runs here: its counts
    // are those of the step.
    const bool extrapolated = _m.trial_extrapolated();
    fem::MaterialUpdateStats implicit;
    const bool ok = _m.accept(&implicit);
    if (extrapolated)
    {
      last = implicit;
      count(implicit);
    }
    if (ok)
      accepted = last;
    return ok;
  }
  /// Material updates as static steps (rate-independent material, no
  /// IMPL-EX) whatever the integrator's dt: the dynamic relaxation of the
  /// static stage.
  bool quasi_static = false;
  fem::MaterialUpdateStats last;     ///< of the last trial
  fem::MaterialUpdateStats accepted; ///< of the last accepted trial
  std::int64_t substepped = 0;       ///< sub-stepped point updates, all trials
  /// return maps and local Newton iterations, all trials
  std::int64_t return_maps = 0, local_iterations = 0;
  /// points that left the elastic fast path and their update time
  /// (core-seconds), all trials
  std::int64_t returned_points = 0;
  double return_map_seconds = 0.0;
  /// Zeroes the counts summed over trials (above).
  void reset_counts()
  {
    substepped = return_maps = local_iterations = returned_points = 0;
    return_map_seconds = 0.0;
  }

protected:
  /// The trial's displacement (system unknowns), kept for the supports.
  void keep_trial(Vec u)
  {
    if (_supports)
      VecCopy(u, _u_trial.vec());
  }
  /// f += K_s u of the last trial.
  void add_supports(Vec f)
  {
    if (_supports)
      MatMultAdd(_supports, _u_trial.vec(), f, f);
  }
  const fem::ConcreteModel& model() const { return _m; }

private:
  Mat _supports = nullptr;
  dolfinx::la::petsc::Vector _u_trial{nullptr, false};
  void count(const fem::MaterialUpdateStats& s)
  {
    substepped += s.substepped;
    return_maps += s.return_maps;
    local_iterations += s.local_iterations;
    returned_points += s.returned_points;
    return_map_seconds += s.return_map_seconds;
  }
  fem::ConcreteModel& _m;
  dolfinx::fem::Function<double> _u;
};
} // namespace damseis::analysis
