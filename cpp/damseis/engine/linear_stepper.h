// The stepper of a linear model: HHT/Newmark (dynamics::LinearNewmark) with
// its effective matrix factorised once.
#pragma once

#include "parts.h"
#include <array>
#include <damseis/dynamics/newmark.h>
#include <dolfinx/la/petsc.h>

namespace damseis::engine
{
class LinearStepper : public Stepper
{
public:
  /// M, K, the extra damping matrices and the constrained solve: see
  /// dynamics::LinearNewmark. The initial displacement (start with u0
  /// null) is `u_start` (copied), or zero if null.
  LinearStepper(
      Mat M, Mat K, dynamics::RayleighDamping damping,
      dynamics::TimeScheme scheme, linalg::Factorization factorization,
      const std::vector<Mat>& extra_damping = {},
      std::shared_ptr<dynamics::ConstrainedSolve> constrained = nullptr,
      Vec u_start = nullptr);

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
  const dynamics::EnergyBalance* energy() const override
  {
    return &_newmark.energy();
  }

protected:
  dynamics::LinearNewmark& newmark() { return _newmark; }

private:
  Mat _K;
  dynamics::LinearNewmark _newmark;
  dolfinx::la::petsc::Vector _u_start{nullptr, false}; ///< null: zero
  /// u, v, a read from a checkpoint until resume().
  std::array<dolfinx::la::petsc::Vector, 3> _restored;
  /// The constraint force and the impulse of the checkpoint.
  dolfinx::la::petsc::Vector _restored_r{nullptr, false},
      _restored_impulse{nullptr, false};
};
} // namespace damseis::engine
