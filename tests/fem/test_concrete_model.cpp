// The nonlinear concrete at the quadrature points (fem::ConcreteModel,
// forms/plasticity_2d.py), checked against independent references:
//  - elastic mode: the tangent assembled from the point tangents equals the
//    stiffness of the linear forms (forms/elasticity_2d.py, a different
//    kernel and quadrature), and f_int(u) = K u. Both are exact for P2 with
//    the degree-2 rule, so the tolerance is round-off (1e-11 relative).
//  - plastic and viscoplastic modes: the assembled consistent tangent times
//    a direction equals the central finite difference of the assembled
//    internal force (algorithms.md 1.9 asks 1e-6 for the point tangent; the
//    structural check is limited by the O(h^2) truncation and by points
//    that change active set inside the difference interval, so 1e-4).
//  - the tangent change added cell by cell (add_tangent_change, used by the
//    Newton iteration) equals the fully assembled tangent minus K0: the
//    same kernel on the same values, so round-off (1e-12 relative).
// Koyna section, 8 m mesh, rigid base; plane stress and plane strain.
#include "fem_test_support.h"

#include <damseis/analysis/run_outputs.h>
#include <damseis/fem/concrete_model.h>
#include <damseis/geometry/gravity_dam.h>
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

struct ConcreteCase
{
  std::unique_ptr<ElasticModel> fe;
  std::unique_ptr<ConcreteModel> cm;
};

ConcreteCase make(material::Mode mode, PlaneMode plane, double ft = 2.5e6)
{
  damseis::geometry::GravityDamSection s;
  s.mesh_size = 8.0;
  const Material concrete{30e9, 0.2, 2500};
  ConcreteCase out;
  out.fe = std::make_unique<ElasticModel>(
      damseis::geometry::build_gravity_dam(MPI_COMM_WORLD, s), 2,
      std::map<int, Material>{{tags::dam, concrete}}, plane);
  out.fe->fix({tags::dam_base});
  material::ConcreteParameters p;
  p.E = concrete.E;
  p.nu = concrete.nu;
  p.fc0 = 10 * ft;
  p.ft0 = ft;
  p.Gf = 2000; // large: no strength reduction on 8 m elements
  p.mode = mode;
  out.cm = std::make_unique<ConcreteModel>(
      *out.fe, std::map<int, material::ConcreteParameters>{{tags::dam, p}},
      std::map<int, Material>{{tags::dam, concrete}}, plane);
  return out;
}

/// A smooth displacement field: the static response to a horizontal load
/// of intensity `scale` (rigid base), so that the base region cracks.
PVec loading(ElasticModel& fe, double scale)
{
  PMat K = own(fe.assemble_stiffness());
  PVec F = own(fe.assemble_gravity({scale, -9.81, 0}));
  PVec u = own(fe.assemble_gravity({0, 0, 0}));
  damseis::linalg::DirectSolver solver(MPI_COMM_WORLD);
  solver.factorize(K.mat());
  solver.solve(F.vec(), u.vec());
  return u;
}

TEST(ConcreteModel, ElasticModeReproducesLinearStiffness)
{
  for (PlaneMode plane : {PlaneMode::plane_stress, PlaneMode::plane_strain})
  {
    ConcreteCase s = make(material::Mode::elastic, plane);
    PMat K = own(s.fe->assemble_stiffness());
    PMat Kt = own(s.cm->assemble_tangent());
    MatAXPY(Kt.mat(), -1.0, K.mat(), SAME_NONZERO_PATTERN);
    double dk = 0, k = 0;
    MatNorm(Kt.mat(), NORM_FROBENIUS, &dk);
    MatNorm(K.mat(), NORM_FROBENIUS, &k);
    print_metric(fmt("elastic tangent vs K: ", dk / k));
    EXPECT_LT(dk / k, 1e-11);

    PVec u = loading(*s.fe, 14.0);
    Function uf(s.fe->V());
    damseis::linalg::to_function(u.vec(), uf);
    s.cm->update(uf, 0.01);
    PVec f = own(s.fe->assemble_gravity({0, 0, 0}));
    s.cm->assemble_internal_force(f.vec());
    PVec Ku = own(s.fe->assemble_gravity({0, 0, 0}));
    MatMult(K.mat(), u.vec(), Ku.vec());
    // K has identity rows at the fixed dofs, where u = 0 and f = 0.
    VecAXPY(f.vec(), -1.0, Ku.vec());
    print_metric(fmt("f_int - K u: ", norm2(f.vec()) / norm2(Ku.vec())));
    EXPECT_LT(norm2(f.vec()) / norm2(Ku.vec()), 1e-11);
  }
}

