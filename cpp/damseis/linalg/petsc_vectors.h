// PETSc vectors laid out like a matrix, their owned values, and their copy
// into a DOLFINx Function.
#pragma once

#include <dolfinx/fem/Function.h>
#include <dolfinx/la/petsc.h>
#include <vector>

namespace damseis::linalg
{
/// A new zero vector with the layout of the columns (rows) of A.
dolfinx::la::petsc::Vector column_vector(Mat A);
dolfinx::la::petsc::Vector row_vector(Mat A);
/// Copies `x` (owned values) into the Function `u` and updates its ghosts.
void to_function(Vec x, dolfinx::fem::Function<double>& u);
std::vector<double> owned_values(Vec x);
/// The owned values of `x` into `out` (resized; no allocation once large
/// enough).
void read_owned_values(Vec x, std::vector<double>& out);
void set_owned_values(Vec x, const std::vector<double>& v);
} // namespace damseis::linalg
