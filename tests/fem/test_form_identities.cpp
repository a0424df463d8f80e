// Integral identities of the compiled forms (forms/elasticity_{2d,3d}.py)
// through ElasticModel, each against a closed-form value. Run serial and on
// 2 MPI ranks.
//
// The Lagrange basis is a partition of unity and reproduces linear
// functions, so sums of assembled vectors/matrices against the influence
// vectors r_k (rigid translations) and against the dof coordinates are
// integrals of the data:
//   r_k^T M r_l = delta_kl int rho,         sum_i F_gravity,k = g_k int rho,
//   sum_i x_j F_k (i) = int x_j f_k,       u^T K u = int sigma(u) : eps(u).
// All integrands below are polynomial on every cell/facet (straight-sided
// polygons, pressure linear on each facet), so the quadrature is exact and
// the tolerances are round-off (1e-12 relative, or 1e-10 where many
// entries of mixed sign are summed).
//
// References: the Koyna polygon area (3588.975 m^2, by hand in
// test_gravity_dam_mesh.cpp) and centroid (shoelace formula here); the
// foundation block 300 x 100 m; hydrostatic resultant rho_w g h^2/2 with
// line of action h/3 above the base (moment rho_w g h^3/6); the reservoir
// floor, 115 m long, under the uniform pressure rho_w g h; Hooke's law for
// the strain energy density of a uniform strain written out by hand.
#include "fem_test_support.h"

#include <damseis/fem/elastic_model.h>
#include <damseis/geometry/gravity_dam.h>
#include <damseis/geometry/tags.h>

#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <mpi.h>
#include <petscmat.h>

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
using Matrix3 = std::array<std::array<double, 3>, 3>;

constexpr double g = 9.81, rho_w = 1000;

GravityDamSection koyna_section(double mesh_size, bool foundation)
{
  GravityDamSection s;
  s.mesh_size = mesh_size;
  if (foundation)
  {
    s.foundation = true;
    s.foundation_width = 300; // x in [-115, 185]
    s.foundation_depth = 100;
  }
  return s;
}

Reservoir reservoir(double level, bool floor = false)
{
  Reservoir r;
  r.level = level;
  r.bottom = 0;
  r.rho_w = rho_w;
  r.g = g;
  r.load_floor = floor;
  return r;
}

/// Sums over the owned dofs of a load vector: force[k] = sum_i F_k(i) and
/// moment[j][k] = sum_i x_j(i) F_k(i) (global).
struct Resultant
{
  std::array<double, 3> force{};
  Matrix3 moment{};
};

Resultant resultant(const ElasticModel& em, Vec F)
{
  const auto& V = *em.V();
  const int bs = V.dofmap()->index_map_bs();
  const std::vector<double> X = V.tabulate_dof_coordinates(false);
  const std::vector<double> f = owned_values(F);
  Resultant r;
  for (std::size_t i = 0; i < f.size(); ++i)
  {
    const std::size_t node = i / bs;
    const int k = i % bs;
    r.force[k] += f[i];
    for (int j = 0; j < 3; ++j)
      r.moment[j][k] += X[3 * node + j] * f[i];
  }
  for (int k = 0; k < 3; ++k)
  {
    r.force[k] = global_sum(r.force[k]);
    for (int j = 0; j < 3; ++j)
      r.moment[j][k] = global_sum(r.moment[j][k]);
  }
  return r;
}

/// The centroid x of the dam polygon (shoelace).
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

