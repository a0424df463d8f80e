// The concrete system on the tied unknowns of bonded joints (u = P u_r,
// also P2 contact's midside constraints): the material sees the full
// displacement P u_r; forces and tangents are restricted, f_r = P^T f,
// A_r += P^T (K_T - K0) P. The tangent change is reduced cell by cell
// (P's rows are node blocks with scalar weights: a node follows one node,
// or a mean of nodes), so its cost stays proportional to the cells that
// left the elastic fast path, as without ties.
#pragma once

#include "concrete_system.h"
#include <dolfinx/la/petsc.h>
#include <utility>
#include <vector>

namespace damseis::analysis
{
class TiedConcreteSystem : public ConcreteSystem
{
public:
  /// `tie`: P (all dofs x tied unknowns, block size 3 in both numberings,
  /// scalar weights per block; it must outlive this). Collective.
  TiedConcreteSystem(fem::ConcreteModel& m, Mat tie);
  bool trial(Vec u, double dt) override;
  void internal_force(Vec f) override;
  void add_tangent_change(Mat A, double scale) override;
  void extrapolation_change(Vec f) override;

private:
  Mat _P;
  dolfinx::la::petsc::Vector _u_full, _f_full;
  /// Per local node block of V (owned and ghost): the tied unknowns'
  /// global node blocks it follows and their weights (a row of P).
  std::vector<std::vector<std::pair<PetscInt, double>>> _follows;
};
} // namespace damseis::analysis
