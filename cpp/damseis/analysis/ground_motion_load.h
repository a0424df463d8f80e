// Seismic input as a load: the relative (base-acceleration) formulation.
#pragma once

#include "seismic_settings.h"
#include <damseis/fem/elastic_model.h>
#include <dolfinx/la/petsc.h>
#include <vector>

namespace damseis::analysis
{
/// The ground-acceleration load of the relative formulation,
/// f(t_k) = base - M sum_c r_c a_gc(t_k), for the active components of the
/// settings; with `tie` the influence vectors are restricted to the tied
/// unknowns (M is then the reduced mass).
class GroundMotionLoad
{
public:
  GroundMotionLoad(const fem::ElasticModel& fe, const SeismicSettings& s, Mat M,
                   Mat tie = nullptr);
  /// f = base (or 0 if base is null) + the ground-motion load at step k.
  void assemble(int k, Vec base, Vec f) const;
  /// The acceleration at rest under the ground motion at t = 0,
  /// a = -sum_c r_c a_gc(0): it satisfies M a = f(0) also where M is
  /// singular (massless foundation, fixed dofs).
  void initial_acceleration(Vec a) const;

private:
  const SeismicSettings& _s;
  std::vector<int> _active;
  std::vector<dolfinx::la::petsc::Vector> _influence, _load;
};
} // namespace damseis::analysis
