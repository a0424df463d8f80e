#include "duplicate_matrix.h"

namespace damseis::linalg
{
namespace
{
bool is_type(Mat A, MatType type)
{
  PetscBool same = PETSC_FALSE;
  PetscObjectTypeCompare(reinterpret_cast<PetscObject>(A), type, &same);
  return same == PETSC_TRUE;
}

void copy_products(Mat from, Mat to)
{
  for (MatOperation op : {MATOP_MULT, MATOP_MULT_ADD, MATOP_MULT_TRANSPOSE,
                          MATOP_MULT_TRANSPOSE_ADD})
  {
    void (*f)(void) = nullptr;
    MatGetOperation(from, op, &f);
    MatSetOperation(to, op, f);
  }
}
} // namespace

Mat duplicate_matrix(Mat A, MatDuplicateOption option)
{
  Mat B = nullptr;
  MatDuplicate(A, option, &B);
  if (is_type(A, MATSEQBAIJ))
    copy_products(A, B);
  else if (is_type(A, MATMPIBAIJ))
  {
    Mat a_diag, a_off, b_diag, b_off;
    const PetscInt* colmap = nullptr;
    MatMPIBAIJGetSeqBAIJ(A, &a_diag, &a_off, &colmap);
    MatMPIBAIJGetSeqBAIJ(B, &b_diag, &b_off, &colmap);
    copy_products(a_diag, b_diag);
    copy_products(a_off, b_off);
  }
  return B;
}
} // namespace damseis::linalg