/// Strain energy density sigma : eps of the uniform strain e (symmetric,
/// dim x dim), by Hooke's law written out per mode.
double energy_density(const Matrix3& e, int dim, const Material& m,
                      PlaneMode mode)
{
  const double G = m.E / (2 * (1 + m.nu));
  if (dim == 2 and mode == PlaneMode::plane_stress)
  {
    return m.E / (1 - m.nu * m.nu) *
               (e[0][0] * e[0][0] + 2 * m.nu * e[0][0] * e[1][1] +
                e[1][1] * e[1][1]) +
           4 * G * e[0][1] * e[0][1];
  }
  const double lam = m.E * m.nu / ((1 + m.nu) * (1 - 2 * m.nu));
  double ee = 0, tr = 0;
  for (int i = 0; i < dim; ++i)
  {
    tr += e[i][i];
    for (int j = 0; j < dim; ++j)
      ee += e[i][j] * e[i][j];
  }
  return 2 * G * ee + lam * tr * tr;
}

/// u^T K u for the field u = e x (K without boundary conditions).
double strain_energy(const ElasticModel& em, const Matrix3& e)
{
  const int dim = em.dim();
  Function u(em.V());
  set_nodal(u,
            [&](const Point& p)
            {
              std::array<double, 3> v{};
              for (int i = 0; i < dim; ++i)
                for (int j = 0; j < dim; ++j)
                  v[i] += e[i][j] * p[j];
              return v;
            });
  PMat K = own(em.assemble_stiffness());
  Vec uv = dolfinx::la::petsc::create_vector_wrap(*u.x());
  const double w = quad(K.mat(), uv, uv);
  VecDestroy(&uv);
  return w;
}

/// max |f_int(u) - K u| / max |K u| for a smooth non-polynomial u (K
/// without boundary conditions): L_internal must be the action of
/// a_stiffness.
double internal_force_mismatch(const ElasticModel& em, double scale)
{
  Function u(em.V());
  set_nodal(u,
            [&](const Point& p)
            {
              const double x = p[0] / scale, y = p[1] / scale, z = p[2] / scale;
              return std::array<double, 3>{1e-3 * std::sin(2 * x + y - z),
                                           1e-3 * std::cos(x - 3 * y),
                                           1e-3 * std::sin(x * y + 2 * z)};
            });
  PMat K = own(em.assemble_stiffness());
  PVec f = own(em.assemble_internal_force(u));
  Vec uv = dolfinx::la::petsc::create_vector_wrap(*u.x());
  Vec Ku;
  VecDuplicate(f.vec(), &Ku);
  MatMult(K.mat(), uv, Ku);
  VecDestroy(&uv);
  const auto a = owned_values(Ku), b = owned_values(f.vec());
  VecDestroy(&Ku);
  double d = 0, ref = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    d = std::max(d, std::abs(a[i] - b[i]));
    ref = std::max(ref, std::abs(a[i]));
  }
  return global_max(d) / global_max(ref);
}

/// ||A - A^T||_max / ||A||_max.
double asymmetry(Mat A)
{
  Mat At;
  MatTranspose(A, MAT_INITIAL_MATRIX, &At);
  double n = 0;
  MatNorm(A, NORM_MAX, &n);
  MatAXPY(At, -1.0, A, DIFFERENT_NONZERO_PATTERN);
  double d = 0;
  MatNorm(At, NORM_MAX, &d);
  MatDestroy(&At);
  return d / n;
}

/// Koyna section (mesh 4 m) and Koyna on a foundation (mesh 8 m), built
/// once.
class FormIdentities : public ::testing::TestWithParam<int>
{
protected:
  static void SetUpTestSuite()
  {
    koyna_ = new Model(damseis::geometry::build_gravity_dam(
        MPI_COMM_WORLD, koyna_section(4, false)));
    foundation_ = new Model(damseis::geometry::build_gravity_dam(
        MPI_COMM_WORLD, koyna_section(8, true)));
  }
  static void TearDownTestSuite()
  {
    delete koyna_;
    delete foundation_;
    koyna_ = foundation_ = nullptr;
  }
  static Model* koyna_;
  static Model* foundation_;
};
Model* FormIdentities::koyna_ = nullptr;
Model* FormIdentities::foundation_ = nullptr;

constexpr double rtol = 1e-12;
} // namespace

