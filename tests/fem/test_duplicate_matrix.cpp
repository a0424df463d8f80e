// linalg::duplicate_matrix: a copy of a BAIJ matrix keeps the original's
// block-size-specialised products (PETSc 3.18's MatDuplicate installs the
// generic one, 3-3.5x slower; see duplicate_matrix.h). Checked:
//  - the copy's MatMult (and, in parallel, that of its diagonal and
//    off-diagonal blocks) is the original's function;
//  - its products equal the original's exactly (same kernel, same values),
//    with copied values and after MatCopy into an empty copy;
// for block sizes 2 and 3 (the 2D and 3D displacement spaces), serial and
// on 2 ranks. And the copy of a matrix with empty block rows (a boundary
// operator: dashpots, springs) writes zeros into those rows of y = A x:
// PETSc 3.18's generic kernel, which plain MatDuplicate installs, leaves
// them unset (one DGEMV per block row, which returns at once for a row
// without columns) unless most rows are empty (compressed rows), and the
// 3D viscous-spring runs diverged on it.
#include "fem_test_support.h"

#include <damseis/linalg/duplicate_matrix.h>

namespace
{
using namespace damseis::test;
using damseis::linalg::duplicate_matrix;

/// A block tridiagonal-like BAIJ matrix with 5 block neighbours per block
/// row and distinct values.
Mat baij(PetscInt block_rows, PetscInt bs)
{
  Mat A;
  MatCreateBAIJ(MPI_COMM_WORLD, bs, PETSC_DECIDE, PETSC_DECIDE, block_rows * bs,
                block_rows * bs, 5, nullptr, 5, nullptr, &A);
  PetscInt lo, hi;
  MatGetOwnershipRange(A, &lo, &hi);
  std::vector<double> v(bs * bs);
  for (PetscInt i = lo / bs; i < hi / bs; ++i)
  {
    for (PetscInt k : {-41, -1, 0, 1, 41})
    {
      const PetscInt j = i + k;
      if (j < 0 || j >= block_rows)
        continue;
      for (PetscInt e = 0; e < bs * bs; ++e)
        v[e] = (k == 0 ? 10.0 : -1.0) + 0.01 * e + 1e-4 * (i % 13);
      MatSetValuesBlocked(A, 1, &i, 1, &j, v.data(), INSERT_VALUES);
    }
  }
  MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY);
  return A;
}

/// The same with only the first `nonempty` of every 10 block rows set
/// (block tridiagonal among them): the pattern of a boundary operator.
Mat baij_with_empty_rows(PetscInt block_rows, PetscInt bs, PetscInt nonempty)
{
  Mat A;
  MatCreateBAIJ(MPI_COMM_WORLD, bs, PETSC_DECIDE, PETSC_DECIDE, block_rows * bs,
                block_rows * bs, 3, nullptr, 3, nullptr, &A);
  PetscInt lo, hi;
  MatGetOwnershipRange(A, &lo, &hi);
  std::vector<double> v(bs * bs, 1.0);
  for (PetscInt i = lo / bs; i < hi / bs; ++i)
  {
    if (i % 10 >= nonempty)
      continue;
    for (PetscInt j : {i - 1, i, i + 1})
      if (j >= 0 && j < block_rows)
        MatSetValuesBlocked(A, 1, &i, 1, &j, v.data(), INSERT_VALUES);
  }
  MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY);
  return A;
}

/// max |y| after y = 1, y = A 0: nonzero where a product left y unset.
double stale_after_product(Mat A)
{
  Vec x, y;
  MatCreateVecs(A, &x, &y);
  VecSet(x, 0.0);
  VecSet(y, 1.0);
  MatMult(A, x, y);
  double stale = 0.0;
  VecNorm(y, NORM_INFINITY, &stale);
  VecDestroy(&x);
  VecDestroy(&y);
  return stale;
}

using Op = void (*)(void);
Op mult_of(Mat A)
{
  Op f = nullptr;
  MatGetOperation(A, MATOP_MULT, &f);
  return f;
}

/// MatMult of the (diagonal block of the) matrix: the function PETSc runs.
Op local_mult_of(Mat A)
{
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size == 1)
    return mult_of(A);
  Mat diag, off;
  const PetscInt* colmap;
  MatMPIBAIJGetSeqBAIJ(A, &diag, &off, &colmap);
  return mult_of(diag);
}

double product_difference(Mat A, Mat B)
{
  Vec x, ya, yb;
  MatCreateVecs(A, &x, &ya);
  VecDuplicate(ya, &yb);
  VecSetRandom(x, nullptr);
  MatMult(A, x, ya);
  MatMult(B, x, yb);
  VecAXPY(yb, -1.0, ya);
  const double d = norm2(yb) / norm2(ya);
  for (Vec* v : {&x, &ya, &yb})
    VecDestroy(v);
  return d;
}

TEST(DuplicateMatrix, KeepsTheBlockSizeProducts)
{
  for (PetscInt bs : {2, 3})
  {
    Mat A = baij(500, bs);
    Mat plain;
    MatDuplicate(A, MAT_COPY_VALUES, &plain);
    print_metric(fmt("bs ", bs, ": plain MatDuplicate keeps MatMult: ",
                     local_mult_of(plain) == local_mult_of(A) ? "yes" : "no"));
    Mat B = duplicate_matrix(A, MAT_COPY_VALUES);
    EXPECT_EQ(local_mult_of(B), local_mult_of(A)) << "bs " << bs;
    EXPECT_EQ(product_difference(A, B), 0.0) << "bs " << bs;
    Mat C = duplicate_matrix(A, MAT_DO_NOT_COPY_VALUES);
    MatCopy(A, C, SAME_NONZERO_PATTERN);
    EXPECT_EQ(local_mult_of(C), local_mult_of(A)) << "bs " << bs;
    EXPECT_EQ(product_difference(A, C), 0.0) << "bs " << bs;
    for (Mat* m : {&A, &plain, &B, &C})
      MatDestroy(m);
  }
}
} // namespace

namespace
{
TEST(DuplicateMatrix, CopyOfABoundaryOperatorZeroesItsEmptyRows)
{
  for (PetscInt bs : {2, 3})
    for (PetscInt nonempty : {1, 5, 9})
    {
      Mat A = baij_with_empty_rows(1000, bs, nonempty);
      Mat plain;
      MatDuplicate(A, MAT_COPY_VALUES, &plain);
      print_metric(fmt("bs ", bs, ", ", nonempty,
                       "0% of the rows set: plain MatDuplicate leaves y ",
                       stale_after_product(plain) == 0.0 ? "zeroed" : "unset",
                       " in the empty rows"));
      Mat B = duplicate_matrix(A, MAT_COPY_VALUES);
      EXPECT_EQ(stale_after_product(A), 0.0);
      EXPECT_EQ(stale_after_product(B), 0.0) << "bs " << bs << ", " << nonempty;
      EXPECT_EQ(product_difference(A, B), 0.0);
      for (Mat* m : {&A, &plain, &B})
        MatDestroy(m);
    }
}
} // namespace
