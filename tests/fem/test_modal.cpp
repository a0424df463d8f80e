// Natural frequencies of a uniform shear column (ElasticModel stiffness
// and mass, linalg::solve_modes). Run serial and on 2 MPI ranks.
//
// Setup: rectangle of width W = H/10 = 10 m and height H = 100 m, E = 30
// GPa, nu = 0.2, rho = 2500 kg/m3; all displacements fixed at the base
// (y = 0) and the vertical displacement constrained to zero everywhere
// (rows and columns of the y dofs removed from K and M: 1 on the diagonal
// of K, 0 on that of M, so solve_modes treats them as fixed dofs). The
// sides and the top are free.
//
// Reference: with u_y = 0 the lowest modes are u_x = u(y) with
// rho w^2 u = -G u'', u(0) = 0, u'(H) = 0 (vertically propagating shear
// waves, fixed base, free top), so
//   f_n = (2n - 1) c_s / (4 H),  c_s = sqrt(G / rho),  G = E / (2 (1 + nu)):
// c_s = 2236.07 m/s, f_1..3 = 5.590, 16.771, 27.951 Hz. Modes with a
// variation across the width are far higher (the width is H/10 and they
// involve lambda + 2 mu), so these are the three lowest.
//
// Discretisation error: conforming Galerkin with the consistent mass
// gives upper bounds f_h >= f_n, and eigenvalue errors O(h^{2p}) for
// degree p, so the frequency error is O(h^{2p}) too (f ~ sqrt(lambda)
// halves the relative error but keeps the order). The exact eigenfunction
// depends on y only and is represented exactly across the width, so only
// the vertical mesh size matters: the meshes have 2 cells across and ny
// layers. The observed rates are printed; the bounds on them are set a
// little below 2p to allow for the pre-asymptotic range.
// Observed (serial and 2 ranks), relative frequency errors of modes 1-3:
//   P1 ny = 40: 6.4e-5, 5.7e-4, 1.6e-3; ny = 80: 1.6e-5, 1.4e-4, 4.0e-4
//     (rates 2.00, 2.00, 2.00);
//   P2 ny = 8: 1.0e-6, 8.0e-5, 6.0e-4; ny = 16: 6.0e-8, 4.8e-6, 3.7e-5
//     (rates 4.06, 4.04, 4.01).
// Mode shapes: |Phi^T M Phi - I| ~ 1e-14, phi^T K phi = omega^2 to 1e-13,
// u_y = 0 exactly, mode 1 within 3.9e-4 (P1, ny = 40) and 1.5e-5 (P2,
// ny = 8) of sin(pi y / 2H) at the nodes.
#include "fem_test_support.h"

#include <damseis/fem/elastic_model.h>
#include <damseis/geometry/tags.h>
#include <damseis/linalg/modal.h>

#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <petsclog.h>
#include <vector>

#include <gtest/gtest.h>
#include <mpi.h>
#include <petscmat.h>

