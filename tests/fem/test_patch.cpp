// Patch tests of the compiled elasticity forms (forms/elasticity_{2d,3d}.py)
// through ElasticModel: 2D plane strain, 2D plane stress and 3D, degrees 1
// and 2. Run serial and on 2 MPI ranks.
//
// Reference (independent of the code): a displacement u = A x + b is
// represented exactly by every Lagrange space, its strain eps = sym(A) is
// constant, so the stress is constant and div(sigma) = 0: with no body
// load and u prescribed on the whole boundary, the exact solution is the
// affine field itself, and a consistent discretisation must reproduce it
// to round-off (the patch test). The constant stress is computed here from
// Hooke's law written out by hand:
//   plane strain / 3D: sigma = 2 mu eps + lambda tr(eps) I,
//     mu = E / (2 (1 + nu)), lambda = E nu / ((1 + nu)(1 - 2 nu));
//   plane stress: sxx = E/(1-nu^2) (exx + nu eyy), syy = E/(1-nu^2) (eyy +
//     nu exx), sxy = E/(1+nu) exy (not through the lambda* of the code).
// The mesh is a structured rectangle / box whose interior nodes are moved
// by a smooth perturbation, so the elements are irregular.
//
// Tolerances: the discrete problem is solved exactly up to round-off,
// ~cond(K) * 1e-16 with cond(K) <= 1e4 on these meshes of a few hundred
// cells, hence 1e-10 relative on displacements; the stress operator only
// differentiates the (exact) field at the stress points, hence 1e-9
// relative (round-off of the element Jacobians and of the lumped weights).
// Observed (serial and 2 ranks): displacement errors 2e-16 .. 3e-15,
// stress errors 4e-15 .. 1e-13 (affine), 7e-15 .. 1e-14 (quadratic).
#include "fem_test_support.h"

#include <damseis/fem/elastic_model.h>
#include <damseis/geometry/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include <dolfinx/fem/petsc.h>
#include <gtest/gtest.h>
#include <mpi.h>

