#include "tied_concrete_system.h"
#include <damseis/fem/tied_dofs.h>

namespace damseis::analysis
{
TiedConcreteSystem::TiedConcreteSystem(fem::ConcreteModel& m, Mat tie, Mat K0)
    : ConcreteSystem(m), _P(tie), _u_full(linalg::row_vector(tie)),
      _f_full(linalg::row_vector(tie)), _W(nullptr, false)
{
  Mat W;
  MatDuplicate(K0, MAT_DO_NOT_COPY_VALUES, &W);
  _W = dolfinx::la::petsc::Matrix(W, false);
}

bool TiedConcreteSystem::trial(Vec u, double dt)
{
  MatMult(_P, u, _u_full.vec());
  return ConcreteSystem::trial(_u_full.vec(), dt);
}

void TiedConcreteSystem::internal_force(Vec f)
{
  ConcreteSystem::internal_force(_f_full.vec());
  MatMultTranspose(_P, _f_full.vec(), f);
}

void TiedConcreteSystem::add_tangent_change(Mat A, double scale)
{
  MatZeroEntries(_W.mat());
  ConcreteSystem::add_tangent_change(_W.mat(), scale);
  // P^T W P has the pattern of P^T K0 P, the pattern of A.
  dolfinx::la::petsc::Matrix R(fem::reduce_to_tied(_W.mat(), _P), false);
  MatAXPY(A, 1.0, R.mat(), SUBSET_NONZERO_PATTERN);
  MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY);
}

void TiedConcreteSystem::extrapolation_change(Vec f)
{
  ConcreteSystem::extrapolation_change(_f_full.vec());
  MatMultTranspose(_P, _f_full.vec(), f);
}
} // namespace damseis::analysis
