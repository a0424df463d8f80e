#include "direct_solver.h"
#include <chrono>
#include <stdexcept>

namespace damseis::linalg
{
Factorization parse_factorization(const std::string& name)
{
  if (name == "auto")
    return Factorization::automatic;
  if (name == "petsc")
    return Factorization::petsc;
  if (name == "mumps")
    return Factorization::mumps;
  if (name == "cholmod")
    return Factorization::cholmod;
  if (name == "redundant")
    return Factorization::redundant;
  throw std::invalid_argument(
      "unknown factorisation \"" + name +
      "\"; expected auto, petsc, mumps, cholmod or redundant");
}

DirectSolver::DirectSolver(MPI_Comm comm, Factorization kind) : _kind(kind)
{
  int size = 1;
  MPI_Comm_size(comm, &size);
  _automatic = _kind == Factorization::automatic;
  if (_automatic)
    _kind = size == 1 ? Factorization::petsc : Factorization::redundant;
  if (size == 1 && _kind == Factorization::redundant)
    _kind = Factorization::petsc;
  if (size > 1 && _kind != Factorization::mumps &&
      _kind != Factorization::redundant)
  {
    throw std::invalid_argument(
        "the " + name() +
        " factorisation is serial; use solver.factorization = \"mumps\", "
        "\"redundant\" or \"auto\" with MPI");
  }
  create_ksp(comm);
}

void DirectSolver::create_ksp(MPI_Comm comm)
{
  if (_ksp)
    KSPDestroy(&_ksp);
  KSPCreate(comm, &_ksp);
  KSPSetType(_ksp, KSPPREONLY);
  PC pc;
  KSPGetPC(_ksp, &pc);
  PCSetType(pc, PCCHOLESKY);
  switch (_kind)
  {
  case Factorization::petsc:
    PCFactorSetMatSolverType(pc, MATSOLVERPETSC);
    PCFactorSetMatOrderingType(pc, MATORDERINGND);
    break;
  case Factorization::cholmod:
    PCFactorSetMatSolverType(pc, MATSOLVERCHOLMOD);
    break;
  case Factorization::redundant:
    set_up_redundant(comm);
    break;
  default:
    PCFactorSetMatSolverType(pc, MATSOLVERMUMPS);
    break;
  }
}

void DirectSolver::set_up_redundant(MPI_Comm comm)
{
  // Every rank gathers the whole matrix and factorises it with PETSc's own
  // LU (nested dissection; one block per node when the matrix is blocked):
  // each solve gathers the right-hand side, solves locally and keeps its
  // part. For the small 2D problems this beats MUMPS' distributed solve,
  // whose messages cost more than the arithmetic.
  int size = 1;
  MPI_Comm_size(comm, &size);
  PC pc;
  KSPGetPC(_ksp, &pc);
  PCSetType(pc, PCREDUNDANT);
  PCRedundantSetNumber(pc, size);
  KSP inner;
  PCRedundantGetKSP(pc, &inner);
  KSPSetType(inner, KSPPREONLY);
  PC inner_pc;
  KSPGetPC(inner, &inner_pc);
  PCSetType(inner_pc, PCLU);
  PCFactorSetMatSolverType(inner_pc, MATSOLVERPETSC);
  PCFactorSetMatOrderingType(inner_pc, MATORDERINGND);
}

void DirectSolver::choose_for(Mat A)
{
  // auto in parallel: the redundant factorisation up to 10^5 unknowns
  // (the 2D sections: koyna 2 ranks 0.6 s against MUMPS' 1.9 s for 1000
  // steps, serial 0.8 s), MUMPS beyond (a 3D arch of 1.5 x 10^5 unknowns:
  // the redundant LU took 9 min against MUMPS' 1 min 12 s).
  PetscInt rows = 0, cols = 0;
  MatGetSize(A, &rows, &cols);
  if (_automatic && _kind == Factorization::redundant && rows > 100000)
  {
    _kind = Factorization::mumps;
    create_ksp(PetscObjectComm(reinterpret_cast<PetscObject>(_ksp)));
  }
}

void DirectSolver::set_up(Mat A)
{
  // The factors are those of A now: later changes of A's values (a tangent
  // reassembled in place) must not refactorise behind the caller's back.
  KSPSetReusePreconditioner(_ksp, PETSC_FALSE);
  KSPSetOperators(_ksp, A, A);
  if (_kind == Factorization::mumps)
  {
    // MUMPS' workspace: 40% above its estimate (its default, 20%, fell
    // short by 1% on a rank of the 7-joint Xiluodu-like dam on rock with
    // mass, in the static contact stage: INFOG(1) = -9).
    PC pc;
    KSPGetPC(_ksp, &pc);
    PCFactorSetUpMatSolverType(pc);
    Mat F;
    PCFactorGetMatrix(pc, &F);
    MatMumpsSetIcntl(F, 14, 40);
  }
  KSPSetUp(_ksp);
  KSPSetReusePreconditioner(_ksp, PETSC_TRUE);
}

DirectSolver::~DirectSolver()
{
  if (_ksp)
    KSPDestroy(&_ksp);
  if (_converted)
    MatDestroy(&_converted);
}

bool is_blocked(Mat A)
{
  MatType type;
  MatGetType(A, &type);
  const std::string t(type);
  return t.find("baij") != std::string::npos &&
         t.find("sbaij") == std::string::npos;
}

void DirectSolver::factorize_lu(Mat A)
{
  const auto t0 = std::chrono::steady_clock::now();
  choose_for(A);
  PC pc;
  KSPGetPC(_ksp, &pc);
  if (_converted)
    MatDestroy(&_converted);
  // (The redundant preconditioner is an LU already: create_ksp.)
  if (_kind != Factorization::redundant)
  {
    PCSetType(pc, PCLU);
    PCFactorSetMatSolverType(
        pc, _kind == Factorization::mumps ? MATSOLVERMUMPS : MATSOLVERPETSC);
    if (_kind != Factorization::mumps)
      PCFactorSetMatOrderingType(pc, MATORDERINGND);
  }
  MatSetOption(A, MAT_SYMMETRIC, PETSC_FALSE);
  set_up(A);
  _lu = true;
  // A failed factorisation (e.g. a numerically singular matrix) is an
  // exception here, before any solve uses the factors.
  // (Redundant: every rank's copy has the same factors; look at its own.)
  PC factor_pc = pc;
  if (_kind == Factorization::redundant)
  {
    KSP inner;
    PCRedundantGetKSP(pc, &inner);
    KSPGetPC(inner, &factor_pc);
  }
  Mat F;
  PCFactorGetMatrix(factor_pc, &F);
  MatFactorError err;
  MatFactorGetError(F, &err);
  if (err != MAT_FACTOR_NOERROR)
  {
    std::string detail;
    if (_kind == Factorization::mumps)
    {
      PetscInt info1 = 0, info2 = 0;
      MatMumpsGetInfog(F, 1, &info1);
      MatMumpsGetInfog(F, 2, &info2);
      detail = ", MUMPS INFOG(1) = " + std::to_string(info1) +
               ", INFOG(2) = " + std::to_string(info2);
    }
    _failed = true;
    // MUMPS keeps a failed instance's state: start afresh next time.
    MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(_ksp));
    create_ksp(comm);
    throw std::runtime_error("LU factorisation failed (" + name() +
                             "): factor error " +
                             std::to_string(static_cast<int>(err)) + detail);
  }
  _failed = false;
  _factor_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
          .count();
}

