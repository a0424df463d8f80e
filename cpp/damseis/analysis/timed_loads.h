// Loads with a time history (tractions on the user's groups) on top of the
// seismic input: f(t_k) = f_base(t_k) + sum_i h_i(t_k) F_i.
#pragma once

#include <damseis/engine/parts.h>
#include <dolfinx/la/petsc.h>
#include <vector>

namespace damseis::analysis
{
/// A load vector (full space, zero at fixed dofs) and its factor per step
/// (starting at 0: the model starts at rest).
struct TimedLoad
{
  Vec load = nullptr;
  std::vector<double> history;
};

class LoadWithTimedTerms : public engine::DynamicLoad
{
public:
  /// `base` must outlive this load; the terms are copied (restricted to
  /// the tied unknowns with `tie`).
  LoadWithTimedTerms(const engine::DynamicLoad& base,
                     const std::vector<TimedLoad>& terms, Mat tie = nullptr);
  void assemble(int k, Vec f) const override;
  /// The base's: the terms vanish at t = 0.
  void initial_acceleration(Vec a) const override
  {
    _base.initial_acceleration(a);
  }

private:
  const engine::DynamicLoad& _base;
  std::vector<dolfinx::la::petsc::Vector> _loads;
  std::vector<std::vector<double>> _histories;
};
} // namespace damseis::analysis
