#include "tangent_solver.h"
#include <chrono>
#include <stdexcept>

namespace damseis::dynamics
{
namespace
{
/// The preconditioner seen by GMRES: a solve with stored factors. A failed
/// solve (not expected: the factors were checked when made) leaves y = x and
/// is reported through `failed`.
struct ShellContext
{
  const linalg::DirectSolver* factors = nullptr;
  bool failed = false;
};

PetscErrorCode apply_factors(PC pc, Vec x, Vec y)
{
  void* ptr = nullptr;
  PCShellGetContext(pc, &ptr);
  auto* ctx = static_cast<ShellContext*>(ptr);
  try
  {
    ctx->factors->solve(x, y);
  }
  catch (const std::runtime_error&)
  {
    ctx->failed = true;
    VecCopy(x, y);
  }
  return 0;
}
} // namespace

TangentSolver::TangentSolver(MPI_Comm comm, double rtol, int max_iterations)
    : _rtol(rtol), _max_iterations(max_iterations),
      _tangent(std::make_unique<linalg::DirectSolver>(
          comm, linalg::Factorization::automatic))
{
  if (_max_iterations <= 0)
    return;
  KSPCreate(comm, &_krylov);
  // Flexible GMRES: with a fixed preconditioner the same iterates as
  // right-preconditioned GMRES, but it keeps the preconditioned basis, so
  // the solution needs no extra preconditioner application at the end
  // (GMRES applies it once more per solve: 1 triangular solve pair in 6.7
  // on Koyna). No restart within the allowed iterations; the tolerance
  // applies to the true residual of J du = R.
  KSPSetType(_krylov, KSPFGMRES);
  KSPGMRESSetRestart(_krylov, _max_iterations);
  KSPSetPCSide(_krylov, PC_RIGHT);
  KSPSetNormType(_krylov, KSP_NORM_UNPRECONDITIONED);
  PC pc;
  KSPGetPC(_krylov, &pc);
  PCSetType(pc, PCSHELL);
  PCShellSetApply(pc, apply_factors);
}

TangentSolver::~TangentSolver()
{
  if (_krylov)
    KSPDestroy(&_krylov);
}

Direction TangentSolver::solve(Mat J, const linalg::DirectSolver& initial,
                               int level, Vec R, Vec du, double abs_tol)
{
  _last_iterations = 0;
  _last_factor_seconds = 0.0;
  if (_krylov)
  {
    ShellContext ctx;
    ctx.factors = _tangent_level == level ? _tangent.get() : &initial;
    PC pc;
    KSPGetPC(_krylov, &pc);
    PCShellSetContext(pc, &ctx);
    KSPSetOperators(_krylov, J, J);
    KSPSetTolerances(_krylov, _rtol, abs_tol, PETSC_DEFAULT, _max_iterations);
    KSPSolve(_krylov, R, du);
    KSPConvergedReason reason;
    KSPGetConvergedReason(_krylov, &reason);
    PetscInt its = 0;
    KSPGetIterationNumber(_krylov, &its);
    _last_iterations = static_cast<int>(its);
    PCShellSetContext(pc, nullptr);
    if (reason > 0 && !ctx.failed)
      return Direction::krylov;
  }
  // GMRES needs more than the allowed iterations: the tangent has moved too
  // far from the stored factors; factorise it (it becomes the new
  // preconditioner).
  const auto t0 = std::chrono::steady_clock::now();
  try
  {
    _tangent_level = -1;
    _tangent->factorize_lu(J);
    _tangent_level = level;
    _last_factor_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
            .count();
    _tangent->solve(R, du);
    return Direction::factorized;
  }
  catch (const std::runtime_error&)
  {
    // Numerically singular J (e.g. a fully softened band): no direction.
    _last_factor_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
            .count();
    return Direction::failed;
  }
}
} // namespace damseis::dynamics
