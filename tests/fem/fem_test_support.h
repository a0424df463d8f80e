// Helpers shared by the finite element verification tests (test_patch,
// test_static_koyna, test_westergaard, test_modal, test_form_identities):
// models on DOLFINx built-in meshes, PETSc ownership and small collective
// reductions. Everything here is collective on the mesh communicator.
#pragma once

#include <damseis/fem/elastic_model.h>
#include <damseis/geometry/gmsh_mesh.h>
#include <damseis/geometry/tags.h>
#include <damseis/linalg/direct_solver.h>
#include <damseis/linalg/petsc_vectors.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <memory>
#include <numeric>
#include <span>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/Function.h>
#include <dolfinx/fem/FunctionSpace.h>
#include <dolfinx/la/petsc.h>
#include <dolfinx/mesh/Geometry.h>
#include <dolfinx/mesh/Mesh.h>
#include <dolfinx/mesh/MeshTags.h>
#include <dolfinx/mesh/Topology.h>
#include <dolfinx/mesh/cell_types.h>
#include <dolfinx/mesh/generation.h>
#include <dolfinx/mesh/utils.h>
#include <gtest/gtest.h>
#include <mpi.h>
#include <petscmat.h>
#include <petscsys.h>
#include <petscvec.h>

namespace damseis::test
{
using damseis::geometry::Model;
using PVec = dolfinx::la::petsc::Vector; ///< owns (destroys) a Vec
using PMat = dolfinx::la::petsc::Matrix; ///< owns (destroys) a Mat
using Point = std::array<double, 3>;

/// Takes ownership of a new Vec / Mat returned by ElasticModel.
inline PVec own(Vec v)
{
  return PVec(v, false);
}
inline PMat own(Mat m)
{
  return PMat(m, false);
}

inline double global_sum(double v, MPI_Comm comm = MPI_COMM_WORLD)
{
  double g = 0;
  MPI_Allreduce(&v, &g, 1, MPI_DOUBLE, MPI_SUM, comm);
  return g;
}

inline double global_max(double v, MPI_Comm comm = MPI_COMM_WORLD)
{
  double g = 0;
  MPI_Allreduce(&v, &g, 1, MPI_DOUBLE, MPI_MAX, comm);
  return g;
}

/// Prints an observed quantity on rank 0 (for the record in the test log).
inline void print_metric(const std::string& text)
{
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::cout << "[   metric ] " << text << std::endl;
}

/// Concatenates values into a string for print_metric: fmt("err ", 1e-3).
template <typename... T>
std::string fmt(const T&... v)
{
  std::ostringstream os;
  os.precision(6);
  ((os << v), ...);
  return os.str();
}

/// Moves the interior geometry nodes (local owned + ghost) of the box
/// [lo, hi] by a smooth, deterministic perturbation of amplitude `amp` per
/// coordinate. The perturbation is a function of the original coordinates only,
/// so nodes shared between ranks move identically. Boundary nodes stay (the
/// domain is unchanged).
inline void perturb_interior(dolfinx::mesh::Mesh& mesh, const Point& lo,
                             const Point& hi, double amp)
{
  const int gdim = mesh.geometry().dim();
  std::span<double> x = mesh.geometry().x();
  for (std::size_t i = 0; i < x.size() / 3; ++i)
  {
    double* p = &x[3 * i];
    bool interior = true;
    for (int k = 0; k < gdim; ++k)
    {
      const double tol = 1e-10 * (hi[k] - lo[k]);
      interior = interior and p[k] > lo[k] + tol and p[k] < hi[k] - tol;
    }
    if (!interior)
      continue;
    const Point p0 = {p[0], p[1], p[2]};
    for (int k = 0; k < gdim; ++k)
    {
      p[k] += amp * std::sin(12.9898 * p0[0] + 78.233 * p0[1] + 37.719 * p0[2] +
                             1.7 * k + 0.3);
    }
  }
}

/// Signed measure of every local cell (area in 2D, volume in 3D); used to
/// check that a perturbed mesh has no inverted or degenerate cells.
inline double min_cell_measure(const dolfinx::mesh::Mesh& mesh)
{
  const int tdim = mesh.topology().dim();
  const auto& dofs = mesh.geometry().dofmap();
  std::span<const double> x = mesh.geometry().x();
  double m = 1e300;
  for (std::int32_t c = 0; c < dofs.num_nodes(); ++c)
  {
    auto v = dofs.links(c);
    auto d = [&](int a, int k) { return x[3 * v[a] + k] - x[3 * v[0] + k]; };
    double s;
    if (tdim == 2)
      s = 0.5 * std::abs(d(1, 0) * d(2, 1) - d(1, 1) * d(2, 0));
    else
    {
      s = std::abs(d(1, 0) * (d(2, 1) * d(3, 2) - d(2, 2) * d(3, 1)) -
                   d(1, 1) * (d(2, 0) * d(3, 2) - d(2, 2) * d(3, 0)) +
                   d(1, 2) * (d(2, 0) * d(3, 1) - d(2, 1) * d(3, 0))) /
          6.0;
    }
    m = std::min(m, s);
  }
  double g = 0;
  MPI_Allreduce(&m, &g, 1, MPI_DOUBLE, MPI_MIN, mesh.comm());
  return g;
}

/// Wraps a DOLFINx built-in mesh as a geometry::Model: every local cell
/// (owned and ghost) is region tags::dam; every exterior facet gets the
/// tag `facet_tag(midpoint)` (no tag if it returns a negative value).
inline Model model_from_mesh(std::shared_ptr<dolfinx::mesh::Mesh> mesh,
                             const std::function<int(const Point&)>& facet_tag)
{
  const int tdim = mesh->topology().dim();
  const int fdim = tdim - 1;
  mesh->topology_mutable().create_entities(fdim);
  mesh->topology_mutable().create_connectivity(fdim, tdim);

  auto cmap = mesh->topology().index_map(tdim);
  std::vector<std::int32_t> cells(cmap->size_local() + cmap->num_ghosts());
  std::iota(cells.begin(), cells.end(), 0);
  std::vector<std::int32_t> cvals(cells.size(), damseis::tags::dam);
  auto ct = std::make_shared<dolfinx::mesh::MeshTags<std::int32_t>>(
      mesh, tdim, std::move(cells), std::move(cvals));

  std::vector<std::int32_t> ext =
      dolfinx::mesh::exterior_facet_indices(mesh->topology());
  std::sort(ext.begin(), ext.end());
  const auto g = dolfinx::mesh::entities_to_geometry(*mesh, fdim, ext, false);
  const std::size_t nv = ext.empty() ? 0 : g.size() / ext.size();
  std::span<const double> x = mesh->geometry().x();
  std::vector<std::int32_t> facets, fvals;
  for (std::size_t i = 0; i < ext.size(); ++i)
  {
    Point mid = {0, 0, 0};
    for (std::size_t a = 0; a < nv; ++a)
      for (int k = 0; k < 3; ++k)
        mid[k] += x[3 * g[nv * i + a] + k] / double(nv);
    const int t = facet_tag(mid);
    if (t >= 0)
    {
      facets.push_back(ext[i]);
      fvals.push_back(t);
    }
  }
  auto ft = std::make_shared<dolfinx::mesh::MeshTags<std::int32_t>>(
      mesh, fdim, std::move(facets), std::move(fvals));
  return Model{mesh, ct, ft};
}

/// Triangle mesh of [x0, x1] x [y0, y1] with nx x ny squares, as a Model.
inline Model rectangle_model(MPI_Comm comm, std::array<double, 2> lo,
                             std::array<double, 2> hi,
                             std::array<std::size_t, 2> n,
                             const std::function<int(const Point&)>& facet_tag)
{
  auto mesh =
      std::make_shared<dolfinx::mesh::Mesh>(dolfinx::mesh::create_rectangle(
          comm, {lo, hi}, n, dolfinx::mesh::CellType::triangle,
          dolfinx::mesh::GhostMode::shared_facet));
  return model_from_mesh(mesh, facet_tag);
}

/// Tetrahedral mesh of a box with n[0] x n[1] x n[2] cubes, as a Model.
inline Model box_model(MPI_Comm comm, Point lo, Point hi,
                       std::array<std::size_t, 3> n,
                       const std::function<int(const Point&)>& facet_tag)
{
  auto mesh = std::make_shared<dolfinx::mesh::Mesh>(dolfinx::mesh::create_box(
      comm, {lo, hi}, n, dolfinx::mesh::CellType::tetrahedron,
      dolfinx::mesh::GhostMode::shared_facet));
  return model_from_mesh(mesh, facet_tag);
}

/// Euclidean norm of a vector (collective).
inline double norm2(Vec x)
{
  double n = 0;
  VecNorm(x, NORM_2, &n);
  return n;
}

/// Number of owned entries (unrolled) of a space's vectors.
inline std::int32_t owned_size(const dolfinx::fem::FunctionSpace& V)
{
  return V.dofmap()->index_map->size_local() * V.dofmap()->index_map_bs();
}

/// Sets the nodal values of a Lagrange function: u(x_i) = f(x_i) at every
/// local (owned and ghost) dof point, for each component.
inline void
set_nodal(dolfinx::fem::Function<double>& u,
          const std::function<std::array<double, 3>(const Point&)>& f)
{
  const auto& V = *u.function_space();
  const int bs = V.dofmap()->index_map_bs();
  const std::vector<double> X = V.tabulate_dof_coordinates(false);
  std::span<double> a = u.x()->mutable_array();
  for (std::size_t i = 0; i < X.size() / 3; ++i)
  {
    const auto v = f({X[3 * i], X[3 * i + 1], X[3 * i + 2]});
    for (int k = 0; k < bs; ++k)
      a[bs * i + k] = v[k];
  }
}

/// a^T M b (collective).
inline double quad(Mat M, Vec a, Vec b)
{
  Vec Mb;
  MatCreateVecs(M, nullptr, &Mb);
  MatMult(M, b, Mb);
  double r = 0;
  VecDot(a, Mb, &r);
  VecDestroy(&Mb);
  return r;
}

/// Records the PETSc errors raised while it lives instead of letting the
/// runner's abort handler (main.cpp) stop the whole run: a PETSc error
/// inside a library call then fails the test that made it (expect_none)
/// and the other tests still run. Library code ignores PETSc return codes,
/// so execution goes on after the error.
class PetscErrorRecorder
{
public:
  PetscErrorRecorder() { PetscPushErrorHandler(&handler, this); }
  ~PetscErrorRecorder() { PetscPopErrorHandler(); }
  PetscErrorRecorder(const PetscErrorRecorder&) = delete;
  PetscErrorRecorder& operator=(const PetscErrorRecorder&) = delete;

