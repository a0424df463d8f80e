// dynamics::TangentSolver (Newton directions on reused factorisations),
// against independent references:
//  1. GMRES preconditioned by the factors of A0 on J = A0 + E, E of rank k,
//     reaches the exact solution in at most k + 1 iterations (the
//     preconditioned operator I + A0^{-1} E has at most k + 1 distinct
//     eigenvalues: finite termination of GMRES, Saad 2003, Prop. 6.18 / the
//     minimal polynomial argument); checked against a direct LU solve of J
//     (relative difference 1e-8, the requested GMRES tolerance 1e-10 times
//     the condition number of J, about 1e2 here).
//  2. When GMRES would need more iterations than allowed, J is factorised:
//     the direction equals the direct solve, and the next call on the same J
//     converges in one iteration (its own factors are exact).
//  3. Factors of another step length (level) are not used as the
//     preconditioner.
#include "fem_test_support.h"

#include <damseis/dynamics/tangent_solver.h>
#include <damseis/linalg/direct_solver.h>

namespace
{
using namespace damseis::test;
using damseis::dynamics::Direction;
using damseis::dynamics::TangentSolver;
using damseis::linalg::DirectSolver;
using damseis::linalg::Factorization;

/// A0: the 1D stiffness + mass tridiagonal matrix (SPD) of n unknowns;
/// with `rank` > 0, a symmetric indefinite perturbation of that rank: the
/// diagonal at rows 7, 14, ... (spread over the ranks' blocks) changed by
/// -3 times its value (a "softening" point).
Mat matrix(PetscInt n, int rank)
{
  Mat A;
  MatCreateAIJ(MPI_COMM_WORLD, PETSC_DECIDE, PETSC_DECIDE, n, n, 3, nullptr, 2,
               nullptr, &A);
  PetscInt lo, hi;
  MatGetOwnershipRange(A, &lo, &hi);
  for (PetscInt i = lo; i < hi; ++i)
  {
    double d = 2.0 + 0.01;
    if (rank > 0 && i % 7 == 0 && i / 7 >= 1 && i / 7 <= rank)
      d -= 3.0 * d;
    MatSetValue(A, i, i, d, INSERT_VALUES);
    if (i > 0)
      MatSetValue(A, i, i - 1, -1.0, INSERT_VALUES);
    if (i + 1 < n)
      MatSetValue(A, i, i + 1, -1.0, INSERT_VALUES);
  }
  MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY);
  return A;
}

double relative_difference(Vec x, Vec y)
{
  Vec d;
  VecDuplicate(x, &d);
  VecWAXPY(d, -1.0, y, x);
  const double r = norm2(d) / norm2(y);
  VecDestroy(&d);
  return r;
}

struct Problem
{
  static constexpr PetscInt n = 400;
  static constexpr int rank = 6;
  PMat A0 = own(matrix(n, 0));
  PMat J = own(matrix(n, rank));
  PVec R = make_rhs();
  PVec exact = make_rhs();
  DirectSolver initial{MPI_COMM_WORLD, Factorization::automatic};
  DirectSolver lu{MPI_COMM_WORLD, Factorization::mumps};

  Problem()
  {
    initial.factorize(A0.mat());
    lu.factorize_lu(J.mat());
    lu.solve(R.vec(), exact.vec());
  }
  PVec make_rhs()
  {
    Vec b;
    MatCreateVecs(A0.mat(), &b, nullptr);
    PetscInt lo, hi;
    VecGetOwnershipRange(b, &lo, &hi);
    for (PetscInt i = lo; i < hi; ++i)
      VecSetValue(b, i, std::sin(0.05 * i) + 0.1, INSERT_VALUES);
    VecAssemblyBegin(b);
    VecAssemblyEnd(b);
    return own(b);
  }
};

TEST(TangentSolver, GmresOnReusedFactorsTerminatesAfterRankPlusOne)
{
  Problem p;
  TangentSolver solver(MPI_COMM_WORLD, 1e-10, 60);
  PVec du = p.make_rhs();
  const Direction d =
      solver.solve(p.J.mat(), p.initial, 0, p.R.vec(), du.vec(), 0.0);
  ASSERT_EQ(d, Direction::krylov);
  const double err = relative_difference(du.vec(), p.exact.vec());
  print_metric(fmt("GMRES iterations ", solver.last_krylov_iterations(),
                   " for a rank-", Problem::rank, " change; difference ", err));
  EXPECT_LE(solver.last_krylov_iterations(), Problem::rank + 1);
  EXPECT_LT(err, 1e-8);
  EXPECT_EQ(solver.last_factor_seconds(), 0.0);
}

TEST(TangentSolver, FactorisesWhenGmresWouldTakeLongerThenReusesThose)
{
  Problem p;
  TangentSolver solver(MPI_COMM_WORLD, 1e-10, Problem::rank - 3);
  PVec du = p.make_rhs();
  ASSERT_EQ(solver.solve(p.J.mat(), p.initial, 0, p.R.vec(), du.vec(), 0.0),
            Direction::factorized);
  EXPECT_LT(relative_difference(du.vec(), p.exact.vec()), 1e-12);
  // Same matrix, same level: its own factors make GMRES exact at once.
  ASSERT_EQ(solver.solve(p.J.mat(), p.initial, 0, p.R.vec(), du.vec(), 0.0),
            Direction::krylov);
  EXPECT_EQ(solver.last_krylov_iterations(), 1);
  EXPECT_LT(relative_difference(du.vec(), p.exact.vec()), 1e-10);
  // Another level: the stored factors belong to a different matrix and are
  // not used; from A0's factors GMRES needs the rank + 1 iterations again,
  // more than allowed, so J is factorised afresh.
  ASSERT_EQ(solver.solve(p.J.mat(), p.initial, 1, p.R.vec(), du.vec(), 0.0),
            Direction::factorized);
  EXPECT_EQ(solver.last_krylov_iterations(), Problem::rank - 3);
}

TEST(TangentSolver, ZeroIterationsMeansExactNewton)
{
  Problem p;
  TangentSolver solver(MPI_COMM_WORLD, 1e-2, 0);
  PVec du = p.make_rhs();
  ASSERT_EQ(solver.solve(p.J.mat(), p.initial, 0, p.R.vec(), du.vec(), 0.0),
            Direction::factorized);
  EXPECT_EQ(solver.last_krylov_iterations(), 0);
  EXPECT_LT(relative_difference(du.vec(), p.exact.vec()), 1e-12);
}
} // namespace
