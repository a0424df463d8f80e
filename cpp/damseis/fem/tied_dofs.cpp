#include "tied_dofs.h"
#include "facet_dofs.h"
#include "prolongation.h"
#include <algorithm>
#include <array>
#include <cmath>
#include <damseis/geometry/coincident_points.h>
#include <damseis/geometry/tagged.h>
#include <damseis/linalg/all_gather.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DirichletBC.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/mesh/Mesh.h>
#include <numeric>
#include <petscksp.h>
#include <stdexcept>

namespace damseis::fem
{

Mat tie_prolongation(const dolfinx::fem::FunctionSpace& V,
                     const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags,
                     const std::vector<std::pair<int, int>>& tag_pairs,
                     double tol)
{
  MPI_Comm comm = V.mesh()->comm();
  const auto& map = *V.dofmap()->index_map;
  const int bs = V.dofmap()->index_map_bs();
  const std::int32_t n_owned = map.size_local();
  const std::int64_t first_block = map.local_range()[0];
  const std::vector<double> x = V.tabulate_dof_coordinates(false);

  // Masters (x, y, z, global block) of every rank; slaves owned here.
  std::vector<double> masters_local;
  std::vector<std::int32_t> slaves;
  for (auto [first, second] : tag_pairs)
  {
    for (std::int32_t b : owned_blocks_on(V, facet_tags, first))
    {
      masters_local.insert(masters_local.end(),
                           {x[3 * b], x[3 * b + 1], x[3 * b + 2],
                            static_cast<double>(first_block + b)});
    }
    auto s = owned_blocks_on(V, facet_tags, second);
    slaves.insert(slaves.end(), s.begin(), s.end());
  }
  std::sort(slaves.begin(), slaves.end());
  slaves.erase(std::unique(slaves.begin(), slaves.end()), slaves.end());
  const std::vector<double> masters = linalg::all_gather(comm, masters_local);
  const std::size_t n_masters = masters.size() / 4;
  // A node on both faces (where a joint meets bonded material, e.g. the
  // foundation) is one dof already: it is not a slave.
  {
    std::vector<std::int64_t> on_first(n_masters);
    for (std::size_t m = 0; m < n_masters; ++m)
      on_first[m] = static_cast<std::int64_t>(masters[4 * m + 3]);
    std::sort(on_first.begin(), on_first.end());
    std::erase_if(slaves,
                  [&](std::int32_t b)
                  {
                    return std::binary_search(on_first.begin(), on_first.end(),
                                              first_block + b);
                  });
  }

  // Match each slave to the coincident master.
  const geometry::CoincidentPoints master_points(
      n_masters,
      [&](std::size_t m)
      {
        return std::array<double, 3>{masters[4 * m], masters[4 * m + 1],
                                     masters[4 * m + 2]};
      },
      tol);
  std::vector<std::int64_t> slave_master(slaves.size(), -1);
  for (std::size_t i = 0; i < slaves.size(); ++i)
  {
    const double* p = &x[3 * slaves[i]];
    const std::int64_t m = master_points.find(p);
    if (m >= 0)
      slave_master[i] = static_cast<std::int64_t>(masters[4 * m + 3]);
    if (slave_master[i] < 0)
    {
      throw std::runtime_error(
          "tied dofs: no coincident partner for the node at (" +
          std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " +
          std::to_string(p[2]) + ")");
    }
  }

  std::vector<BlockConstraint> constraints(slaves.size());
  for (std::size_t i = 0; i < slaves.size(); ++i)
    constraints[i] = {slaves[i], {{slave_master[i], 1.0}}};
  return constraint_prolongation(V, constraints);
}

Mat reduce_to_tied(Mat A, Mat P)
{
  // PETSc's PtAP takes AIJ, not the blocked storage of the assembled
  // operators.
  Mat aij, reduced;
  MatConvert(A, MATAIJ, MAT_INITIAL_MATRIX, &aij);
  MatPtAP(aij, P, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &reduced);
  MatDestroy(&aij);
  return reduced;
}

Vec restrict_to_tied(Mat P, Vec x)
{
  // Least squares, x_r = (P^T P)^-1 P^T x: exact where x = P x_r. For ties
  // P^T P is diagonal (the nodes tied together), the mean of the tied
  // values; general constraints (weights of both signs) need the solve.
  Vec xr, rhs;
  MatCreateVecs(P, &xr, nullptr);
  VecDuplicate(xr, &rhs);
  MatMultTranspose(P, x, rhs);
  Mat PtP;
  MatTransposeMatMult(P, P, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &PtP);
  // Conjugate gradients with Jacobi: P^T P is diagonal for ties (one
  // iteration, the mean) and well conditioned for the midside constraints
  // (weights 1 and 1/2), where a factorisation would cost more than it
  // saves.
  KSP ksp;
  KSPCreate(PetscObjectComm(reinterpret_cast<PetscObject>(P)), &ksp);
  KSPSetOperators(ksp, PtP, PtP);
  KSPSetType(ksp, KSPCG);
  PC pc;
  KSPGetPC(ksp, &pc);
  PCSetType(pc, PCJACOBI);
  KSPSetTolerances(ksp, 1e-14, 0.0, PETSC_DEFAULT, 1000);
  KSPSolve(ksp, rhs, xr);
  KSPConvergedReason reason;
  KSPGetConvergedReason(ksp, &reason);
  KSPDestroy(&ksp);
  MatDestroy(&PtP);
  VecDestroy(&rhs);
  if (reason < 0)
  {
    VecDestroy(&xr);
    throw std::runtime_error("restrict_to_tied: CG did not converge");
  }
  return xr;
}
} // namespace damseis::fem
