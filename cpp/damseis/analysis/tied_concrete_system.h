// The concrete system on the tied unknowns of bonded joints (u = P u_r):
// the material sees the full displacement P u_r; forces and tangents are
// restricted, f_r = P^T f, A_r += P^T (K_T - K0) P.
#pragma once

#include "concrete_system.h"
#include <dolfinx/la/petsc.h>

namespace damseis::analysis
{
class TiedConcreteSystem : public ConcreteSystem
{
public:
  /// `tie`: P (all dofs x tied unknowns); `K0`: the full initial stiffness
  /// (its pattern holds every tangent change). Both must outlive this.
  TiedConcreteSystem(fem::ConcreteModel& m, Mat tie, Mat K0);
  bool trial(Vec u, double dt) override;
  void internal_force(Vec f) override;
  void add_tangent_change(Mat A, double scale) override;
  void extrapolation_change(Vec f) override;

private:
  Mat _P;
  dolfinx::la::petsc::Vector _u_full, _f_full;
  dolfinx::la::petsc::Matrix _W; ///< full-size work matrix (K0's pattern)
};
} // namespace damseis::analysis