void DirectSolver::factorize(Mat A)
{
  _lu = false;
  choose_for(A);
  if (_kind == Factorization::redundant)
  {
    // LU of the gathered matrix, as create_ksp set it up.
    const auto t0 = std::chrono::steady_clock::now();
    MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE);
    set_up(A);
    _factor_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
            .count();
    return;
  }
  {
    PC pc;
    KSPGetPC(_ksp, &pc);
    PCSetType(pc, PCCHOLESKY);
    if (_kind == Factorization::cholmod)
      PCFactorSetMatSolverType(pc, MATSOLVERCHOLMOD);
    if (_kind == Factorization::mumps)
      PCFactorSetMatSolverType(pc, MATSOLVERMUMPS);
  }
  // Parallel BAIJ rejects MAT_SPD: mark only the factorised matrix SPD.
  MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE);
  const auto t0 = std::chrono::steady_clock::now();
  const bool blocked = is_blocked(A);
  PC pc;
  KSPGetPC(_ksp, &pc);
  Mat F = A;
  if (_converted)
    MatDestroy(&_converted);
  switch (_kind)
  {
  case Factorization::petsc:
    // Blocked storage (one block per node) makes PETSc's LU with
    // nested-dissection ordering faster than its scalar Cholesky (bench/).
    PCSetType(pc, blocked ? PCLU : PCCHOLESKY);
    break;
  case Factorization::mumps:
    // MUMPS' Cholesky takes symmetric blocked storage.
    if (blocked)
    {
      MatConvert(A, MATSBAIJ, MAT_INITIAL_MATRIX, &_converted);
      F = _converted;
    }
    break;
  case Factorization::cholmod:
    if (blocked)
    {
      MatConvert(A, MATAIJ, MAT_INITIAL_MATRIX, &_converted);
      F = _converted;
    }
    break;
  default:
    break;
  }
  MatSetOption(F, MAT_SYMMETRIC, PETSC_TRUE);
  int size = 1;
  MPI_Comm_size(PetscObjectComm(reinterpret_cast<PetscObject>(F)), &size);
  if (!(blocked && F == A && size > 1))
    MatSetOption(F, MAT_SPD, PETSC_TRUE);
  set_up(F);
  _factor_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
          .count();
}

