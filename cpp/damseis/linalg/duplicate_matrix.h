// A copy of a PETSc matrix that multiplies as fast as the original.
#pragma once

#include <petscmat.h>

namespace damseis::linalg
{
/// MatDuplicate(A, option), keeping the block-size-specialised products of
/// (Seq/MPI)BAIJ matrices. PETSc 3.18's MatDuplicate of a BAIJ matrix
/// installs the generic MatMult_SeqBAIJ_N (one BLAS DGEMV per block row)
/// instead of the unrolled kernel of its block size: measured 3.0-3.5x
/// slower MatMult for bs = 2 on 17,720 rows, serial and on 2 ranks. The
/// products of the copy (and of its diagonal and off-diagonal blocks in
/// parallel) are set to those of A; all other types are returned as
/// MatDuplicate gives them.
Mat duplicate_matrix(Mat A, MatDuplicateOption option);
} // namespace damseis::linalg