TEST_P(FormIdentities, KoynaMassAndDeadWeight)
{
  const int degree = GetParam();
  const GravityDamSection s = koyna_section(4, false);
  const double A = damseis::geometry::section_area(s);
  const double rho = 2500;
  ElasticModel em(*koyna_, degree, {{tags::dam, Material{30e9, 0.2, rho}}});
  EXPECT_NEAR(em.region_measure(tags::dam), A, rtol * A);

  // Rigid-body mass: rho A in each direction, no coupling
  PMat M = own(em.assemble_mass(nullptr));
  PVec rx = own(em.influence(0)), ry = own(em.influence(1));
  const double m = rho * A;
  EXPECT_NEAR(quad(M.mat(), rx.vec(), rx.vec()), m, rtol * m);
  EXPECT_NEAR(quad(M.mat(), ry.vec(), ry.vec()), m, rtol * m);
  EXPECT_NEAR(quad(M.mat(), rx.vec(), ry.vec()), 0.0, rtol * m);

  // Dead weight for a body acceleration with both components (checks
  // their order): force g_k rho A, first moment sum x F_y = g_y rho A x_c
  const std::array<double, 3> gv = {1.5, -g, 0};
  PVec F = own(em.assemble_gravity_free(gv));
  const Resultant r = resultant(em, F.vec());
  EXPECT_NEAR(r.force[0], 1.5 * m, rtol * m);
  EXPECT_NEAR(r.force[1], -g * m, rtol * g * m);
  const double mx = -g * m * centroid_x(s);
  EXPECT_NEAR(r.moment[0][1], mx, rtol * std::abs(mx));

  // With the base fixed: the same load at free dofs, zero at fixed dofs;
  // the influence vector is zero at fixed dofs and 1 at free x dofs.
  em.fix({tags::dam_base});
  PVec Fb = own(em.assemble_gravity(gv));
  PVec rxb = own(em.influence(0));
  const auto f = owned_values(F.vec()), fb = owned_values(Fb.vec()),
             ib = owned_values(rxb.vec());
  std::vector<char> fixed(f.size(), 0);
  for (std::int32_t i : em.fixed_dofs())
    if (i < std::int32_t(f.size()))
      fixed[i] = 1;
  double bad = 0, nfixed = 0;
  for (std::size_t i = 0; i < f.size(); ++i)
  {
    nfixed += fixed[i];
    bad += fixed[i] ? (fb[i] != 0.0) + (ib[i] != 0.0)
                    : (fb[i] != f[i]) + (ib[i] != (i % 2 == 0 ? 1.0 : 0.0));
  }
  EXPECT_EQ(global_sum(bad), 0.0);
  EXPECT_GT(global_sum(nfixed), 0.0);
}

TEST_P(FormIdentities, KoynaHydrostaticResultantAndLineOfAction)
{
  const int degree = GetParam();
  ElasticModel em(*koyna_, degree, {{tags::dam, Material{30e9, 0.2, 2500}}});
  // h = 91.75 (a mesh node at the water level) and h = 120 above the
  // crest (the whole face is wetted, depth 17 m at the crest).
  for (double h : {91.75, 120.0})
  {
    PVec F = own(em.assemble_hydrostatic_free(reservoir(h)));
    const Resultant r = resultant(em, F.vec());
    const double top = std::max(h - 103.0, 0.0);
    const double P = rho_w * g * (h * h - top * top) / 2;
    // moment sum y F_x = int_0^min(h,103) rho_w g (h - y) y dy
    const double c = std::min(h, 103.0);
    const double My = rho_w * g * (h * c * c / 2 - c * c * c / 3);
    EXPECT_NEAR(r.force[0], P, rtol * P) << "h = " << h;
    EXPECT_NEAR(r.force[1], 0.0, rtol * P) << "h = " << h;
    EXPECT_NEAR(r.moment[1][0], My, rtol * My) << "h = " << h;
  }
}

