#include "modal.h"
#include "direct_solver.h"
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <slepceps.h>
#include <stdexcept>
#include <string>

namespace damseis::fem
{
Modes::Modes(Modes&& other) noexcept
    : frequencies_hz(std::move(other.frequencies_hz)),
      shapes(std::move(other.shapes))
{
  other.shapes.clear();
}

Modes& Modes::operator=(Modes&& other) noexcept
{
  std::swap(frequencies_hz, other.frequencies_hz);
  std::swap(shapes, other.shapes);
  return *this;
}

Modes::~Modes()
{
  for (Vec& v : shapes)
    VecDestroy(&v);
}

Modes solve_modes(Mat K, Mat M, int count)
{
  static bool slepc_ready = false;
  if (!slepc_ready)
  {
    SlepcInitialize(nullptr, nullptr, nullptr, nullptr);
    slepc_ready = true;
  }
  MPI_Comm comm;
  PetscObjectGetComm(reinterpret_cast<PetscObject>(K), &comm);
  EPS eps;
  EPSCreate(comm, &eps);
  EPSSetOperators(eps, K, M);
  EPSSetProblemType(eps, EPS_GHEP);
  EPSSetType(eps, EPSKRYLOVSCHUR);
  EPSSetDimensions(eps, count, PETSC_DEFAULT, PETSC_DEFAULT);
  EPSSetTarget(eps, 0.0);
  EPSSetWhichEigenpairs(eps, EPS_TARGET_MAGNITUDE);
  EPSSetTolerances(eps, 1e-10, 200);
  ST st;
  EPSGetST(eps, &st);
  STSetType(st, STSINVERT);
  KSP ksp;
  STGetKSP(st, &ksp);
  KSPSetType(ksp, KSPPREONLY);
  PC pc;
  KSPGetPC(ksp, &pc);
  // MUMPS Cholesky does not take blocked (BAIJ) storage; LU does.
  PCSetType(pc, is_blocked(K) ? PCLU : PCCHOLESKY);
  PCFactorSetMatSolverType(pc, MATSOLVERMUMPS);
  EPSSolve(eps);

  PetscInt nconv = 0;
  EPSGetConverged(eps, &nconv);
  if (nconv < count)
  {
    EPSDestroy(&eps);
    throw std::runtime_error("modal analysis: only " + std::to_string(nconv) +
                             " of " + std::to_string(count) +
                             " modes converged");
  }
  std::vector<double> lambda(nconv);
  for (PetscInt i = 0; i < nconv; ++i)
  {
    PetscScalar kr, ki;
    EPSGetEigenvalue(eps, i, &kr, &ki);
    lambda[i] = PetscRealPart(kr);
  }
  std::vector<int> order(nconv);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return lambda[a] < lambda[b]; });

  Modes modes;
  for (int k = 0; k < count; ++k)
  {
    const int i = order[k];
    modes.frequencies_hz.push_back(std::sqrt(std::max(lambda[i], 0.0)) /
                                   (2.0 * std::numbers::pi));
    Vec x;
    MatCreateVecs(K, &x, nullptr);
    EPSGetEigenvector(eps, i, x, nullptr);
    modes.shapes.push_back(x);
  }
  EPSDestroy(&eps);
  return modes;
}
} // namespace damseis::fem
