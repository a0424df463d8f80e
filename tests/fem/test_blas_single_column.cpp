// fem/blas_single_column.cpp: single-column DGEMM / DTRSM calls forwarded to
// DGEMV / DTRSV. Checked against products and substitutions written out in
// loops here (independent of any BLAS), in every transpose combination,
// with strided operands and the corner cases that must not be forwarded
// (k = 0 and alpha = 0 scale C by beta; alpha != 1 in DTRSM). Tolerance
// 1e-13 relative: rounding of sums of at most 40 terms of size 1. Then a
// MUMPS Cholesky solve in this process must reach the forwarding and give
// the residual of a direct solve (1e-12 relative).
#include "fem_test_support.h"

#include <damseis/linalg/blas_single_column.h>
#include <damseis/linalg/direct_solver.h>
#include <random>
#include <vector>

extern "C"
{
  void dgemm_(const char*, const char*, const int*, const int*, const int*,
              const double*, const double*, const int*, const double*,
              const int*, const double*, double*, const int*, std::size_t,
              std::size_t);
  void dtrsm_(const char*, const char*, const char*, const char*, const int*,
              const int*, const double*, const double*, const int*, double*,
              const int*, std::size_t, std::size_t, std::size_t, std::size_t);
}

namespace
{
std::vector<double> random_vector(std::size_t n, unsigned seed)
{
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> v(n);
  for (double& x : v)
    x = u(g);
  return v;
}

TEST(BlasSingleColumn, GemmWithOneColumnEqualsTheProduct)
{
  const int m = 37, k = 23, n = 1;
  for (const char ta : {'N', 'T'})
  {
    for (const char tb : {'N', 'T'})
    {
      for (const double beta : {0.0, 0.7})
      {
        // Leading dimensions larger than the operands (strided access).
        const int lda = (ta == 'N' ? m : k) + 3, ldb = (tb == 'N' ? k : n) + 2,
                  ldc = m + 5;
        const auto a = random_vector(std::size_t(lda) * (ta == 'N' ? k : m), 1);
        const auto b = random_vector(std::size_t(ldb) * (tb == 'N' ? n : k), 2);
        auto c = random_vector(std::size_t(ldc) * n, 3);
        if (beta == 0.0)
          c[0] = std::numeric_limits<double>::quiet_NaN(); // must not be read
        std::vector<double> ref(m);
        const double alpha = -1.3;
        for (int i = 0; i < m; ++i)
        {
          double s = 0;
          for (int l = 0; l < k; ++l)
          {
            const double ail = ta == 'N' ? a[i + l * lda] : a[l + i * lda];
            const double bl = tb == 'N' ? b[l] : b[l * ldb];
            s += ail * bl;
          }
          ref[i] = alpha * s + (beta == 0.0 ? 0.0 : beta * c[i]);
        }
        const long before = damseis::linalg::blas_single_column_calls();
        dgemm_(&ta, &tb, &m, &n, &k, &alpha, a.data(), &lda, b.data(), &ldb,
               &beta, c.data(), &ldc, 1, 1);
        EXPECT_EQ(damseis::linalg::blas_single_column_calls(), before + 1);
        for (int i = 0; i < m; ++i)
          EXPECT_NEAR(c[i], ref[i], 1e-13 * std::max(1.0, std::abs(ref[i])))
              << ta << tb << " beta " << beta << " row " << i;
      }
    }
  }
}

TEST(BlasSingleColumn, GemmCornerCasesStillScaleByBeta)
{
  // k = 0 and alpha = 0 go to DGEMM (C = beta C), as do two columns.
  const int m = 5, lda = 5, ldb = 5, ldc = 5;
  const double beta = 0.5;
  const auto a = random_vector(25, 4), b = random_vector(25, 5);
  for (const auto& [n, k, alpha] :
       {std::tuple{1, 0, 1.0}, std::tuple{1, 5, 0.0}, std::tuple{2, 5, 1.0}})
  {
    auto c = random_vector(std::size_t(ldc) * n, 6);
    const auto c0 = c;
    const long before = damseis::linalg::blas_single_column_calls();
    dgemm_("N", "N", &m, &n, &k, &alpha, a.data(), &lda, b.data(), &ldb, &beta,
           c.data(), &ldc, 1, 1);
    EXPECT_EQ(damseis::linalg::blas_single_column_calls(), before);
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < m; ++i)
      {
        double s = 0;
        for (int l = 0; l < k; ++l)
          s += a[i + l * lda] * b[l + j * ldb];
        EXPECT_NEAR(c[i + j * ldc], alpha * s + beta * c0[i + j * ldc], 1e-13);
      }
    }
  }
}