namespace
{
using damseis::fem::ElasticModel;
using damseis::fem::Material;
using namespace damseis::test;
namespace tags = damseis::tags;

constexpr double H = 100, W = 10, E = 30e9, nu = 0.2, rho = 2500;

double exact_frequency(int n)
{
  const double G = E / (2 * (1 + nu));
  return (2 * n - 1) * std::sqrt(G / rho) / (4 * H);
}

/// Modal results of the column with ny layers of elements of degree
/// `degree`.
struct Column
{
  std::vector<double> f;     ///< 3 lowest frequencies [Hz]
  double orthonormality = 0; ///< max |phi_i^T M phi_j - delta_ij|
  double stiffness = 0;      ///< max |phi_i^T K phi_i / (2 pi f_i)^2 - 1|
  double uy = 0;             ///< max |phi_y| / max |phi_x| (constraint)
  double shape = 0; ///< mode 1: max |phi_x / phi_x(top) - sin(pi y / 2H)|
};

/// The column's stiffness and mass with u_y removed (1 on the diagonal of
/// K, 0 on that of M).
struct ColumnMatrices
{
  std::unique_ptr<ElasticModel> em;
  PMat K, M;
};

ColumnMatrices column_matrices(int degree, std::size_t ny)
{
  const Model m = rectangle_model(MPI_COMM_WORLD, {0, 0}, {W, H}, {2, ny},
                                  [](const Point& p) {
                                    return p[1] < 1e-9 ? int(tags::dam_base)
                                                       : int(tags::crest);
                                  });
  auto em = std::make_unique<ElasticModel>(
      m, degree, std::map<int, Material>{{tags::dam, Material{E, nu, rho}}});
  em->fix({tags::dam_base});
  PMat K = own(em->assemble_stiffness());
  PMat M = own(em->assemble_mass(nullptr));

  // Global indices of the owned y dofs
  const auto& map = *em->V()->dofmap()->index_map;
  const int bs = em->V()->dofmap()->index_map_bs();
  std::vector<PetscInt> rows;
  for (std::int32_t i = 0; i < map.size_local(); ++i)
    rows.push_back(bs * (map.local_range()[0] + i) + 1);
  MatZeroRowsColumns(K.mat(), rows.size(), rows.data(), 1.0, nullptr, nullptr);
  MatZeroRowsColumns(M.mat(), rows.size(), rows.data(), 0.0, nullptr, nullptr);
  return {std::move(em), std::move(K), std::move(M)};
}

Column column(int degree, std::size_t ny)
{
  ColumnMatrices cm = column_matrices(degree, ny);
  ElasticModel& em = *cm.em;
  PMat &K = cm.K, &M = cm.M;
  const auto& map = *em.V()->dofmap()->index_map;
  const int bs = em.V()->dofmap()->index_map_bs();

  PetscErrorRecorder errors;
  damseis::linalg::Modes modes =
      damseis::linalg::solve_modes(K.mat(), M.mat(), 3);
  errors.expect_none("solve_modes");
  Column c;
  c.f = modes.frequencies_hz;
  const double two_pi = 2 * std::acos(-1.0);
  for (std::size_t i = 0; i < modes.shapes.size(); ++i)
  {
    for (std::size_t j = 0; j < modes.shapes.size(); ++j)
    {
      const double mij = quad(M.mat(), modes.shapes[i], modes.shapes[j]);
      c.orthonormality = std::max(c.orthonormality, std::abs(mij - (i == j)));
    }
    const double w2 = std::pow(two_pi * c.f[i], 2);
    c.stiffness = std::max(
        c.stiffness,
        std::abs(quad(K.mat(), modes.shapes[i], modes.shapes[i]) / w2 - 1));
  }

  // Mode 1 against sin(pi y / 2H), normalised by its value at the top
  const std::vector<double> X = em.V()->tabulate_dof_coordinates(false);
  const std::vector<double> phi = owned_values(modes.shapes[0]);
  double top = 0, ux = 0, uy = 0;
  for (std::int32_t i = 0; i < map.size_local(); ++i)
  {
    ux = std::max(ux, std::abs(phi[bs * i]));
    uy = std::max(uy, std::abs(phi[bs * i + 1]));
    if (std::abs(X[3 * i + 1] - H) < 1e-9)
      top = std::max(top, std::abs(phi[bs * i]));
  }
  top = global_max(top);
  c.uy = global_max(uy) / global_max(ux);
  double sign = 0; // orientation of the computed mode
  for (std::int32_t i = 0; i < map.size_local(); ++i)
    if (std::abs(X[3 * i + 1] - H) < 1e-9)
      sign = phi[bs * i] > 0 ? 1 : -1;
  sign = global_max(sign) > 0 ? 1 : -1;
  double shape = 0;
  for (std::int32_t i = 0; i < map.size_local(); ++i)
  {
    const double y = X[3 * i + 1];
    shape = std::max(shape, std::abs(sign * phi[bs * i] / top -
                                     std::sin(std::acos(-1.0) * y / (2 * H))));
  }
  c.shape = global_max(shape);
  return c;
}

/// Checks one degree: the coarse mesh within 0.5 %, upper bounds, and the
/// observed order of convergence between the two meshes.
void check_degree(int degree, std::size_t ny, double min_rate)
{
  const Column cc = column(degree, ny), cf = column(degree, 2 * ny);
  const auto &fc = cc.f, &ff = cf.f;
  ASSERT_EQ(fc.size(), 3u);
  ASSERT_EQ(ff.size(), 3u);
  // solve_modes returns M-normalised shapes (modal.h) that satisfy the
  // constraint u_y = 0 and the Rayleigh quotient phi^T K phi = omega^2;
  // mode 1 is sin(pi y / 2H) up to the discretisation error.
  print_metric(fmt("shear column P", degree, " ny=", ny,
                   ": |Phi^T M Phi - I| = ", cc.orthonormality,
                   ", |phi^T K phi / w^2 - 1| = ", cc.stiffness,
                   ", |phi_y|/|phi_x| = ", cc.uy, ", mode 1 shape error ",
                   cc.shape, " (ny=", 2 * ny, ": ", cf.shape, ")"));
  EXPECT_LT(cc.orthonormality, 1e-8);
  EXPECT_LT(cc.stiffness, 1e-8);
  EXPECT_LT(cc.uy, 1e-12);
  EXPECT_LT(cc.shape, 1e-3);
  EXPECT_LT(cf.shape, cc.shape);
  for (int n = 1; n <= 3; ++n)
  {
    const double fe = exact_frequency(n);
    const double ec = (fc[n - 1] - fe) / fe, ef = (ff[n - 1] - fe) / fe;
    const double rate = std::log2(ec / ef);
    print_metric(fmt("shear column P", degree, " mode ", n, ": exact ", fe,
                     " Hz, ny=", ny, " f=", fc[n - 1], " err ", ec, "; ny=",
                     2 * ny, " f=", ff[n - 1], " err ", ef, "; rate ", rate));
    EXPECT_LT(std::abs(ec), 5e-3) << "mode " << n << ", ny = " << ny;
    // Rayleigh-Ritz upper bound (up to the eigensolver tolerance)
    EXPECT_GT(ec, -1e-9) << "mode " << n;
    EXPECT_GT(ef, -1e-9) << "mode " << n;
    EXPECT_LT(ef, ec) << "mode " << n;
    EXPECT_GT(rate, min_rate) << "mode " << n;
  }
}
} // namespace