  /// Fails the current test if any rank recorded an error (collective).
  void expect_none(const std::string& where) const
  {
    const double n = global_sum(double(_errors.size()));
    EXPECT_EQ(n, 0.0) << "PETSc error(s) inside " << where << ": "
                      << (_errors.empty() ? std::string("(on another rank)")
                                          : _errors.front());
  }

private:
  static PetscErrorCode handler(MPI_Comm, int line, const char* fun,
                                const char* file, PetscErrorCode n,
                                PetscErrorType p, const char* mess, void* ctx)
  {
    if (p == PETSC_ERROR_INITIAL)
    {
      static_cast<PetscErrorRecorder*>(ctx)->_errors.push_back(
          std::string(fun) + " (" + file + ":" + std::to_string(line) + "): " +
          (mess ? mess : "") + " [PETSc error " + std::to_string(n) + "]");
    }
    return n;
  }
  std::vector<std::string> _errors;
};

/// Solves K u = b with the project's direct solver into the Function u
/// (ghosts updated). A PETSc error inside the solver fails the test.
inline void solve(Mat K, Vec b, dolfinx::fem::Function<double>& u)
{
  PetscErrorRecorder errors;
  damseis::linalg::DirectSolver solver(u.function_space()->mesh()->comm());
  solver.factorize(K);
  Vec x = dolfinx::la::petsc::create_vector_wrap(*u.x());
  solver.solve(b, x);
  VecDestroy(&x);
  u.x()->scatter_fwd();
  errors.expect_none("DirectSolver (" + solver.name() + ")");
}

/// Owned entries of a (ghosted or not) Vec, copied.
using damseis::linalg::owned_values;
} // namespace damseis::test