TEST_P(FormIdentities, InternalForceIsStiffnessActionAndMatricesSymmetric)
{
  const int degree = GetParam();
  for (PlaneMode mode : {PlaneMode::plane_strain, PlaneMode::plane_stress})
  {
    ElasticModel em(*koyna_, degree, {{tags::dam, Material{30e9, 0.2, 2500}}},
                    mode);
    EXPECT_LT(internal_force_mismatch(em, 30.0), 1e-12);
    PMat K = own(em.assemble_stiffness());
    PMat M = own(em.assemble_mass(nullptr));
    EXPECT_LT(asymmetry(K.mat()), 1e-14);
    EXPECT_LT(asymmetry(M.mat()), 1e-14);
    const Reservoir res = reservoir(91.75);
    PMat Mw = own(em.assemble_mass(&res));
    EXPECT_LT(asymmetry(Mw.mat()), 1e-14);
  }
}

TEST_P(FormIdentities, RegionMaterialsOnTheFoundationModel)
{
  const int degree = GetParam();
  const double A_dam = damseis::geometry::section_area(koyna_section(8, true));
  const double A_fnd = 300.0 * 100.0;
  const Material dam{30e9, 0.2, 2500}, rock{12e9, 0.33, 2700};

  for (PlaneMode mode : {PlaneMode::plane_strain, PlaneMode::plane_stress})
  {
    ElasticModel em(*foundation_, degree,
                    {{tags::dam, dam}, {tags::foundation, rock}}, mode);
    EXPECT_NEAR(em.region_measure(tags::foundation), A_fnd, rtol * A_fnd);

    // Mass and weight of both regions
    const double m = dam.rho * A_dam + rock.rho * A_fnd;
    PMat M = own(em.assemble_mass(nullptr));
    PVec rx = own(em.influence(0));
    EXPECT_NEAR(quad(M.mat(), rx.vec(), rx.vec()), m, rtol * m);
    PVec F = own(em.assemble_gravity_free({0, -g, 0}));
    EXPECT_NEAR(resultant(em, F.vec()).force[1], -g * m, rtol * g * m);

    // Strain energy of a uniform strain: sum over regions of area x
    // energy density (K assembled with the per-region Lame constants)
    const Matrix3 e = {{{1e-4, -0.6e-4, 0}, {-0.6e-4, -2e-4, 0}, {0, 0, 0}}};
    const double w = A_dam * energy_density(e, 2, dam, mode) +
                     A_fnd * energy_density(e, 2, rock, mode);
    const double wh = strain_energy(em, e);
    EXPECT_NEAR(wh, w, 1e-10 * w)
        << (mode == PlaneMode::plane_stress ? "plane stress" : "plane strain");
  }

  // A massless foundation (rho = 0) carries neither mass nor weight
  {
    const Material massless{12e9, 0.33, 0.0};
    ElasticModel em(*foundation_, degree,
                    {{tags::dam, dam}, {tags::foundation, massless}});
    const double m = dam.rho * A_dam;
    PMat M = own(em.assemble_mass(nullptr));
    PVec ry = own(em.influence(1));
    EXPECT_NEAR(quad(M.mat(), ry.vec(), ry.vec()), m, rtol * m);
    PVec F = own(em.assemble_gravity_free({0, -g, 0}));
    EXPECT_NEAR(resultant(em, F.vec()).force[1], -g * m, rtol * g * m);
  }

  // Reservoir floor: with load_floor the 115 m floor upstream of the heel
  // carries the uniform pressure rho_w g h downward; without, nothing. The
  // face thrust is the same in both cases.
  {
    ElasticModel em(*foundation_, degree,
                    {{tags::dam, dam}, {tags::foundation, rock}});
    const double h = 91.75;
    const double P = rho_w * g * h * h / 2, Pf = rho_w * g * h * 115.0;
    PVec F1 = own(em.assemble_hydrostatic_free(reservoir(h, true)));
    PVec F0 = own(em.assemble_hydrostatic_free(reservoir(h, false)));
    const Resultant r1 = resultant(em, F1.vec()), r0 = resultant(em, F0.vec());
    EXPECT_NEAR(r1.force[0], P, rtol * P);
    EXPECT_NEAR(r1.force[1], -Pf, rtol * Pf);
    EXPECT_NEAR(r0.force[0], P, rtol * P);
    EXPECT_NEAR(r0.force[1], 0.0, rtol * Pf);
    // Floor load centred at x = -57.5
    EXPECT_NEAR(r1.moment[0][1], 57.5 * Pf, rtol * 57.5 * Pf);
  }
}