TEST(ShearColumn, ExactFrequencies)
{
  // Hand values of the reference: c_s = sqrt(12.5e9 / 2500) = 2236.068
  EXPECT_NEAR(exact_frequency(1), 5.590170, 1e-6);
  EXPECT_NEAR(exact_frequency(3), 27.950850, 1e-6);
}

TEST(ShearColumn, P1FrequenciesConvergeAtSecondOrder)
{
  // Theory: rate 2 (eigenvalue error O(h^2))
  check_degree(1, 40, 1.8);
}

TEST(ShearColumn, P2FrequenciesConvergeAtFourthOrder)
{
  // Theory: rate 4 (eigenvalue error O(h^4))
  check_degree(2, 8, 3.5);
}

// Two mass matrices with one stiffness (the dam with and without added
// mass) and the static solve: K is factorised once. Reference: with
// M2 = 4 M every frequency halves exactly; the frequencies of M equal those
// of a solve of M alone (both to the eigensolver tolerance 1e-10: 1e-8
// relative); K x = K 1 gives x = 1 (1e-8, a direct solve of a
// well-conditioned column); and PETSc's log counts one numeric Cholesky
// factorisation for all of it.
TEST(ShearColumn, TwoMassMatricesAndStaticSolveShareOneFactorisation)
{
  ColumnMatrices cm = column_matrices(2, 8);
  Mat m4;
  MatDuplicate(cm.M.mat(), MAT_COPY_VALUES, &m4);
  MatScale(m4, 4.0);
  PMat M4 = own(m4);
  const std::vector<double> alone =
      damseis::linalg::solve_modes(cm.K.mat(), cm.M.mat(), 3).frequencies_hz;

  PetscLogDefaultBegin();
  PetscLogEvent chol = 0, lu = 0;
  PetscLogEventGetId("MatCholFctrNum", &chol);
  PetscLogEventGetId("MatLUFactorNum", &lu);
  auto factorisations = [&]
  {
    PetscEventPerfInfo a{}, b{};
    PetscLogEventGetPerfInfo(0, chol, &a);
    PetscLogEventGetPerfInfo(0, lu, &b);
    return a.count + b.count;
  };
  const int before = factorisations();
  // The callback solves K x = K 1 with the same factors (the static load
  // case of the seismic engines): x = 1 to the factorisation's accuracy.
  Vec one, b, x;
  MatCreateVecs(cm.K.mat(), &one, &b);
  VecDuplicate(b, &x);
  VecSet(one, 1.0);
  MatMult(cm.K.mat(), one, b);
  PetscErrorRecorder errors;
  const std::vector<damseis::linalg::Modes> both =
      damseis::linalg::solve_modes(cm.K.mat(), {cm.M.mat(), M4.mat()}, 3,
                                   [&](KSP ksp) { KSPSolve(ksp, b, x); });
  errors.expect_none("solve_modes");
  VecAXPY(x, -1.0, one);
  double err = 0.0;
  VecNorm(x, NORM_INFINITY, &err);
  print_metric(fmt("K x = K 1 with the modal factors: max |x - 1| = ", err));
  EXPECT_LT(err, 1e-8);
  for (Vec* v : {&one, &b, &x})
    VecDestroy(v);
  const int count = factorisations() - before;
  print_metric(fmt("two mass matrices: ", count, " factorisation(s)"));
  ASSERT_EQ(both.size(), 2u);
  EXPECT_EQ(count, 1);
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_NEAR(both[0].frequencies_hz[i] / alone[i], 1.0, 1e-8);
    EXPECT_NEAR(both[1].frequencies_hz[i] / both[0].frequencies_hz[i], 0.5,
                1e-8);
  }
}
