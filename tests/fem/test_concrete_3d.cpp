// The nonlinear concrete in 3D (fem::ConcreteModel on tetrahedra,
// forms/plasticity_3d.py), against the same independent references as in
// 2D (test_concrete_model.cpp, test_concrete_structure.cpp):
//  - elastic mode: the tangent assembled from the point tangents equals the
//    stiffness of the linear forms (forms/elasticity_3d.py, another kernel
//    and quadrature) and f_int(u) = K u: exact for P1 and P2 with the
//    quadrature used, so round-off (1e-11 relative);
//  - plastic and viscoplastic: the assembled consistent tangent times a
//    direction equals the central difference of the internal force (1e-4,
//    as in 2D: truncation and points changing active set);
//  - the concrete analysis in elastic mode (NonlinearNewmark, Newton on
//    the point stresses) reproduces the linear analysis (LinearNewmark with
//    its images) on the block under a ground motion: crest peak 1e-9, the
//    same frequencies, one Newton iteration per step;
//  - a bar pulled along x under displacement control dissipates the
//    fracture energy Gf times its section whatever the mesh (crack band,
//    Bazant & Oh 1983, with h = (6 V)^(1/3): exact for the six tetrahedra
//    of a cube; 3% as in 2D: the tail beyond the last increment, e^-8 Gf,
//    and the load-step quadrature; measured 0.999, 1.002, 0.996, the 2D
//    values to 6 digits: with nu = 0 both are the 1D bar). P1.
// A block 2 x 1 x 4 m fixed at its base z = 0.
#include "fem_test_support.h"
#include "tension_bar.h"

#include <damseis/analysis/linear_seismic.h>
#include <damseis/analysis/nonlinear_seismic.h>
#include <damseis/analysis/tied_concrete_system.h>
#include <damseis/fem/concrete_model.h>
#include <damseis/fem/tied_dofs.h>
#include <damseis/linalg/direct_solver.h>
#include <damseis/linalg/petsc_vectors.h>
#include <dolfinx/fem/petsc.h>

