#pragma once

namespace damseis::linalg
{
/// Number of single-column DGEMM / DTRSM calls forwarded to DGEMV / DTRSV
/// in this process so far (blas_single_column.cpp; tests use it to check
/// that the forwarding is linked in and reached by MUMPS).
long blas_single_column_calls();
} // namespace damseis::linalg