TEST(BlasSingleColumn, TrsmWithOneColumnEqualsSubstitution)
{
  const int m = 29, n = 1, lda = 31, ldb = 29;
  auto a = random_vector(std::size_t(lda) * m, 7);
  for (int i = 0; i < m; ++i)
    a[i + i * lda] = 3.0 + std::abs(a[i + i * lda]); // well conditioned
  for (const char uplo : {'L', 'U'})
  {
    for (const char trans : {'N', 'T'})
    {
      for (const char diag : {'N', 'U'})
      {
        for (const double alpha : {1.0, 2.0}) // 2: not forwarded
        {
          const auto b0 = random_vector(m, 8);
          auto x = b0;
          const long before = damseis::linalg::blas_single_column_calls();
          dtrsm_("L", &uplo, &trans, &diag, &m, &n, &alpha, a.data(), &lda,
                 x.data(), &ldb, 1, 1, 1, 1);
          EXPECT_EQ(damseis::linalg::blas_single_column_calls(),
                    before + (alpha == 1.0 ? 1 : 0));
          // op(T) x = alpha b0, T the triangle of a (unit diagonal if 'U').
          for (int i = 0; i < m; ++i)
          {
            double s = 0;
            for (int j = 0; j < m; ++j)
            {
              const bool in = uplo == 'L' ? (trans == 'N' ? j <= i : j >= i)
                                          : (trans == 'N' ? j >= i : j <= i);
              if (!in)
                continue;
              const double tij = i == j && diag == 'U' ? 1.0
                                 : trans == 'N'        ? a[i + j * lda]
                                                       : a[j + i * lda];
              s += tij * x[j];
            }
            EXPECT_NEAR(s, alpha * b0[i], 1e-12)
                << uplo << trans << diag << " alpha " << alpha;
          }
        }
      }
    }
  }
}

TEST(BlasSingleColumn, MumpsSolveReachesTheForwarding)
{
  // 2D Laplacian (5-point, 80 x 80 grid, Dirichlet): fronts large enough
  // for MUMPS to call DGEMM / DTRSM in its solve phase.
  const PetscInt nx = 80, n = nx * nx;
  Mat A;
  MatCreateAIJ(MPI_COMM_WORLD, PETSC_DECIDE, PETSC_DECIDE, n, n, 5, nullptr, 4,
               nullptr, &A);
  PetscInt lo, hi;
  MatGetOwnershipRange(A, &lo, &hi);
  for (PetscInt r = lo; r < hi; ++r)
  {
    const PetscInt i = r % nx, j = r / nx;
    MatSetValue(A, r, r, 4.0, INSERT_VALUES);
    if (i > 0)
      MatSetValue(A, r, r - 1, -1.0, INSERT_VALUES);
    if (i < nx - 1)
      MatSetValue(A, r, r + 1, -1.0, INSERT_VALUES);
    if (j > 0)
      MatSetValue(A, r, r - nx, -1.0, INSERT_VALUES);
    if (j < nx - 1)
      MatSetValue(A, r, r + nx, -1.0, INSERT_VALUES);
  }
  MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY);
  Vec x, b, r;
  MatCreateVecs(A, &x, &b);
  VecDuplicate(b, &r);
  VecSetRandom(b, nullptr);
  {
    damseis::linalg::DirectSolver solver(MPI_COMM_WORLD,
                                         damseis::linalg::Factorization::mumps);
    solver.factorize(A);
    const long before = damseis::linalg::blas_single_column_calls();
    solver.solve(b, x);
    EXPECT_GT(damseis::linalg::blas_single_column_calls(), before);
    MatMult(A, x, r);
    VecAXPY(r, -1.0, b);
    PetscReal rn, bn;
    VecNorm(r, NORM_2, &rn);
    VecNorm(b, NORM_2, &bn);
    EXPECT_LT(rn / bn, 1e-12);
  }
  VecDestroy(&x);
  VecDestroy(&b);
  VecDestroy(&r);
  MatDestroy(&A);
}
} // namespace
