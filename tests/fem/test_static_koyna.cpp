// Static equilibrium of the Koyna section on a rigid base (ElasticModel,
// DirectSolver): gravity and hydrostatic loads solved separately, base
// reactions compared with closed-form resultants. Run serial and on 2 MPI
// ranks.
//
// Setup: geometry::build_gravity_dam with the default (Koyna) section,
// mesh size 4 m, P2 displacements, plane stress, E = 30 GPa, nu = 0.2,
// rho = 2500 kg/m3, all displacements fixed on tags::dam_base (y = 0).
//
// References (independent of the finite element code):
//  - dead weight: the vertical base reaction is the weight rho g A, with
//    A the polygon area (geometry::section_area, checked by hand in
//    test_gravity_dam_mesh.cpp: 3588.975 m^2); its moment about the heel
//    is rho g A x_c with x_c the polygon centroid (shoelace formula here);
//  - reservoir at h = 91.75 m (rho_w = 1000, g = 9.81): the horizontal
//    reaction balances the hydrostatic resultant rho_w g h^2 / 2, its
//    moment about the heel is rho_w g h^3 / 6 (line of action h/3).
// The reactions are R = f_int(u) - F (assemble_internal_force and the
// *_free loads) summed over the owned fixed dofs. By global equilibrium of
// the discrete system (rigid translations and the rotation are in the P2
// space and have zero strain energy) they equal minus the discrete load
// resultants exactly, and those resultants are exact here: the gravity
// integrand is polynomial, and the pressure is linear on every wetted
// facet because the mesh has a node at the water level. So the tolerance
// is round-off (1e-9 relative allows for the direct-solve residual).
// Observed (serial and 2 ranks): reaction and moment relative errors
// 1e-15 .. 3e-13, residuals 4e-12 (gravity) and 4e-13 (water) relative to
// the largest load entry.
#include "fem_test_support.h"

#include <damseis/fem/elastic_model.h>
#include <damseis/geometry/gravity_dam.h>
#include <damseis/geometry/tags.h>

#include <array>
#include <cmath>
#include <vector>

#include <dolfinx/fem/petsc.h>
#include <gtest/gtest.h>
#include <mpi.h>

namespace
{
using damseis::fem::ElasticModel;
using damseis::fem::Material;
using damseis::fem::PlaneMode;
using damseis::fem::Reservoir;
using damseis::geometry::GravityDamSection;
using namespace damseis::test;
namespace tags = damseis::tags;
using Function = dolfinx::fem::Function<double>;

constexpr double rho = 2500, g = 9.81, rho_w = 1000, h = 91.75;

GravityDamSection koyna()
{
  GravityDamSection s;
  s.mesh_size = 4.0;
  return s;
}

/// Centroid x of the dam polygon (heel, toe, neck, crest corners).
double centroid_x(const GravityDamSection& s)
{
  const double px[5] = {s.heel_x, s.toe_x, s.neck_x, s.crest_down_x, s.heel_x};
  const double py[5] = {s.base_y, s.base_y, s.neck_y, s.crest_y, s.crest_y};
  double a2 = 0, cx = 0;
  for (int i = 0; i < 5; ++i)
  {
    const int j = (i + 1) % 5;
    const double c = px[i] * py[j] - px[j] * py[i];
    a2 += c;
    cx += (px[i] + px[j]) * c;
  }
  return cx / (3 * a2);
}

/// Result of one static solve.
struct Equilibrium
{
  double Rx = 0, Ry = 0; ///< base reaction resultant
  double M = 0;          ///< reaction moment about the heel (counter-clockwise)
  double residual_K = 0; ///< max |K u - F| at free dofs / max |F|
  double residual_int = 0; ///< max |f_int(u) - F_free| at free dofs / max |F|
};

/// Solves K u = F for the load `load` (assembled with and without
/// boundary conditions by the two callables) and computes the reactions.
template <typename Load, typename LoadFree>
Equilibrium solve_and_react(const ElasticModel& em, Load load,
                            LoadFree load_free)
{
  auto V = em.V();
  const std::int32_t n_owned = owned_size(*V);
  const int bs = V->dofmap()->index_map_bs();
  PMat K = own(em.assemble_stiffness());
  PVec F = load(), Ff = load_free();
  Function u(V);
  solve(K.mat(), F.vec(), u);

  const std::vector<std::int32_t> fixed = em.fixed_dofs();
  std::vector<char> is_fixed(n_owned, 0);
  for (std::int32_t i : fixed)
    if (i < n_owned)
      is_fixed[i] = 1;

  // Residual of the linear system with the model's K (fixed rows identity)
  Vec Ku;
  VecDuplicate(F.vec(), &Ku);
  Vec uv = dolfinx::la::petsc::create_vector_wrap(*u.x());
  MatMult(K.mat(), uv, Ku);
  VecDestroy(&uv);
  const auto ku = owned_values(Ku);
  VecDestroy(&Ku);
  const auto f = owned_values(F.vec());
  const auto ff = owned_values(Ff.vec());
  PVec fint = own(em.assemble_internal_force(u));
  const auto fi = owned_values(fint.vec());

  // Dof coordinates (blocks) for the moment
  const std::vector<double> X = V->tabulate_dof_coordinates(false);
  double local[3] = {0, 0, 0}, res[3] = {0, 0, 0};
  for (std::int32_t i = 0; i < n_owned; ++i)
  {
    res[2] = std::max(res[2], std::abs(ff[i]));
    if (is_fixed[i])
    {
      const double r = fi[i] - ff[i];
      const int k = i % bs;
      const double* p = &X[3 * (i / bs)];
      local[k] += r;
      local[2] += k == 0 ? -p[1] * r : p[0] * r;
    }
    else
    {
      res[0] = std::max(res[0], std::abs(ku[i] - f[i]));
      res[1] = std::max(res[1], std::abs(fi[i] - ff[i]));
    }
  }
  Equilibrium e;
  e.Rx = global_sum(local[0]);
  e.Ry = global_sum(local[1]);
  e.M = global_sum(local[2]);
  const double fmax = global_max(res[2]);
  e.residual_K = global_max(res[0]) / fmax;
  e.residual_int = global_max(res[1]) / fmax;
  return e;
}

class StaticKoyna : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    model_ = new Model(
        damseis::geometry::build_gravity_dam(MPI_COMM_WORLD, koyna()));
  }
  static void TearDownTestSuite()
  {
    delete model_;
    model_ = nullptr;
  }
  static ElasticModel make_model()
  {
    ElasticModel em(*model_, 2, {{tags::dam, Material{30e9, 0.2, rho}}},
                    PlaneMode::plane_stress);
    em.fix({tags::dam_base});
    return em;
  }