namespace
{
using namespace damseis::test;
using damseis::fem::ConcreteModel;
using damseis::fem::ElasticModel;
using damseis::fem::Material;
using damseis::fem::PlaneMode;
namespace tags = damseis::tags;
namespace material = damseis::material;
using Function = dolfinx::fem::Function<double>;

constexpr int base_tag = 5;
const Material block_concrete{30e9, 0.2, 2500};

struct Block
{
  std::unique_ptr<ElasticModel> fe;
  std::unique_ptr<ConcreteModel> cm;
};

Block block(int degree, material::Mode mode, double ft = 2.5e6)
{
  Block b;
  b.fe = std::make_unique<ElasticModel>(
      box_model(MPI_COMM_WORLD, {0, 0, 0}, {2, 1, 4}, {4, 2, 8},
                [](const Point& x) { return x[2] < 1e-12 ? base_tag : -1; }),
      degree, std::map<int, Material>{{tags::dam, block_concrete}});
  b.fe->fix({base_tag});
  material::ConcreteParameters p;
  p.E = block_concrete.E;
  p.nu = block_concrete.nu;
  p.fc0 = 10 * ft;
  p.ft0 = ft;
  p.Gf = 2000; // large: no strength reduction on 0.5 m cells
  p.mode = mode;
  b.cm = std::make_unique<ConcreteModel>(
      *b.fe, std::map<int, material::ConcreteParameters>{{tags::dam, p}},
      std::map<int, Material>{{tags::dam, block_concrete}},
      PlaneMode::plane_strain);
  return b;
}

/// The static response to a lateral body acceleration `ax` with gravity:
/// bending of the cantilever block, tension at its base.
PVec loading(ElasticModel& fe, double ax)
{
  PMat K = own(fe.assemble_stiffness());
  PVec F = own(fe.assemble_gravity({ax, 0.3 * ax, -9.81}));
  PVec u = own(fe.assemble_gravity({0, 0, 0}));
  damseis::linalg::DirectSolver solver(MPI_COMM_WORLD);
  solver.factorize(K.mat());
  solver.solve(F.vec(), u.vec());
  return u;
}

TEST(Concrete3D, ElasticModeReproducesLinearStiffness)
{
  for (int degree : {1, 2})
  {
    Block b = block(degree, material::Mode::elastic);
    EXPECT_EQ(b.cm->components(), 6);
    PMat K = own(b.fe->assemble_stiffness());
    PMat Kt = own(b.cm->assemble_tangent());
    MatAXPY(Kt.mat(), -1.0, K.mat(), SAME_NONZERO_PATTERN);
    double dk = 0, k = 0;
    MatNorm(Kt.mat(), NORM_FROBENIUS, &dk);
    MatNorm(K.mat(), NORM_FROBENIUS, &k);
    print_metric(fmt("P", degree, " elastic tangent vs K: ", dk / k));
    EXPECT_LT(dk / k, 1e-11);

    PVec u = loading(*b.fe, 20.0);
    Function uf(b.fe->V());
    damseis::linalg::to_function(u.vec(), uf);
    b.cm->update(uf, 0.01);
    PVec f = own(b.fe->assemble_gravity({0, 0, 0}));
    b.cm->assemble_internal_force(f.vec());
    PVec Ku = own(b.fe->assemble_gravity({0, 0, 0}));
    MatMult(K.mat(), u.vec(), Ku.vec());
    VecAXPY(f.vec(), -1.0, Ku.vec());
    print_metric(
        fmt("P", degree, " f_int - K u: ", norm2(f.vec()) / norm2(Ku.vec())));
    EXPECT_LT(norm2(f.vec()) / norm2(Ku.vec()), 1e-11);
  }
}

TEST(Concrete3D, TangentMatchesFiniteDifferenceOfInternalForce)
{
  for (material::Mode mode :
       {material::Mode::plastic, material::Mode::viscoplastic})
  {
    Block b = block(2, mode, 0.3e6);
    PVec u = loading(*b.fe, mode == material::Mode::plastic ? 60.0 : 40.0);
    Function uf(b.fe->V());
    damseis::linalg::to_function(u.vec(), uf);
    const double dt = 0.01;
    const auto stats = b.cm->update(uf, dt);
    ASSERT_EQ(stats.failed, 0);
    ASSERT_GT(stats.inelastic, 10) << "the load must make points yield";
    PMat Kt = own(b.cm->assemble_tangent());
    PVec d = loading(*b.fe, -15.0);
    VecScale(d.vec(), norm2(u.vec()) / norm2(d.vec()));
    PVec Kd = own(b.fe->assemble_gravity({0, 0, 0}));
    MatMult(Kt.mat(), d.vec(), Kd.vec());
    double best = 1e300;
    for (double h : {1e-5, 1e-6, 1e-7})
    {
      PVec fp = own(b.fe->assemble_gravity({0, 0, 0}));
      PVec fm = own(b.fe->assemble_gravity({0, 0, 0}));
      PVec up = own(b.fe->assemble_gravity({0, 0, 0}));
      VecWAXPY(up.vec(), h, d.vec(), u.vec());
      damseis::linalg::to_function(up.vec(), uf);
      ASSERT_EQ(b.cm->update(uf, dt).failed, 0);
      b.cm->assemble_internal_force(fp.vec());
      VecWAXPY(up.vec(), -h, d.vec(), u.vec());
      damseis::linalg::to_function(up.vec(), uf);
      ASSERT_EQ(b.cm->update(uf, dt).failed, 0);
      b.cm->assemble_internal_force(fm.vec());
      VecAXPY(fp.vec(), -1.0, fm.vec());
      VecScale(fp.vec(), 0.5 / h);
      VecAXPY(fp.vec(), -1.0, Kd.vec());
      const double err = norm2(fp.vec()) / norm2(Kd.vec());
      print_metric(fmt(
          mode == material::Mode::plastic ? "plastic" : "viscoplastic", ": ",
          stats.inelastic, " of ", stats.points, " points inelastic, h = ", h,
          ", |K_T d - FD| / |K_T d| = ", err));
      best = std::min(best, err);
    }
    EXPECT_LT(best, 1e-4);
  }
}

// The tangent change on tied unknowns (u = P u_r: bonded joints, P2
// contact's midside constraints), reduced cell by cell
// (analysis::TiedConcreteSystem), equals P^T (K_T - K0) P formed as a
// matrix product (PETSc's PtAP): round-off (1e-12). P: the identity, and
// every other node also following the next node's displacement with weight
// 0.5 (rows with two entries, across ranks).
TEST(Concrete3D, TiedTangentChangeEqualsMatrixProduct)
{
  Block b = block(2, material::Mode::plastic, 0.3e6);
  PVec u = loading(*b.fe, 60.0);
  Function uf(b.fe->V());
  damseis::linalg::to_function(u.vec(), uf);
  const auto stats = b.cm->update(uf, 0.01);
  ASSERT_GT(stats.inelastic, 10) << "the load must make points yield";

  PMat K = own(b.fe->assemble_stiffness());
  PetscInt r0 = 0, r1 = 0, N = 0, m = 0;
  MatGetOwnershipRange(K.mat(), &r0, &r1);
  MatGetSize(K.mat(), &N, nullptr);
  MatGetLocalSize(K.mat(), &m, nullptr);
  Mat P;
  MatCreateAIJ(MPI_COMM_WORLD, m, m, N, N, 2, nullptr, 2, nullptr, &P);
  for (PetscInt row = r0; row < r1; ++row)
  {
    MatSetValue(P, row, row, 1.0, INSERT_VALUES);
    const PetscInt node = row / 3, k = row % 3;
    if (node % 2 == 1)
      MatSetValue(P, row, (3 * (node + 1) + k) % N, 0.5, INSERT_VALUES);
  }
  MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY);
  PMat Pm = own(P);

