// Seismic input as a load of the engine: the relative (base-acceleration)
// formulation.
#pragma once

#include "seismic_settings.h"
#include <damseis/engine/parts.h>
#include <damseis/fem/elastic_model.h>
#include <dolfinx/la/petsc.h>
#include <vector>

namespace damseis::analysis
{
/// The ground-acceleration load of the relative formulation,
/// f(t_k) = F - M sum_c r_c a_gc(t_k), for the active components of the
/// settings, F a sustained load (the static loads, where the state is total)
/// or zero; with `tie` the influence vectors are restricted to the tied
/// unknowns (M is then the reduced mass).
class GroundMotionLoad : public engine::DynamicLoad
{
public:
  /// `sustained`: F (copied), or null for none.
  GroundMotionLoad(const fem::ElasticModel& fe, const SeismicSettings& s, Mat M,
                   Mat tie = nullptr, Vec sustained = nullptr);
  void assemble(int k, Vec f) const override;
  /// The acceleration at rest under the ground motion at t = 0,
  /// a = -sum_c r_c a_gc(0): it satisfies M a = f(0) - F also where M is
  /// singular (massless foundation, fixed dofs).
  void initial_acceleration(Vec a) const override;

private:
  const SeismicSettings& _s;
  std::vector<int> _active;
  std::vector<dolfinx::la::petsc::Vector> _influence, _load;
  dolfinx::la::petsc::Vector _sustained{nullptr, false};
};
} // namespace damseis::analysis