namespace
{
using damseis::fem::ElasticModel;
using damseis::fem::Material;
using damseis::fem::PlaneMode;
using namespace damseis::test;
namespace tags = damseis::tags;
using Function = dolfinx::fem::Function<double>;
using Tensor = std::array<std::array<double, 3>, 3>;

constexpr double E = 30e9, nu = 0.3;

struct PatchCase
{
  int dim;
  int degree;
  PlaneMode mode;
  std::string name;
};

/// gtest prints the case by name.
void PrintTo(const PatchCase& c, std::ostream* os)
{
  *os << c.name;
}

/// A general displacement gradient: every entry non-zero, not symmetric.
constexpr Tensor A = {{{1.2e-3, -0.7e-3, 0.5e-3},
                       {0.4e-3, -0.9e-3, 0.8e-3},
                       {-0.6e-3, 0.3e-3, 1.1e-3}}};
constexpr std::array<double, 3> b = {2e-3, -1e-3, 0.5e-3};

/// Second derivatives of the quadratic field: u_k = ... + 1/2 x^T Q_k x,
/// Q_k symmetric with all entries non-zero.
double Q(int k, int j, int l)
{
  const int s = std::min(j, l), t = std::max(j, l);
  return 1e-3 * (0.35 + 0.2 * k - 0.45 * s + 0.3 * t + 0.1 * s * t) *
         ((k + s + t) % 2 ? -1.0 : 1.0);
}

/// Stress vector (2D: sxx, syy, sxy; 3D: sxx, syy, szz, sxy, syz, sxz) of
/// the displacement gradient G, by Hooke's law (see the header).
std::vector<double> hooke(const Tensor& G, int dim, PlaneMode mode)
{
  double e[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      e[i][j] = 0.5 * (G[i][j] + G[j][i]);
  const double mu = E / (2 * (1 + nu));
  const double lam = E * nu / ((1 + nu) * (1 - 2 * nu));
  if (dim == 2 and mode == PlaneMode::plane_stress)
  {
    const double c = E / (1 - nu * nu);
    return {c * (e[0][0] + nu * e[1][1]), c * (e[1][1] + nu * e[0][0]),
            E / (1 + nu) * e[0][1]};
  }
  double tr = 0;
  for (int i = 0; i < dim; ++i)
    tr += e[i][i];
  auto s = [&](int i, int j) { return 2 * mu * e[i][j] + (i == j) * lam * tr; };
  if (dim == 2)
    return {s(0, 0), s(1, 1), s(0, 1)};
  return {s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(1, 2), s(0, 2)};
}

/// Gradient of u at p restricted to `dim` (the z-row/column are zero in
/// 2D); `quadratic` adds the Q terms.
Tensor gradient(const Point& p, int dim, bool quadratic)
{
  Tensor G{};
  for (int k = 0; k < dim; ++k)
    for (int j = 0; j < dim; ++j)
    {
      G[k][j] = A[k][j];
      if (quadratic)
        for (int l = 0; l < dim; ++l)
          G[k][j] += Q(k, j, l) * p[l];
    }
  return G;
}

std::array<double, 3> displacement(const Point& p, int dim, bool quadratic)
{
  std::array<double, 3> u{};
  for (int k = 0; k < dim; ++k)
  {
    u[k] = b[k];
    for (int j = 0; j < dim; ++j)
    {
      u[k] += A[k][j] * p[j];
      if (quadratic)
        for (int l = 0; l < dim; ++l)
          u[k] += 0.5 * Q(k, j, l) * p[j] * p[l];
    }
  }
  return u;
}

/// Irregular mesh of a rectangle / box, every boundary facet tagged
/// dam_base (the face that ElasticModel::fix is given).
Model patch_model(int dim)
{
  auto all = [](const Point&) { return int(tags::dam_base); };
  if (dim == 2)
  {
    Model m =
        rectangle_model(MPI_COMM_WORLD, {0.3, -0.4}, {1.7, 0.9}, {4, 3}, all);
    perturb_interior(*m.mesh, {0.3, -0.4, 0}, {1.7, 0.9, 0}, 0.03);
    return m;
  }
  Model m = box_model(MPI_COMM_WORLD, {0.3, -0.4, 0.1}, {1.7, 0.9, 1.2},
                      {3, 3, 3}, all);
  perturb_interior(*m.mesh, {0.3, -0.4, 0.1}, {1.7, 0.9, 1.2}, 0.03);
  return m;
}

/// Max over the owned stress points of |B u - sigma_exact(x)|, and max
/// |sigma_exact|, both global.
std::pair<double, double> stress_error(const ElasticModel& em,
                                       const Function& u, bool quadratic,
                                       PlaneMode mode)
{
  const int dim = em.dim();
  PMat B = own(em.assemble_stress_operator());
  Vec s;
  MatCreateVecs(B.mat(), nullptr, &s);
  Vec uv = dolfinx::la::petsc::create_vector_wrap(*u.x());
  MatMult(B.mat(), uv, s);
  VecDestroy(&uv);
  const std::vector<double> sv = owned_values(s);
  VecDestroy(&s);

  const auto& S = *em.S();
  const int nc = S.dofmap()->index_map_bs();
  EXPECT_EQ(nc, em.forms().stress_size());
  const std::vector<double> X = S.tabulate_dof_coordinates(false);
  double err = 0, ref = 0;
  for (std::size_t i = 0; i < sv.size() / nc; ++i)
  {
    const Point p = {X[3 * i], X[3 * i + 1], X[3 * i + 2]};
    const auto exact = hooke(gradient(p, dim, quadratic), dim, mode);
    for (int c = 0; c < nc; ++c)
    {
      err = std::max(err, std::abs(sv[nc * i + c] - exact[c]));
      ref = std::max(ref, std::abs(exact[c]));
    }
  }
  return {global_max(err), global_max(ref)};
}

class Patch : public ::testing::TestWithParam<PatchCase>
{
};
class PatchP2 : public ::testing::TestWithParam<PatchCase>
{
};

std::string case_name(const ::testing::TestParamInfo<PatchCase>& info)
{
  return info.param.name;
}
} // namespace

TEST_P(Patch, AffineFieldIsReproducedWithConstantStress)
{
  const PatchCase c = GetParam();
  Model m = patch_model(c.dim);
  ASSERT_GT(min_cell_measure(*m.mesh), 0.0) << "perturbed mesh is invalid";
  ElasticModel em(m, c.degree, {{tags::dam, Material{E, nu, 2500}}}, c.mode);
  em.fix({tags::dam_base});
  auto V = em.V();
  const std::int32_t n_owned = owned_size(*V);
  auto affine = [&](const Point& p) { return displacement(p, c.dim, false); };

  Function u_exact(V), u_bc(V), w(V);
  set_nodal(u_exact, affine);
  const std::vector<std::int32_t> fixed = em.fixed_dofs();
  std::vector<char> is_fixed(n_owned, 0);
  {
    std::span<const double> ue = u_exact.x()->array();
    std::span<double> ub = u_bc.x()->mutable_array();
    for (std::int32_t i : fixed)
    {
      ub[i] = ue[i];
      if (i < n_owned)
        is_fixed[i] = 1;
    }
  }
  const double n_fixed =
      global_sum(std::count(is_fixed.begin(), is_fixed.end(), 1));
  const double n_total = global_sum(n_owned);
  ASSERT_GT(n_fixed, 0.0);
  ASSERT_LT(n_fixed, n_total); // there are interior (free) dofs

  // 1. The internal force of the exact field vanishes at the free dofs
  // (each interior node is in equilibrium): relative to the boundary
  // forces, zero to round-off.
  {
    PVec f = own(em.assemble_internal_force(u_exact));
    const auto fv = owned_values(f.vec());
    double free_max = 0, fixed_max = 0;
    for (std::int32_t i = 0; i < n_owned; ++i)
    {
      double& m = is_fixed[i] ? fixed_max : free_max;
      m = std::max(m, std::abs(fv[i]));
    }
    free_max = global_max(free_max);
    fixed_max = global_max(fixed_max);
    EXPECT_GT(fixed_max, 0.0);
    EXPECT_LT(free_max, 1e-11 * fixed_max)
        << "interior residual of the affine field";
  }

  // 2. Solve with u = u_exact on the boundary: u = u_bc + w with
  // K_ff w_f = -K_fb u_b (lifting through the internal force of u_bc,
  // which is zero inside).
  {
    PVec rhs = own(em.assemble_internal_force(u_bc));
    VecScale(rhs.vec(), -1.0);
    dolfinx::fem::petsc::set_bc(rhs.vec(), em.bcs(), nullptr);
    PMat K = own(em.assemble_stiffness());
    solve(K.mat(), rhs.vec(), w);
  }
  Function u(V);
  {
    std::span<double> a = u.x()->mutable_array();
    std::span<const double> ub = u_bc.x()->array(), wa = w.x()->array();
    for (std::size_t i = 0; i < a.size(); ++i)
      a[i] = ub[i] + wa[i];
  }
  double err = 0, ref = 0;
  {
    std::span<const double> a = u.x()->array(), ue = u_exact.x()->array();
    for (std::int32_t i = 0; i < n_owned; ++i)
    {
      err = std::max(err, std::abs(a[i] - ue[i]));
      ref = std::max(ref, std::abs(ue[i]));
    }
  }
  err = global_max(err), ref = global_max(ref);
  EXPECT_LT(err, 1e-10 * ref) << "max |u - u_exact| = " << err;

  // 3. B u is the constant stress at every stress point.
  const auto [serr, sref] = stress_error(em, u, false, c.mode);
  print_metric(fmt("patch ", c.name, ": |u - u_exact|/|u| = ", err / ref,
                   ", |s - s_exact|/|s| = ", serr / sref));
  EXPECT_GT(sref, 1e6);
  EXPECT_LT(serr, 1e-9 * sref) << "max stress error " << serr << " Pa";
}

TEST_P(PatchP2, QuadraticFieldGivesExactLinearStressAtStressPoints)
{
  // A quadratic field is exact in P2 and its stress is linear; the
  // vertex-quadrature stress operator must return it exactly at the
  // stress points (the vertices of each cell). No solve: this checks B.
  const PatchCase c = GetParam();
  Model m = patch_model(c.dim);
  ElasticModel em(m, c.degree, {{tags::dam, Material{E, nu, 2500}}}, c.mode);
  Function u(em.V());
  set_nodal(u, [&](const Point& p) { return displacement(p, c.dim, true); });
  const auto [serr, sref] = stress_error(em, u, true, c.mode);
  print_metric(
      fmt("quadratic ", c.name, ": |s - s_exact|/|s| = ", serr / sref));
  EXPECT_GT(sref, 1e6);
  EXPECT_LT(serr, 1e-9 * sref) << "max stress error " << serr << " Pa";

  // The field really is non-affine: its stress differs from that of the
  // affine part alone by much more than the tolerance.
  const auto [dev, dref] = stress_error(em, u, false, c.mode);
  EXPECT_GT(dev, 1e-2 * dref);
}

INSTANTIATE_TEST_SUITE_P(
    Forms, Patch,
    ::testing::Values(PatchCase{2, 1, PlaneMode::plane_strain, "PlaneStrainP1"},
                      PatchCase{2, 2, PlaneMode::plane_strain, "PlaneStrainP2"},
                      PatchCase{2, 1, PlaneMode::plane_stress, "PlaneStressP1"},
                      PatchCase{2, 2, PlaneMode::plane_stress, "PlaneStressP2"},
                      PatchCase{3, 1, PlaneMode::plane_strain, "Solid3dP1"},
                      PatchCase{3, 2, PlaneMode::plane_strain, "Solid3dP2"}),
    case_name);

INSTANTIATE_TEST_SUITE_P(
    Forms, PatchP2,
    ::testing::Values(PatchCase{2, 2, PlaneMode::plane_strain, "PlaneStrainP2"},
                      PatchCase{2, 2, PlaneMode::plane_stress, "PlaneStressP2"},
                      PatchCase{3, 2, PlaneMode::plane_strain, "Solid3dP2"}),
    case_name);
