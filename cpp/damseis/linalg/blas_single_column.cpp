// Single-column DGEMM and DTRSM forwarded to DGEMV and DTRSV.
//
// MUMPS' solve phase (Debian's build, without MUMPS_USE_BLAS2) calls DGEMM
// and DTRSM with one right-hand-side column. OpenBLAS 0.3.21 (bookworm)
// packs the whole factor panel for such calls before multiplying: in the
// arch_dam time loop 50% of the time went to its packing routines
// (dgemm_incopy/itcopy) against 8% to the multiplication kernel. OpenBLAS
// forwards these calls to GEMV itself from 0.3.28 on (its PR #4814). Until
// then the executables define dgemm_ and dtrsm_ (exported, and forced in
// from the static library by the link options in cpp/CMakeLists.txt), so
// that every caller in the process reaches these: a call with one column
// goes to the BLAS library's own DGEMV / DTRSV, every other call to its
// DGEMM / DTRSM, found with dlsym(RTLD_NEXT). Same operation; the sums are
// taken in another order (differences at rounding level).
// DAMSEIS_BLAS_SINGLE_COLUMN=0 in the environment turns the forwarding off
// (A/B timings: bench/results/arch-blas-forward-2026-11-22.md).
#include "blas_single_column.h"
#include <atomic>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <dlfcn.h>

namespace
{
using Gemm = void(const char*, const char*, const int*, const int*, const int*,
                  const double*, const double*, const int*, const double*,
                  const int*, const double*, double*, const int*, std::size_t,
                  std::size_t);
using Gemv = void(const char*, const int*, const int*, const double*,
                  const double*, const int*, const double*, const int*,
                  const double*, double*, const int*, std::size_t);
using Trsm = void(const char*, const char*, const char*, const char*,
                  const int*, const int*, const double*, const double*,
                  const int*, double*, const int*, std::size_t, std::size_t,
                  std::size_t, std::size_t);
using Trsv = void(const char*, const char*, const char*, const int*,
                  const double*, const int*, double*, const int*, std::size_t,
                  std::size_t, std::size_t);

std::atomic<long> forwarded_calls{0};

template <typename F>
F* next_symbol(const char* name)
{
  void* f = dlsym(RTLD_NEXT, name);
  if (!f)
  {
    std::fprintf(stderr, "damseis: BLAS routine %s not found (%s)\n", name,
                 dlerror());
    std::abort();
  }
  return reinterpret_cast<F*>(f);
}

bool forwarding_enabled()
{
  static const bool on = []
  {
    const char* v = std::getenv("DAMSEIS_BLAS_SINGLE_COLUMN");
    return !(v && v[0] == '0');
  }();
  return on;
}

bool transposed(char c)
{
  return c == 'T' || c == 't' || c == 'C' || c == 'c';
}
} // namespace

extern "C"
{
  // Fortran BLAS interface, with gfortran's hidden character lengths.
  void dgemm_(const char* transa, const char* transb, const int* m,
              const int* n, const int* k, const double* alpha, const double* a,
              const int* lda, const double* b, const int* ldb,
              const double* beta, double* c, const int* ldc, std::size_t la,
              std::size_t lb)
  {
    static Gemm* const gemm = next_symbol<Gemm>("dgemm_");
    static Gemv* const gemv = next_symbol<Gemv>("dgemv_");
    // k = 0 and alpha = 0 must still scale C by beta, which DGEMV skips.
    if (*n == 1 && *m > 0 && *k > 0 && *alpha != 0.0 && forwarding_enabled())
    {
      forwarded_calls.fetch_add(1, std::memory_order_relaxed);
      const int incx = transposed(*transb) ? *ldb : 1, incy = 1;
      if (transposed(*transa))
        gemv("T", k, m, alpha, a, lda, b, &incx, beta, c, &incy, 1);
      else
        gemv("N", m, k, alpha, a, lda, b, &incx, beta, c, &incy, 1);
      return;
    }
    gemm(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc, la, lb);
  }

  void dtrsm_(const char* side, const char* uplo, const char* transa,
              const char* diag, const int* m, const int* n, const double* alpha,
              const double* a, const int* lda, double* b, const int* ldb,
              std::size_t ls, std::size_t lu, std::size_t lt, std::size_t ld)
  {
    static Trsm* const trsm = next_symbol<Trsm>("dtrsm_");
    static Trsv* const trsv = next_symbol<Trsv>("dtrsv_");
    if ((*side == 'L' || *side == 'l') && *n == 1 && *m > 0 && *alpha == 1.0 &&
        forwarding_enabled())
    {
      forwarded_calls.fetch_add(1, std::memory_order_relaxed);
      const int incx = 1;
      trsv(uplo, transa, diag, m, a, lda, b, &incx, 1, 1, 1);
      return;
    }
    trsm(side, uplo, transa, diag, m, n, alpha, a, lda, b, ldb, ls, lu, lt, ld);
  }
}

namespace damseis::linalg
{
long blas_single_column_calls()
{
  return forwarded_calls.load(std::memory_order_relaxed);
}
} // namespace damseis::linalg
