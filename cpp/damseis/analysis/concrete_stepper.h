// The stepper of a model with nonlinear concrete: HHT with Newton per step
// (dynamics::NonlinearNewmark) on the concrete system, with contact joints
// as a constraint of the Newton iteration if any (joint::NonlinearContact),
// the material (and contact) state in checkpoints, and the Newton
// statistics of the time history.
#pragma once

#include "concrete_system.h"
#include <array>
#include <damseis/engine/parts.h>
#include <damseis/joint/nonlinear_contact.h>
#include <dolfinx/la/petsc.h>
#include <memory>
#include <nlohmann/json.hpp>

namespace damseis::analysis
{
/// Newton work summed over the steps of a time history (checkpointed, so a
/// restarted run reports all steps).
struct NewtonTotals
{
  double iterations = 0, tangent_factorizations = 0, cuts = 0,
         max_iterations_in_a_step = 0, max_inelastic_points = 0,
         krylov_iterations = 0;
  /// Seconds in residuals, tangent assembly, factorisations, direction
  /// solves.
  double seconds_residual = 0, seconds_tangent = 0, seconds_factorization = 0,
         seconds_solve = 0;
  /// Sub-stepped point updates, return maps, local Newton iterations,
  /// points that left the elastic fast path and the core-seconds of their
  /// updates.
  double substepped = 0, return_maps = 0, local_iterations = 0,
         returned_points = 0, return_map_seconds = 0;
  /// IMPL-EX equilibrium error: sum of squares, largest, its time.
  double implex_error_squares = 0, implex_error_max = 0, implex_error_time = 0;

  void add(const dynamics::StepReport& r, const ConcreteSystem& system,
           double t);
  std::vector<double> to_array() const;
  /// Throws std::runtime_error if `a` has more values than the totals.
  void from_array(std::vector<double> a);
};

class ConcreteStepper : public engine::Stepper
{
public:
  /// `u_static`, `f_int_static`: the displacement and internal force of the
  /// static stage (copied), where the run starts (the state is total).
  /// M, K0 and the system (and `extra_damping`: boundary dashpots, or
  /// null) must outlive the stepper.
  ConcreteStepper(Mat M, Mat K0, dynamics::RayleighDamping damping,
                  dynamics::TimeScheme scheme, ConcreteSystem& system,
                  fem::ConcreteModel& model, dynamics::NewtonSettings newton,
                  linalg::Factorization factorization, Vec u_static,
                  Vec f_int_static, Mat extra_damping = nullptr);

  Vec create_vector() const override;
  void start(Vec u0, Vec v0, Vec a0, Vec f0) override;
  dynamics::StepReport step(Vec f) override;
  Vec u() const override { return _newmark.u(); }
  Vec v() const override { return _newmark.v(); }
  Vec a() const override { return _newmark.a(); }
  void save(engine::Arrays& arrays) const override;
  void restore(const engine::CheckpointData& data) override;
  void resume(Vec f) override;
  std::string progress_note(const dynamics::StepReport& r) const override;
  std::string solver_name() const override { return _newmark.solver().name(); }
  double factor_seconds() const override
  {
    return _newmark.solver().factor_seconds();
  }
  const NewtonTotals& totals() const { return _totals; }
  /// Contact joints solved in every step (before start()); their state is
  /// the static stage's.
  void set_contact(std::shared_ptr<joint::NonlinearContact> contact);
  /// The contact joints (null: none).
  const joint::NonlinearContact* contact() const { return _contact.get(); }
  /// The implicit-explicit partition of a transmitting boundary (before
  /// start()); its history (u one step back) goes into checkpoints.
  void set_partition(dynamics::Partition partition);

private:
  Mat _K0;
  ConcreteSystem& _system;
  fem::ConcreteModel& _model;
  dynamics::NonlinearNewmark _newmark;
  dolfinx::la::petsc::Vector _u_static, _f_int_static;
  /// u, v, a, f_int read from a checkpoint until resume().
  std::array<dolfinx::la::petsc::Vector, 4> _restored;
  bool _partitioned = false;
  /// u one step back read from a checkpoint (a partition) until resume().
  /// The transmitting boundary's history: u, v, a one step back.
  std::array<dolfinx::la::petsc::Vector, 3> _restored_prev{
      dolfinx::la::petsc::Vector(nullptr, false),
      dolfinx::la::petsc::Vector(nullptr, false),
      dolfinx::la::petsc::Vector(nullptr, false)};
  NewtonTotals _totals;
  int _step = 0;
  std::shared_ptr<joint::NonlinearContact> _contact;
};
} // namespace damseis::analysis