TEST_P(FormIdentities, Box3d)
{
  // Box [0, 20] x [0, 10] x [0, 30] (z vertical), upstream face x = 0,
  // water at z = 24 (a node plane): mass, weight, hydrostatic thrust and
  // its line of action, strain energy, internal force, symmetry.
  const int degree = GetParam();
  const double Lx = 20, Ly = 10, Lz = 30, h = 24, V = Lx * Ly * Lz;
  const Model model = box_model(
      MPI_COMM_WORLD, {0, 0, 0}, {Lx, Ly, Lz}, {2, 2, 5},
      [](const Point& p)
      { return p[0] < 1e-9 ? int(tags::upstream_face) : int(tags::dam_base); });
  const Material mat{30e9, 0.2, 2500};
  ElasticModel em(model, degree, {{tags::dam, mat}});
  EXPECT_NEAR(em.region_measure(tags::dam), V, rtol * V);

  const double m = mat.rho * V;
  PMat M = own(em.assemble_mass(nullptr));
  PVec rz = own(em.influence(2)), rx = own(em.influence(0));
  EXPECT_NEAR(quad(M.mat(), rz.vec(), rz.vec()), m, rtol * m);
  EXPECT_NEAR(quad(M.mat(), rx.vec(), rz.vec()), 0.0, rtol * m);

  PVec Fg = own(em.assemble_gravity_free({0.5, 1.0, -g}));
  const Resultant rg = resultant(em, Fg.vec());
  EXPECT_NEAR(rg.force[0], 0.5 * m, rtol * m);
  EXPECT_NEAR(rg.force[1], 1.0 * m, rtol * m);
  EXPECT_NEAR(rg.force[2], -g * m, rtol * g * m);
  EXPECT_NEAR(rg.moment[0][2], -g * m * Lx / 2, rtol * g * m * Lx);

  PVec Fh = own(em.assemble_hydrostatic_free(reservoir(h)));
  const Resultant rh = resultant(em, Fh.vec());
  const double P = rho_w * g * h * h / 2 * Ly;
  EXPECT_NEAR(rh.force[0], P, rtol * P);
  EXPECT_NEAR(rh.force[1], 0.0, rtol * P);
  EXPECT_NEAR(rh.force[2], 0.0, rtol * P);
  EXPECT_NEAR(rh.moment[2][0], P * h / 3, rtol * P * h);

  const Matrix3 e = {{{1e-4, 0.3e-4, -0.5e-4},
                      {0.3e-4, -2e-4, 0.7e-4},
                      {-0.5e-4, 0.7e-4, 0.6e-4}}};
  const double w = V * energy_density(e, 3, mat, PlaneMode::plane_strain);
  EXPECT_NEAR(strain_energy(em, e), w, 1e-10 * w);

  EXPECT_LT(internal_force_mismatch(em, 10.0), 1e-12);
  PMat K = own(em.assemble_stiffness());
  EXPECT_LT(asymmetry(K.mat()), 1e-14);
  EXPECT_LT(asymmetry(M.mat()), 1e-14);
}

INSTANTIATE_TEST_SUITE_P(Degree, FormIdentities, ::testing::Values(1, 2),
                         [](const ::testing::TestParamInfo<int>& info)
                         { return "P" + std::to_string(info.param); });
