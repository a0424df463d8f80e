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
//    and the load-step quadrature). P1.
// A block 2 x 1 x 4 m fixed at its base z = 0.
#include "fem_test_support.h"

#include <damseis/analysis/linear_seismic.h>
#include <damseis/analysis/nonlinear_seismic.h>
#include <damseis/fem/concrete_model.h>
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

/// Dissipated work of a bar [0, L] x [0, H]^2 pulled at x = L, clamped at
/// x = 0; the middle slab of cubes is 2% weaker so that the crack forms
/// there. Returns W / (Gf H^2).
double bar_energy_ratio(int nx)
{
  const double L = 0.5, H = 0.05, Gf = 300.0, ft = 3e6, E = 30e9;
  const int ny = std::max(1, nx / 10);
  Model m = box_model(MPI_COMM_WORLD, {0, 0, 0}, {L, H, H},
                      {std::size_t(nx), std::size_t(ny), std::size_t(ny)},
                      [&](const Point& x)
                      {
                        if (x[0] < 1e-12)
                          return 5;
                        if (x[0] > L - 1e-12)
                          return 6;
                        return -1;
                      });
  {
    auto& t = *m.cell_tags;
    const auto& x = m.mesh->geometry().x();
    const auto& g = m.mesh->geometry().dofmap();
    std::vector<std::int32_t> idx(t.indices().begin(), t.indices().end());
    std::vector<std::int32_t> val(t.values().begin(), t.values().end());
    const double a = L / nx;
    for (std::size_t i = 0; i < idx.size(); ++i)
    {
      auto v = g.links(idx[i]);
      double xc = 0;
      for (int k = 0; k < 4; ++k)
        xc += x[3 * v[k]] / 4.0;
      if (std::abs(xc - (std::floor(nx / 2) + 0.5) * a) < 0.5 * a)
        val[i] = 3;
    }
    m.cell_tags = std::make_shared<dolfinx::mesh::MeshTags<std::int32_t>>(
        m.mesh, 3, std::move(idx), std::move(val));
  }
  const Material mat{E, 0.0, 2500};
  ElasticModel fe(m, 1, {{tags::dam, mat}, {3, mat}});
  fe.fix({5, 6});
  material::ConcreteParameters p;
  p.E = E;
  p.nu = 0.0;
  p.fc0 = 10 * ft;
  p.ft0 = ft;
  p.Gf = Gf;
  p.mode = material::Mode::plastic;
  material::ConcreteParameters weak = p;
  weak.ft0 = 0.98 * ft;
  ConcreteModel cm(fe, {{tags::dam, p}, {3, weak}},
                   {{tags::dam, mat}, {3, mat}}, PlaneMode::plane_strain);
  EXPECT_EQ(cm.cells_with_reduced_strength(), 0);

  auto V = fe.V();
  const std::vector<double> X = V->tabulate_dof_coordinates(false);
  const std::int32_t nown = V->dofmap()->index_map->size_local();
  std::vector<PetscInt> right;
  for (std::int32_t i = 0; i < nown; ++i)
    if (X[3 * i] > L - 1e-12)
      right.push_back(3 * i);
  PMat J = own(cm.assemble_tangent());
  PVec u = own(fe.assemble_gravity({0, 0, 0}));
  PVec R = own(fe.assemble_gravity({0, 0, 0}));
  PVec du = own(fe.assemble_gravity({0, 0, 0}));
  PVec f_free = own(fe.assemble_gravity({0, 0, 0}));
  Function uf(V);
  auto reaction = [&]()
  {
    cm.assemble_internal_force(f_free.vec(), false);
    const double* a = nullptr;
    VecGetArrayRead(f_free.vec(), &a);
    double s = 0;
    for (PetscInt i : right)
      s += a[i];
    VecRestoreArrayRead(f_free.vec(), &a);
    return global_sum(s);
  };
  const double peak = ft / E * L, w_end = 8.0 * Gf / ft;
  std::vector<double> steps;
  for (double d = 0; d < w_end + peak;)
  {
    d += d < 0.9 * peak ? 0.1 * peak : 0.02 * peak + 0.004 * d;
    steps.push_back(d);
  }
  double work = 0, F_prev = 0, d_prev = 0, d_pp = 0, F_max = 0;
  PVec u_old = own(fe.assemble_gravity({0, 0, 0}));
  PVec step = own(fe.assemble_gravity({0, 0, 0}));
  for (double d : steps)
  {
    VecWAXPY(step.vec(), -1.0, u_old.vec(), u.vec());
    VecCopy(u.vec(), u_old.vec());
    if (d_prev > d_pp)
      VecAXPY(u.vec(), (d - d_prev) / (d_prev - d_pp), step.vec());
    else
    {
      double* a = nullptr;
      VecGetArray(u.vec(), &a);
      for (std::int32_t i = 0; i < nown; ++i)
        a[3 * i] = d * X[3 * i] / L;
      VecRestoreArray(u.vec(), &a);
    }
    {
      double* a = nullptr;
      VecGetArray(u.vec(), &a);
      for (PetscInt i : right)
        a[i] = d;
      VecRestoreArray(u.vec(), &a);
    }
    bool ok = false;
    for (int it = 0; it < 40 && !ok; ++it)
    {
      damseis::linalg::to_function(u.vec(), uf);
      const auto st = cm.update(uf, 0.0);
      EXPECT_EQ(st.failed, 0) << "d / peak = " << d / peak;
      cm.assemble_internal_force(R.vec());
      if (norm2(R.vec()) <= 1e-9 * ft * H * H)
      {
        ok = true;
        break;
      }
      cm.assemble_tangent(J.mat());
      damseis::linalg::DirectSolver lu(MPI_COMM_WORLD,
                                       damseis::linalg::Factorization::mumps);
      lu.factorize_lu(J.mat());
      lu.solve(R.vec(), du.vec());
      VecAXPY(u.vec(), -1.0, du.vec());
    }
    EXPECT_TRUE(ok) << "displacement step " << d;
    cm.accept();
    const double F = reaction();
    F_max = std::max(F_max, F);
    work += 0.5 * (F + F_prev) * (d - d_prev);
    F_prev = F;
    d_pp = d_prev;
    d_prev = d;
  }
  work -= F_prev * F_prev * L / (2 * E * H * H);
  print_metric(fmt("3D bar nx = ", nx,
                   ": peak force / (ft H^2) = ", F_max / (ft * H * H),
                   ", final force / peak = ", F_prev / F_max,
                   ", work / (Gf H^2) = ", work / (Gf * H * H)));
  return work / (Gf * H * H);
}

TEST(Concrete3D, TensionBarDissipatesFractureEnergy)
{
  for (int nx : {10, 20, 40})
    EXPECT_NEAR(bar_energy_ratio(nx), 1.0, 0.03) << "nx = " << nx;
}
} // namespace
