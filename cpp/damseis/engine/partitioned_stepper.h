// The stepper of a linear model with an explicit band next to a
// transmitting boundary: the Hughes-Liu partition of Newmark's method
// (dynamics::PartitionedNewmark), its effective matrix factorised once.
#pragma once

#include "parts.h"
#include <array>
#include <damseis/dynamics/partitioned_newmark.h>
#include <dolfinx/la/petsc.h>

namespace damseis::engine
{
class PartitionedStepper : public Stepper
{
public:
  /// See dynamics::PartitionedNewmark. Runs start at rest.
  PartitionedStepper(Mat M, Mat K, Mat K_implicit,
                     dynamics::RayleighDamping damping, double dt,
                     linalg::Factorization factorization,
                     std::shared_ptr<dynamics::PrescribedMotion> prescribed,
                     double b_explicit = 0.0);

  Vec create_vector() const override;
  void start(Vec u0, Vec v0, Vec a0, Vec f0) override;
  dynamics::StepReport step(Vec f) override;
  Vec u() const override { return _newmark.u(); }
  Vec v() const override { return _newmark.v(); }
  Vec a() const override { return _newmark.a(); }
  void save(Arrays& arrays) const override;
  void restore(const CheckpointData& data) override;
  void resume(Vec f) override;
  std::string solver_name() const override { return _newmark.solver_name(); }
  double factor_seconds() const override { return _newmark.factor_seconds(); }
  /// The steps' time split into boundary, solve, band and the rest.
  const dynamics::StepSeconds& step_seconds() const
  {
    return _newmark.step_seconds();
  }
  const dynamics::EnergyBalance* energy() const override
  {
    return &_newmark.energy();
  }

private:
  Mat _K;
  dynamics::PartitionedNewmark _newmark;
  int _step = 0; ///< the step of the state
  /// u, v, a and the displacement one step back, read from a checkpoint
  /// until resume().
  std::array<dolfinx::la::petsc::Vector, 6> _restored;
};
} // namespace damseis::engine