TEST(ConcreteModel, TangentMatchesFiniteDifferenceOfInternalForce)
{
  for (material::Mode mode :
       {material::Mode::plastic, material::Mode::viscoplastic})
  {
    for (PlaneMode plane : {PlaneMode::plane_stress, PlaneMode::plane_strain})
    {
      ConcreteCase s = make(mode, plane, 0.5e6);
      // A single step from the virgin state: viscoplastic points need a
      // smaller one (their local solve from zero is the harder one).
      PVec u = loading(*s.fe, mode == material::Mode::plastic ? 14.0 : 9.0);
      Function uf(s.fe->V());
      damseis::linalg::to_function(u.vec(), uf);
      const double dt = 0.01;
      const auto stats = s.cm->update(uf, dt);
      ASSERT_EQ(stats.failed, 0);
      ASSERT_GT(stats.inelastic, 10) << "the load must make points yield";
      PMat Kt = own(s.cm->assemble_tangent());

      // Direction: a different smooth field of similar size.
      PVec d = loading(*s.fe, -2.0);
      VecScale(d.vec(), 1.0 / norm2(d.vec()) * norm2(u.vec()));
      PVec Kd = own(s.fe->assemble_gravity({0, 0, 0}));
      MatMult(Kt.mat(), d.vec(), Kd.vec());
      double worst = 1e300;
      for (double h : {1e-5, 1e-6, 1e-7})
      {
        PVec fp = own(s.fe->assemble_gravity({0, 0, 0}));
        PVec fm = own(s.fe->assemble_gravity({0, 0, 0}));
        PVec up = own(s.fe->assemble_gravity({0, 0, 0}));
        VecWAXPY(up.vec(), h, d.vec(), u.vec());
        damseis::linalg::to_function(up.vec(), uf);
        ASSERT_EQ(s.cm->update(uf, dt).failed, 0);
        s.cm->assemble_internal_force(fp.vec());
        VecWAXPY(up.vec(), -h, d.vec(), u.vec());
        damseis::linalg::to_function(up.vec(), uf);
        ASSERT_EQ(s.cm->update(uf, dt).failed, 0);
        s.cm->assemble_internal_force(fm.vec());
        VecAXPY(fp.vec(), -1.0, fm.vec());
        VecScale(fp.vec(), 0.5 / h);
        // Fixed rows: identity in Kt, zero in f_int, and d = 0 there.
        VecAXPY(fp.vec(), -1.0, Kd.vec());
        const double err = norm2(fp.vec()) / norm2(Kd.vec());
        print_metric(
            fmt(mode == material::Mode::plastic ? "plastic" : "viscoplastic",
                plane == PlaneMode::plane_stress ? " plane stress"
                                                 : " plane strain",
                ": ", stats.inelastic, " inelastic points, h = ", h,
                ", |K_T d - FD| / |K_T d| = ", err));
        worst = std::min(worst, err);
      }
      EXPECT_LT(worst, 1e-4);
    }
  }
}

TEST(ConcreteModel, TangentChangeMatchesFullAssembly)
{
  for (PlaneMode plane : {PlaneMode::plane_stress, PlaneMode::plane_strain})
  {
    ConcreteCase s = make(material::Mode::viscoplastic, plane, 0.5e6);
    PVec u = loading(*s.fe, 9.0);
    Function uf(s.fe->V());
    damseis::linalg::to_function(u.vec(), uf);
    const auto stats = s.cm->update(uf, 0.01);
    ASSERT_EQ(stats.failed, 0);
    ASSERT_GT(stats.inelastic, 10) << "the load must make points yield";
    ASSERT_LT(stats.inelastic, stats.points) << "some cells must stay elastic";
    PMat K0 = own(s.fe->assemble_stiffness());
    PMat Kt = own(s.cm->assemble_tangent());
    // A = 3 K0 + 2.5 (K_T - K0), by the change alone.
    const double scale = 2.5;
    PMat A = own(s.fe->assemble_stiffness());
    MatScale(A.mat(), 3.0);
    s.cm->add_tangent_change(A.mat(), scale);
    // Reference from the full assembly: 0.5 K0 + 2.5 K_T, but the fixed rows
    // and columns (identity in both K0 and K_T) get nothing from the change.
    PMat B = own(s.fe->assemble_stiffness());
    MatScale(B.mat(), 3.0);
    MatAXPY(B.mat(), scale, Kt.mat(), SAME_NONZERO_PATTERN);
    MatAXPY(B.mat(), -scale, K0.mat(), SAME_NONZERO_PATTERN);
    double change = 0, k = 0;
    PMat D = own(s.fe->assemble_stiffness());
    MatCopy(Kt.mat(), D.mat(), SAME_NONZERO_PATTERN);
    MatAXPY(D.mat(), -1.0, K0.mat(), SAME_NONZERO_PATTERN);
    MatNorm(D.mat(), NORM_FROBENIUS, &change);
    MatAXPY(A.mat(), -1.0, B.mat(), SAME_NONZERO_PATTERN);
    double diff = 0;
    MatNorm(A.mat(), NORM_FROBENIUS, &diff);
    MatNorm(K0.mat(), NORM_FROBENIUS, &k);
    print_metric(
        fmt(plane == PlaneMode::plane_stress ? "plane stress" : "plane strain",
            ": ", stats.inelastic, " of ", stats.points,
            " points inelastic, |K_T - K0| / |K0| = ", change / k,
            ", change vs full assembly: ", diff / k));
    EXPECT_GT(change / k, 1e-3) << "the tangent must differ from K0";
    EXPECT_LT(diff / k, 1e-12);
  }
}
} // namespace