private:
  static Model* model_;
};
Model* StaticKoyna::model_ = nullptr;
} // namespace

TEST_F(StaticKoyna, GravityReactionIsTheDamWeight)
{
  const ElasticModel em = make_model();
  const std::array<double, 3> gv = {0, -g, 0};
  const Equilibrium e = solve_and_react(
      em, [&] { return own(em.assemble_gravity(gv)); },
      [&] { return own(em.assemble_gravity_free(gv)); });

  const double A = damseis::geometry::section_area(koyna());
  const double W = rho * g * A; // 88.0 MN per metre
  const double M = W * centroid_x(koyna());
  print_metric(fmt("gravity: Ry = ", e.Ry, " N/m, rel. error ", (e.Ry - W) / W,
                   "; Rx/W = ", e.Rx / W, "; moment rel. error ", (e.M - M) / M,
                   "; residuals ", e.residual_K, ", ", e.residual_int));
  EXPECT_NEAR(e.Ry, W, 1e-9 * W);
  EXPECT_NEAR(e.Rx, 0.0, 1e-9 * W);
  EXPECT_NEAR(e.M, M, 1e-9 * M);
  EXPECT_LT(e.residual_K, 1e-9);
  EXPECT_LT(e.residual_int, 1e-9);
}

TEST_F(StaticKoyna, HydrostaticReactionIsTheWaterThrust)
{
  const ElasticModel em = make_model();
  Reservoir r;
  r.level = h;
  r.bottom = 0;
  r.rho_w = rho_w;
  r.g = g;
  const Equilibrium e = solve_and_react(
      em, [&] { return own(em.assemble_hydrostatic(r)); },
      [&] { return own(em.assemble_hydrostatic_free(r)); });

  // The water pushes downstream (+x) on the upstream face x = 0; the base
  // pulls back. Its moment (counter-clockwise about the heel) balances the
  // clockwise overturning moment P h / 3.
  const double P = rho_w * g * h * h / 2; // 41.3 MN per metre
  const double M = rho_w * g * h * h * h / 6;
  print_metric(fmt("hydrostatic: Rx = ", e.Rx, " N/m, rel. error ",
                   (e.Rx + P) / P, "; Ry/P = ", e.Ry / P,
                   "; moment rel. error ", (e.M - M) / M, "; residuals ",
                   e.residual_K, ", ", e.residual_int));
  EXPECT_NEAR(e.Rx, -P, 1e-9 * P);
  EXPECT_NEAR(e.Ry, 0.0, 1e-9 * P);
  EXPECT_NEAR(e.M, M, 1e-9 * M);
  EXPECT_LT(e.residual_K, 1e-9);
  EXPECT_LT(e.residual_int, 1e-9);
}
