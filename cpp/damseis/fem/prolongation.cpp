#include "prolongation.h"
#include <algorithm>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/mesh/Mesh.h>
#include <petscvec.h>
#include <stdexcept>

namespace damseis::fem
{
namespace
{
/// The values of the distributed vector x at global indices `at` (any
/// rank's), on this rank (collective).
std::vector<double> values_at(Vec x, const std::vector<PetscInt>& at)
{
  IS is;
  ISCreateGeneral(PETSC_COMM_SELF, static_cast<PetscInt>(at.size()), at.data(),
                  PETSC_COPY_VALUES, &is);
  Vec y;
  VecCreateSeq(PETSC_COMM_SELF, static_cast<PetscInt>(at.size()), &y);
  VecScatter sc;
  VecScatterCreate(x, is, y, nullptr, &sc);
  VecScatterBegin(sc, x, y, INSERT_VALUES, SCATTER_FORWARD);
  VecScatterEnd(sc, x, y, INSERT_VALUES, SCATTER_FORWARD);
  std::vector<double> out(at.size());
  const double* a = nullptr;
  VecGetArrayRead(y, &a);
  std::copy(a, a + at.size(), out.begin());
  VecRestoreArrayRead(y, &a);
  VecScatterDestroy(&sc);
  VecDestroy(&y);
  ISDestroy(&is);
  return out;
}
} // namespace

Mat constraint_prolongation(const dolfinx::fem::FunctionSpace& V,
                            const std::vector<BlockConstraint>& constraints)
{
  MPI_Comm comm = V.mesh()->comm();
  const auto& map = *V.dofmap()->index_map;
  const int bs = V.dofmap()->index_map_bs();
  const std::int32_t n_owned = map.size_local();
  const std::int64_t first = map.local_range()[0];

  // Reduced numbering: the owned blocks that are not slaves, in order.
  std::vector<const BlockConstraint*> of(n_owned, nullptr);
  for (const auto& c : constraints)
  {
    if (c.slave < 0 || c.slave >= n_owned || of[c.slave])
      throw std::invalid_argument("constraint_prolongation: bad slave block");
    of[c.slave] = &c;
  }
  std::vector<std::int64_t> reduced(n_owned, -1);
  std::int64_t n_reduced = 0;
  for (std::int32_t b = 0; b < n_owned; ++b)
    if (!of[b])
      reduced[b] = n_reduced++;
  std::int64_t offset = 0;
  MPI_Exscan(&n_reduced, &offset, 1, MPI_INT64_T, MPI_SUM, comm);
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0)
    offset = 0;
  std::int64_t N_reduced = 0;
  MPI_Allreduce(&n_reduced, &N_reduced, 1, MPI_INT64_T, MPI_SUM, comm);

  // The reduced index of every block, as a distributed vector, read at the
  // masters this rank's slaves name.
  Vec index;
  VecCreateMPI(comm, n_owned, PETSC_DETERMINE, &index);
  {
    double* a = nullptr;
    VecGetArray(index, &a);
    for (std::int32_t b = 0; b < n_owned; ++b)
      a[b] = reduced[b] < 0 ? -1.0 : static_cast<double>(reduced[b] + offset);
    VecRestoreArray(index, &a);
  }
  std::vector<PetscInt> wanted;
  for (const auto& c : constraints)
    for (const auto& [m, w] : c.masters)
      wanted.push_back(static_cast<PetscInt>(m));
  const std::vector<double> master_reduced = values_at(index, wanted);
  VecDestroy(&index);

  Mat P;
  MatCreateAIJ(comm, n_owned * bs, n_reduced * bs, map.size_global() * bs,
               N_reduced * bs, 5, nullptr, 5, nullptr, &P);
  std::size_t k_master = 0;
  for (std::int32_t b = 0; b < n_owned; ++b)
  {
    for (int k = 0; k < bs; ++k)
    {
      const PetscInt row = static_cast<PetscInt>((first + b) * bs + k);
      if (!of[b])
      {
        const PetscInt col =
            static_cast<PetscInt>((reduced[b] + offset) * bs + k);
        MatSetValue(P, row, col, 1.0, ADD_VALUES);
      }
    }
  }
  for (const auto& c : constraints)
  {
    for (const auto& [m, w] : c.masters)
    {
      const double r = master_reduced[k_master++];
      if (r < 0.0)
        throw std::invalid_argument(
            "constraint_prolongation: a master is itself constrained");
      for (int k = 0; k < bs; ++k)
      {
        const PetscInt row = static_cast<PetscInt>((first + c.slave) * bs + k);
        const PetscInt col =
            static_cast<PetscInt>(static_cast<std::int64_t>(r) * bs + k);
        MatSetValue(P, row, col, w, ADD_VALUES);
      }
    }
  }
  MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY);
  return P;
}

std::vector<std::int64_t> reduced_blocks(Mat P, int bs,
                                         std::span<const std::int64_t> blocks)
{
  // Row (block * bs) of P holds one 1 at the reduced column of an
  // unconstrained block; the owner reads it, the others add zero.
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(P));
  PetscInt r0 = 0, r1 = 0;
  MatGetOwnershipRange(P, &r0, &r1);
  std::vector<std::int64_t> local(blocks.size(), 0), out(blocks.size());
  for (std::size_t i = 0; i < blocks.size(); ++i)
  {
    const PetscInt row = static_cast<PetscInt>(blocks[i] * bs);
    if (row < r0 || row >= r1)
      continue;
    PetscInt ncols = 0;
    const PetscInt* cols = nullptr;
    const PetscScalar* vals = nullptr;
    MatGetRow(P, row, &ncols, &cols, &vals);
    local[i] = (ncols == 1 && vals[0] == 1.0) ? cols[0] / bs + 1 : 0;
    MatRestoreRow(P, row, &ncols, &cols, &vals);
  }
  MPI_Allreduce(local.data(), out.data(), static_cast<int>(out.size()),
                MPI_INT64_T, MPI_SUM, comm);
  for (auto& o : out)
    o -= 1; // 0 (constrained, or a master-weighted row) -> -1
  return out;
}
} // namespace damseis::fem
