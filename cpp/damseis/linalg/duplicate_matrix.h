// A copy of a PETSc matrix that multiplies as correctly and as fast as the
// original.
#pragma once

#include <petscmat.h>

namespace damseis::linalg
{
/// MatDuplicate(A, option), keeping the block-size-specialised products of
/// (Seq/MPI)BAIJ matrices. PETSc 3.18's MatDuplicate of a BAIJ matrix
/// installs the generic MatMult_SeqBAIJ_N instead of the unrolled kernel of
/// its block size, and that kernel is wrong for matrices with empty block
/// rows (unless most rows are empty, when PETSc switches to compressed
/// rows and zeroes y first): it calls BLAS DGEMV per block row, which for a
/// row without columns returns at once, so that row of y = A x keeps what
/// it held before. Measured on the 3D viscous-spring
/// boundary's dashpot matrix (40% of the rows nonempty): the copy's
/// products carried M u from the previous product in the interior rows,
/// and P1 arch runs on rock with mass grew exponentially. It is also slower
/// (one BLAS DGEMV per block row): 3.0-3.5x for bs = 2 on 17,720 rows. The
/// products of the copy (and of its diagonal and off-diagonal blocks in
/// parallel) are set to those of A; all other types are returned as
/// MatDuplicate gives them. Never call MatDuplicate directly.
Mat duplicate_matrix(Mat A, MatDuplicateOption option);
} // namespace damseis::linalg