void DirectSolver::solve(Vec b, Vec x) const
{
  if (_failed)
    throw std::runtime_error("direct solve after a failed factorisation");
  KSPSolve(_ksp, b, x);
  KSPConvergedReason reason;
  KSPGetConvergedReason(_ksp, &reason);
  if (reason < 0)
  {
    // Say why the factorisation failed (MUMPS: INFOG(1), INFOG(2)).
    std::string detail;
    PC pc;
    KSPGetPC(_ksp, &pc);
    PCFailedReason pc_reason;
    PCGetFailedReason(pc, &pc_reason);
    detail +=
        ", PC failed reason " + std::to_string(static_cast<int>(pc_reason));
    if (_kind == Factorization::mumps)
    {
      Mat F;
      PCFactorGetMatrix(pc, &F);
      PetscInt info1 = 0, info2 = 0;
      MatMumpsGetInfog(F, 1, &info1);
      MatMumpsGetInfog(F, 2, &info2);
      detail += ", MUMPS INFOG(1) = " + std::to_string(info1) +
                ", INFOG(2) = " + std::to_string(info2);
    }
    throw std::runtime_error("direct solve failed (" + name() +
                             "): PETSc reason " +
                             std::to_string(static_cast<int>(reason)) + detail);
  }
}

std::string DirectSolver::name() const
{
  switch (_kind)
  {
  case Factorization::petsc:
  {
    PC pc;
    KSPGetPC(_ksp, &pc);
    PCType type;
    PCGetType(pc, &type);
    return std::string("petsc-") +
           (type && std::string(type) == PCLU ? "lu" : "cholesky") + "-nd";
  }
  case Factorization::cholmod:
    return _lu ? "petsc-lu-nd" : "cholmod-cholesky";
  case Factorization::mumps:
    return _lu ? "mumps-lu" : "mumps-cholesky";
  case Factorization::redundant:
    return "redundant-petsc-lu-nd";
  default:
    return "auto";
  }
}
} // namespace damseis::linalg
