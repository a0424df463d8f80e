#include "petsc_vectors.h"
#include <algorithm>

namespace damseis::linalg
{
using dolfinx::la::petsc::Vector;

Vector column_vector(Mat A)
{
  Vec x;
  MatCreateVecs(A, &x, nullptr);
  VecSet(x, 0.0);
  return Vector(x, false);
}

Vector row_vector(Mat A)
{
  Vec x;
  MatCreateVecs(A, nullptr, &x);
  VecSet(x, 0.0);
  return Vector(x, false);
}

void to_function(Vec x, dolfinx::fem::Function<double>& u)
{
  const double* a = nullptr;
  VecGetArrayRead(x, &a);
  std::span<double> y = u.x()->mutable_array();
  const auto& map = *u.function_space()->dofmap()->index_map;
  const int bs = u.function_space()->dofmap()->index_map_bs();
  std::copy_n(a, map.size_local() * bs, y.begin());
  VecRestoreArrayRead(x, &a);
  u.x()->scatter_fwd();
}

std::vector<double> owned_values(Vec x)
{
  PetscInt n = 0;
  VecGetLocalSize(x, &n);
  const double* a = nullptr;
  VecGetArrayRead(x, &a);
  std::vector<double> v(a, a + n);
  VecRestoreArrayRead(x, &a);
  return v;
}

void read_owned_values(Vec x, std::vector<double>& out)
{
  PetscInt n = 0;
  VecGetLocalSize(x, &n);
  const double* a = nullptr;
  VecGetArrayRead(x, &a);
  out.assign(a, a + n);
  VecRestoreArrayRead(x, &a);
}

void set_owned_values(Vec x, const std::vector<double>& v)
{
  PetscInt n = 0;
  VecGetLocalSize(x, &n);
  if (static_cast<PetscInt>(v.size()) != n)
    throw std::runtime_error("an array of " + std::to_string(v.size()) +
                             " values for a vector of " + std::to_string(n));
  double* a = nullptr;
  VecGetArray(x, &a);
  std::copy(v.begin(), v.end(), a);
  VecRestoreArray(x, &a);
}
} // namespace damseis::linalg
