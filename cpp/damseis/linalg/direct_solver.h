// Sparse Cholesky factorisation of a symmetric positive definite matrix,
// factorised once and reused for many right-hand sides.
#pragma once

#include <mpi.h>
#include <petscksp.h>
#include <string>

namespace damseis::linalg
{
/// The factorisations PETSc offers here (bench/ compares them).
enum class Factorization
{
  /// PETSc's own factorisation serial; in parallel the redundant one up to
  /// 10^5 unknowns, MUMPS beyond
  automatic,
  petsc,   ///< PETSc's own LU/Cholesky, nested-dissection ordering (serial)
  mumps,   ///< MUMPS Cholesky (serial or parallel)
  cholmod, ///< SuiteSparse CHOLMOD (serial)
           /// Every rank factorises the whole matrix (PETSc LU, nested
           /// dissection): small problems in parallel (serial: the same as
           /// petsc)
  redundant,
};

/// Parses "auto", "petsc", "mumps", "cholmod" or "redundant"; throws
/// std::invalid_argument otherwise.
Factorization parse_factorization(const std::string& name);

/// True for blocked, non-symmetric storage (BAIJ): one block per node.
bool is_blocked(Mat A);

/// A KSP in "preonly" mode with a Cholesky preconditioner.
class DirectSolver
{
public:
  DirectSolver(MPI_Comm comm, Factorization kind = Factorization::automatic);
  ~DirectSolver();
  DirectSolver(const DirectSolver&) = delete;
  DirectSolver& operator=(const DirectSolver&) = delete;

  /// Factorises A (marked symmetric positive definite). A must outlive the
  /// solver's use of it. With blocked storage (BAIJ) PETSc's own solver uses
  /// LU (its fastest here); MUMPS and CHOLMOD get a converted copy.
  void factorize(Mat A);
  /// Factorises a general (possibly non-symmetric or indefinite) A by LU:
  /// PETSc's LU serially, MUMPS LU in parallel (CHOLMOD -> PETSc LU).
  /// Throws std::runtime_error if the factorisation fails (then solve()
  /// throws until the next successful factorisation).
  void factorize_lu(Mat A);
  /// Solves A x = b with the stored factors (those of A when it was
  /// factorised, even if A has changed since).
  void solve(Vec b, Vec x) const;
  /// Name of the factorisation used, e.g. "petsc-cholesky-nd".
  std::string name() const;
  /// Wall time of the last factorize() [s].
  double factor_seconds() const { return _factor_seconds; }

private:
  /// (Re)creates the KSP with the settings of the constructor.
  void create_ksp(MPI_Comm comm);
  /// Resolves `automatic` in parallel by the size of A.
  void choose_for(Mat A);
  /// Makes the KSP's preconditioner the redundant PETSc LU.
  void set_up_redundant(MPI_Comm comm);
  /// Factorises A in the KSP; the factors stay until the next call.
  void set_up(Mat A);
  KSP _ksp = nullptr;
  Mat _converted = nullptr; ///< A in the storage the package needs
  Factorization _kind;
  bool _automatic = false; ///< _kind was chosen, not given
  bool _lu = false;        ///< the last factorisation was factorize_lu
  bool _failed = false;    ///< the last factorize_lu failed
  double _factor_seconds = 0.0;
};
} // namespace damseis::linalg
