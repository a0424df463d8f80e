#include "initial_motion.h"
#include <damseis/fem/tied_dofs.h>
#include <damseis/linalg/duplicate_matrix.h>
#include <damseis/linalg/petsc_vectors.h>

namespace damseis::analysis
{
using dolfinx::la::petsc::Matrix;
using dolfinx::la::petsc::Vector;

InitialMotion initial_motion(MPI_Comm comm, Mat M, Mat K,
                             const dynamics::RayleighDamping& damping,
                             const engine::DynamicLoad& load, Vec v0_full,
                             Mat tie, linalg::Factorization factorization)
{
  InitialMotion s;
  if (tie)
    s.v0 = Vector(fem::restrict_to_tied(tie, v0_full), false);
  else
  {
    s.v0 = linalg::column_vector(K);
    VecCopy(v0_full, s.v0.vec());
  }
  s.a0 = linalg::column_vector(K);
  load.initial_acceleration(s.a0.vec());
  // r = -C v0.
  Vector r = linalg::column_vector(K), Kv = linalg::column_vector(K);
  MatMult(M, s.v0.vec(), r.vec());
  MatMult(K, s.v0.vec(), Kv.vec());
  VecAXPBY(r.vec(), -damping.b_stiffness, -damping.a_mass, Kv.vec());
  // M with 1 on the diagonal of the rows without mass, and r = 0 there.
  Mat Mr = linalg::duplicate_matrix(M, MAT_COPY_VALUES);
  Matrix M_reg(Mr, false);
  Vector d = linalg::column_vector(K);
  MatGetDiagonal(Mr, d.vec());
  double* dd = nullptr;
  double* rr = nullptr;
  PetscInt n = 0;
  VecGetLocalSize(d.vec(), &n);
  VecGetArray(d.vec(), &dd);
  VecGetArray(r.vec(), &rr);
  for (PetscInt i = 0; i < n; ++i)
  {
    if (dd[i] == 0.0)
    {
      dd[i] = 1.0;
      rr[i] = 0.0;
    }
  }
  VecRestoreArray(r.vec(), &rr);
  VecRestoreArray(d.vec(), &dd);
  MatDiagonalSet(Mr, d.vec(), INSERT_VALUES);
  linalg::DirectSolver solver(comm, factorization);
  solver.factorize(Mr);
  Vector da = linalg::column_vector(K);
  solver.solve(r.vec(), da.vec());
  VecAXPY(s.a0.vec(), 1.0, da.vec());
  return s;
}
} // namespace damseis::analysis
