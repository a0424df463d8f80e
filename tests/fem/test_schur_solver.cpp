// linalg::SchurSolver (MUMPS with a centralised Schur complement), checked
// against dense linear algebra on the same matrix (Eigen, every rank):
//  - S equals A_ss - A_si A_ii^-1 A_is;
//  - condense, S x_s = y, expand solves A x = b;
//  - expand with an arbitrary x_s gives x_i = A_ii^-1 (b_i - A_is x_s);
// for AIJ and BAIJ (block size 3) storage, serial and on 2 ranks.
// Tolerance 1e-10 relative: both sides are direct solves of a matrix of
// condition number about 20 (diagonally dominant), so round-off is ~1e-14.
#include "fem_test_support.h"

#include <damseis/linalg/schur_solver.h>

namespace
{
using namespace damseis::test;
using damseis::linalg::SchurSolver;

constexpr PetscInt N = 3 * 120; // unknowns
constexpr PetscInt band = 17;   // the grid-like second neighbour

double entry(PetscInt i, PetscInt j)
{
  if (i == j)
    return 4.5 + 0.01 * static_cast<double>(i % 7);
  const PetscInt d = std::abs(i - j);
  if (d == 1 || d == band)
    return -1.0 - 0.001 * static_cast<double>((i + j) % 5);
  return 0.0;
}

Mat matrix(bool blocked)
{
  Mat A;
  if (blocked)
  {
    MatCreateBAIJ(MPI_COMM_WORLD, 3, PETSC_DECIDE, PETSC_DECIDE, N, N, 12,
                  nullptr, 12, nullptr, &A);
  }
  else
  {
    MatCreateAIJ(MPI_COMM_WORLD, PETSC_DECIDE, PETSC_DECIDE, N, N, 5, nullptr,
                 5, nullptr, &A);
  }
  PetscInt lo, hi;
  MatGetOwnershipRange(A, &lo, &hi);
  for (PetscInt i = lo; i < hi; ++i)
  {
    for (PetscInt j : {i - band, i - 1, i, i + 1, i + band})
    {
      if (j < 0 || j >= N)
        continue;
      const double v = entry(i, j);
      MatSetValues(A, 1, &i, 1, &j, &v, INSERT_VALUES);
    }
  }
  MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY);
  return A;
}

Eigen::MatrixXd dense()
{
  Eigen::MatrixXd A(N, N);
  for (PetscInt i = 0; i < N; ++i)
    for (PetscInt j = 0; j < N; ++j)
      A(i, j) = entry(i, j);
  return A;
}

double rhs(PetscInt i)
{
  return std::sin(0.37 * static_cast<double>(i)) + 0.2;
}

/// A vector with values value(i) at the owned global indices.
Vec vector(Mat A, const std::function<double(PetscInt)>& value)
{
  Vec b;
  MatCreateVecs(A, nullptr, &b);
  PetscInt lo, hi;
  VecGetOwnershipRange(b, &lo, &hi);
  for (PetscInt i = lo; i < hi; ++i)
    VecSetValue(b, i, value(i), INSERT_VALUES);
  VecAssemblyBegin(b);
  VecAssemblyEnd(b);
  return b;
}

/// x gathered on every rank.
Eigen::VectorXd everywhere(Vec x)
{
  PetscInt lo, hi;
  VecGetOwnershipRange(x, &lo, &hi);
  Eigen::VectorXd local = Eigen::VectorXd::Zero(N), all(N);
  const double* a;
  VecGetArrayRead(x, &a);
  for (PetscInt i = lo; i < hi; ++i)
    local[i] = a[i - lo];
  VecRestoreArrayRead(x, &a);
  MPI_Allreduce(local.data(), all.data(), N, MPI_DOUBLE, MPI_SUM,
                MPI_COMM_WORLD);
  return all;
}

/// Rows `rows` and columns `cols` of A.
Eigen::MatrixXd block(const Eigen::MatrixXd& A,
                      const std::vector<PetscInt>& rows,
                      const std::vector<PetscInt>& cols)
{
  Eigen::MatrixXd B(rows.size(), cols.size());
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = 0; j < cols.size(); ++j)
      B(i, j) = A(rows[i], cols[j]);
  return B;
}

void check(bool blocked)
{
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  // Schur unknowns spread over both ranks' rows, unsorted.
  const std::vector<PetscInt> s = {301, 7, 8, 9, 150, 151, 200, 359, 0, 42};
  std::vector<PetscInt> interior;
  for (PetscInt i = 0; i < N; ++i)
    if (std::find(s.begin(), s.end(), i) == s.end())
      interior.push_back(i);
  PMat A(matrix(blocked), false);
  SchurSolver solver(A.mat(), s);

  const Eigen::MatrixXd Ad = dense();
  const Eigen::MatrixXd Aii = block(Ad, interior, interior);
  const Eigen::MatrixXd Ais = block(Ad, interior, s);
  const Eigen::LLT<Eigen::MatrixXd> Lii(Aii);
  const Eigen::MatrixXd S_ref =
      block(Ad, s, s) - Ais.transpose() * Lii.solve(Ais);
  const Eigen::MatrixXd& S = solver.schur_complement();
  if (rank == 0)
  {
    ASSERT_EQ(S.rows(), static_cast<Eigen::Index>(s.size()));
    EXPECT_LT((S - S_ref).norm(), 1e-10 * S_ref.norm());
  }
  else
  {
    EXPECT_EQ(S.size(), 0);
  }

  // A whole solve through the dense problem on s.
  PVec b(vector(A.mat(), rhs), false), x(vector(A.mat(), rhs), false);
  Eigen::VectorXd y;
  solver.condense(b.vec(), y);
  Eigen::VectorXd xs;
  if (rank == 0)
    xs = S.llt().solve(y);
  solver.expand(xs, x.vec());
  Eigen::VectorXd bd(N);
  for (PetscInt i = 0; i < N; ++i)
    bd[i] = rhs(i);
  const Eigen::VectorXd x_ref = Ad.llt().solve(bd);
  const Eigen::VectorXd xa = everywhere(x.vec());
  EXPECT_LT((xa - x_ref).norm(), 1e-10 * x_ref.norm());

  // Expansion of an arbitrary x_s (the interior equations only).
  solver.condense(b.vec(), y);
  Eigen::VectorXd xs_any(s.size());
  for (std::size_t k = 0; k < s.size(); ++k)
    xs_any[k] = 0.1 * static_cast<double>(k) - 0.3;
  solver.expand(rank == 0 ? xs_any : Eigen::VectorXd(), x.vec());
  const Eigen::VectorXd xb = everywhere(x.vec());
  Eigen::VectorXd bi(interior.size());
  for (std::size_t k = 0; k < interior.size(); ++k)
    bi[k] = rhs(interior[k]);
  const Eigen::VectorXd xi_ref = Lii.solve(bi - Ais * xs_any);
  for (std::size_t k = 0; k < interior.size(); ++k)
    EXPECT_NEAR(xb[interior[k]], xi_ref[k], 1e-10 * xi_ref.norm());
  for (std::size_t k = 0; k < s.size(); ++k)
    EXPECT_NEAR(xb[s[k]], xs_any[k], 1e-12);
}

TEST(SchurSolver, MatchesDenseAlgebraAij)
{
  check(false);
}
TEST(SchurSolver, MatchesDenseAlgebraBaij)
{
  check(true);
}
} // namespace
