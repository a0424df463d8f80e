#include "tied_concrete_system.h"
#include <array>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>
#include <stdexcept>

namespace damseis::analysis
{
namespace
{
/// Per local node block of V: the row of P for its first component, as
/// (global reduced node block, weight); P's rows of the other components
/// are the same shifted (tie_prolongation, midside_prolongation).
std::vector<std::vector<std::pair<PetscInt, double>>>
node_rows(const dolfinx::fem::FunctionSpace& V, Mat P)
{
  const auto& map = *V.dofmap()->index_map;
  const int bs = V.dofmap()->index_map_bs();
  const std::int32_t n = map.size_local() + map.num_ghosts();
  std::vector<std::int32_t> local(n);
  for (std::int32_t i = 0; i < n; ++i)
    local[i] = i;
  std::vector<std::int64_t> global(n);
  map.local_to_global(local, global);
  std::vector<PetscInt> rows(n);
  for (std::int32_t i = 0; i < n; ++i)
    rows[i] = static_cast<PetscInt>(bs * global[i]);
  PetscInt N = 0;
  MatGetSize(P, nullptr, &N);
  IS is_rows, is_cols;
  ISCreateGeneral(PETSC_COMM_SELF, n, rows.data(), PETSC_COPY_VALUES, &is_rows);
  ISCreateStride(PETSC_COMM_SELF, N, 0, 1, &is_cols);
  Mat* sub = nullptr;
  MatCreateSubMatrices(P, 1, &is_rows, &is_cols, MAT_INITIAL_MATRIX, &sub);
  std::vector<std::vector<std::pair<PetscInt, double>>> follows(n);
  int coupled = 0; // a row of P coupling components (not a node block)
  for (std::int32_t i = 0; i < n; ++i)
  {
    PetscInt ncols = 0;
    const PetscInt* cols = nullptr;
    const PetscScalar* vals = nullptr;
    MatGetRow(sub[0], i, &ncols, &cols, &vals);
    for (PetscInt k = 0; k < ncols; ++k)
    {
      if (vals[k] == 0.0)
        continue;
      coupled = coupled || cols[k] % bs != 0;
      follows[i].emplace_back(cols[k] / bs, vals[k]);
    }
    MatRestoreRow(sub[0], i, &ncols, &cols, &vals);
  }
  MatDestroySubMatrices(1, &sub);
  ISDestroy(&is_rows);
  ISDestroy(&is_cols);
  MPI_Allreduce(MPI_IN_PLACE, &coupled, 1, MPI_INT, MPI_MAX,
                PetscObjectComm(reinterpret_cast<PetscObject>(P)));
  if (coupled)
    throw std::logic_error("TiedConcreteSystem: P couples components");
  return follows;
}
} // namespace

TiedConcreteSystem::TiedConcreteSystem(fem::ConcreteModel& m, Mat tie)
    : ConcreteSystem(m), _P(tie), _u_full(linalg::row_vector(tie)),
      _f_full(linalg::row_vector(tie)),
      _follows(node_rows(*m.elastic_model().V(), tie))
{
}

bool TiedConcreteSystem::trial(Vec u, double dt)
{
  MatMult(_P, u, _u_full.vec());
  return ConcreteSystem::trial(_u_full.vec(), dt);
}

void TiedConcreteSystem::internal_force(Vec f)
{
  ConcreteSystem::internal_force(_f_full.vec());
  MatMultTranspose(_P, _f_full.vec(), f);
}

void TiedConcreteSystem::add_tangent_change(Mat A, double scale)
{
  // Each cell's 3x3 blocks K_ab go to (r_a, r_b) with weight w_a w_b for
  // every pair of tied unknowns the nodes a and b follow.
  constexpr int bs = 3;
  auto set = [&](std::span<const std::int32_t> rows,
                 std::span<const std::int32_t> cols,
                 std::span<const double> vals) -> int
  {
    const std::size_t nc = bs * cols.size();
    std::array<PetscInt, bs> r, c;
    std::array<double, bs * bs> block;
    for (std::size_t a = 0; a < rows.size(); ++a)
    {
      for (const auto& [ra, wa] : _follows[rows[a]])
      {
        for (std::size_t b = 0; b < cols.size(); ++b)
        {
          for (const auto& [rb, wb] : _follows[cols[b]])
          {
            for (int i = 0; i < bs; ++i)
            {
              r[i] = bs * ra + i;
              c[i] = bs * rb + i;
              for (int j = 0; j < bs; ++j)
                block[bs * i + j] =
                    wa * wb * vals[(bs * a + i) * nc + bs * b + j];
            }
            MatSetValues(A, bs, r.data(), bs, c.data(), block.data(),
                         ADD_VALUES);
          }
        }
      }
    }
    return 0;
  };
  model().add_tangent_change(set, scale);
  MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY);
}

void TiedConcreteSystem::extrapolation_change(Vec f)
{
  ConcreteSystem::extrapolation_change(_f_full.vec());
  MatMultTranspose(_P, _f_full.vec(), f);
}
} // namespace damseis::analysis
