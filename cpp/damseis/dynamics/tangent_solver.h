// Newton directions J du = R for the nonlinear integrators, reusing
// factorisations (algorithms.md 6.2): GMRES (flexible) on the consistent J,
// preconditioned by a matrix factorised earlier (the initial effective
// matrix J0, or a tangent of the same step length factorised earlier in the
// step; forget() at a step's start).
// Where few material points are inelastic, J differs from that matrix by a
// low-rank term and GMRES converges in a few iterations, each costing one
// pair of triangular solves; only when it does not (the cracked zone has
// changed too much) is J itself factorised, and that factorisation becomes
// the preconditioner of the following iterations of the step.
#pragma once

#include <damseis/linalg/direct_solver.h>
#include <memory>
#include <petscksp.h>

namespace damseis::dynamics
{
/// How a direction was found.
enum class Direction
{
  krylov,     ///< GMRES converged with the stored preconditioner
  factorized, ///< J factorised and solved directly
  failed,     ///< no direction (singular J and GMRES did not converge)
};

class TangentSolver
{
public:
  /// rtol: GMRES tolerance relative to ||R||; max_iterations: GMRES
  /// iterations before J is factorised instead (0: always factorise, i.e.
  /// exact Newton).
  TangentSolver(MPI_Comm comm, double rtol, int max_iterations);
  ~TangentSolver();
  TangentSolver(const TangentSolver&) = delete;
  TangentSolver& operator=(const TangentSolver&) = delete;

  /// du with J du = R (to rtol ||R||, or abs_tol if larger). `initial` is
  /// the factorised initial matrix for the step length `level`; a stored
  /// tangent factorisation is used as preconditioner only for the same
  /// level. J may be reassembled after the call (the factors are kept).
  Direction solve(Mat J, const linalg::DirectSolver& initial, int level, Vec R,
                  Vec du, double abs_tol);

  /// Forgets the stored tangent factors: GMRES starts again from the
  /// initial matrix's.
  void forget() { _tangent_level = -1; }

  int last_krylov_iterations() const { return _last_iterations; }
  /// Wall time of the last factorisation in solve() [s] (0 if none).
  double last_factor_seconds() const { return _last_factor_seconds; }

private:
  double _rtol;
  int _max_iterations;
  KSP _krylov = nullptr;
  /// LU of J: PETSc's serially (its solves cost a third of MUMPS' here; a
  /// zero pivot is reported and the initial matrix used instead); in
  /// parallel the redundant PETSc LU up to 10^5 unknowns, MUMPS beyond.
  std::unique_ptr<linalg::DirectSolver> _tangent;
  int _tangent_level = -1; ///< level of the stored factors (-1: none)
  int _last_iterations = 0;
  double _last_factor_seconds = 0.0;
};
} // namespace damseis::dynamics