  // The matrix product: the change assembled on all dofs, then P^T W P.
  PMat W = own(b.fe->assemble_stiffness());
  MatZeroEntries(W.mat());
  b.cm->add_tangent_change(W.mat(), 1.0);
  PMat R = own(damseis::fem::reduce_to_tied(W.mat(), P));
  // Cell by cell into a zeroed matrix of P^T K P's pattern.
  PMat A = own(damseis::fem::reduce_to_tied(K.mat(), P));
  MatZeroEntries(A.mat());
  damseis::analysis::TiedConcreteSystem tied(*b.cm, P);
  tied.add_tangent_change(A.mat(), 1.0);
  MatAXPY(A.mat(), -1.0, R.mat(), DIFFERENT_NONZERO_PATTERN);
  double diff = 0.0, ref = 0.0;
  MatNorm(A.mat(), NORM_FROBENIUS, &diff);
  MatNorm(R.mat(), NORM_FROBENIUS, &ref);
  print_metric(fmt(stats.inelastic,
                   " points inelastic; |cell by cell - "
                   "PtAP| / |PtAP| = ",
                   diff / ref));
  EXPECT_GT(ref, 0.0);
  EXPECT_LT(diff, 1e-12 * ref);
}

TEST(Concrete3D, ElasticModeMatchesLinearAnalysis)
{
  damseis::analysis::SeismicSettings s;
  s.modes = 3;
  s.damping_modes = {1, 3};
  s.scheme.dt = 0.005;
  s.steps = 100;
  for (int c : {0, 2})
  {
    s.motion[c].active = true;
    for (int k = 0; k <= s.steps; ++k)
    {
      const double t = k * s.scheme.dt;
      s.motion[c].acceleration.push_back((c == 0 ? 3.0 : 1.0) *
                                             std::sin(2 * M_PI * 6.0 * t) +
                                         1.5 * std::sin(2 * M_PI * 17.0 * t));
    }
  }
  s.output_every = 100000;
  s.crest_point = {1, 0, 4};
  s.base_point = {1, 0, 0};
  s.plots = false;
  s.factorization = damseis::linalg::Factorization::mumps;
  const auto dir = std::filesystem::temp_directory_path() / "damseis_3d";
  auto run = [&](bool nonlinear)
  {
    ElasticModel fe(box_model(MPI_COMM_WORLD, {0, 0, 0}, {2, 1, 4}, {4, 2, 8},
                              [](const Point& x)
                              { return x[2] < 1e-12 ? base_tag : -1; }),
                    2, {{tags::dam, block_concrete}});
    fe.fix({base_tag});
    if (!nonlinear)
      return damseis::analysis::run_linear_seismic(fe, s, {},
                                                   {dir / "linear", ""});
    damseis::analysis::ConcreteSettings c;
    c.kind = damseis::analysis::ConcreteModelKind::elastic;
    c.params.E = block_concrete.E;
    c.params.nu = block_concrete.nu;
    c.params.mode = material::Mode::elastic;
    return damseis::analysis::run_nonlinear_seismic(
        fe, s, {c, {{tags::dam, block_concrete}}, PlaneMode::plane_strain}, {},
        {dir / "nonlinear", ""});
  };
  const auto a = run(false), b = run(true);
  const double ua = a["crest_displacement_max_m"]["value"];
  const double ub = b["crest_displacement_max_m"]["value"];
  print_metric(fmt("3D crest peak linear ", ua, " m, elastic concrete ", ub,
                   " m, relative difference ",
                   std::abs(ua - ub) / std::abs(ua)));
  EXPECT_NEAR(ub, ua, 1e-9 * std::abs(ua));
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(b["frequencies_hz"][i].get<double>(),
                a["frequencies_hz"][i].get<double>(), 1e-10);
  EXPECT_EQ(b["newton"]["iterations_per_step"].get<double>(), 1.0);
}

TEST(Concrete3D, TensionBarDissipatesFractureEnergy)
{
  for (int nx : {10, 20, 40})
    EXPECT_NEAR(tension_bar_energy_ratio(3, nx, 1), 1.0, 0.03) << "nx = " << nx;
}
} // namespace
