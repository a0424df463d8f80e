// The viscous boundary (fem/ViscousBoundary's dashpots, rho c_p normal and
// rho c_s tangential: Lysmer & Kuhlemeyer 1969) under a plane P wave at
// oblique incidence, against the closed form of its reflection.
//
// Closed form (derived here as Lysmer & Kuhlemeyer did): in the elastic
// half-plane z > 0 with dashpots on z = 0 (sigma_zz = rho c_p v_z,
// sigma_xz = rho c_s v_x), a P wave u = d_i f(t - p_i.x / c_p), p_i = d_i
// = (sin th, -cos th), reflects as a P wave A_p d_p f(t - p_p.x / c_p),
// p_p = d_p = (sin th, cos th), and an SV wave A_s d_s f(t - p_s.x / c_s),
// p_s = (sin ph, cos ph), d_s = (cos ph, -sin ph), sin ph = c_s / c_p
// sin th. For a plane wave sigma_ij = -(A / c)(lambda delta_ij p.d +
// mu (d_i p_j + d_j p_i)) f' and v = A d f', so the two dashpot conditions
// are two real linear equations for A_p and A_s, the same for every pulse
// shape f: the boundary reflects every frequency alike. (At normal
// incidence A_p = A_s = 0; the energy reflected is A_p^2 + A_s^2 c_s cos
// ph / (c_p cos th): 0.036 at 60 degrees, 0.117 at 70 for nu = 1/4, as in
// Lysmer & Kuhlemeyer's Fig. 2.)
//
// The finite element check: a rectangle [0, 200] x [0, 100] m (P2, 5 m
// squares), the dashpots on its bottom, the closed-form field (incident
// plus both reflections) prescribed on its sides and top. The bottom then
// moves as the closed form says, within the discretisation error, and
// visibly not as a perfectly absorbing boundary (A_p = A_s = 0) would.
#include "fem_test_support.h"
#include "soil_column.h"
#include <damseis/boundary/viscous_spring.h>
#include <damseis/dynamics/newmark.h>
#include <damseis/fem/viscous_boundary.h>
#include <damseis/linalg/duplicate_matrix.h>
#include <numbers>

using namespace damseis;
using namespace damseis::test;

namespace
{
constexpr int bottom = 5, others = 6;

/// One plane wave A d f(t - t0 - p.x / c).
struct PlaneWave
{
  double A;
  std::array<double, 2> p, d;
  double c;
};

/// The incident P wave and its two reflections for the dashpot boundary:
/// Lysmer & Kuhlemeyer's amplitudes (see the file's comment).
std::array<PlaneWave, 3> reflected_field(double theta, double lambda, double mu,
                                         double rho)
{
  const double cp = std::sqrt((lambda + 2 * mu) / rho),
               cs = std::sqrt(mu / rho);
  const double phi = std::asin(cs / cp * std::sin(theta));
  std::array<PlaneWave, 3> w = {PlaneWave{1.0,
                                          {std::sin(theta), -std::cos(theta)},
                                          {std::sin(theta), -std::cos(theta)},
                                          cp},
                                PlaneWave{0.0,
                                          {std::sin(theta), std::cos(theta)},
                                          {std::sin(theta), std::cos(theta)},
                                          cp},
                                PlaneWave{0.0,
                                          {std::sin(phi), std::cos(phi)},
                                          {std::cos(phi), -std::sin(phi)},
                                          cs}};
  // Row 1: sigma_zz - rho c_p v_z, row 2: sigma_xz - rho c_s v_x, per
  // unit A f'.
  double m[3][2];
  for (int i = 0; i < 3; ++i)
  {
    const auto& [A, p, d, c] = w[i];
    const double pd = p[0] * d[0] + p[1] * d[1];
    m[i][0] = -(lambda * pd + 2 * mu * p[1] * d[1]) / c - rho * cp * d[1];
    m[i][1] = -mu * (p[1] * d[0] + p[0] * d[1]) / c - rho * cs * d[0];
  }
  const double det = m[1][0] * m[2][1] - m[2][0] * m[1][1];
  w[1].A = (-m[0][0] * m[2][1] + m[2][0] * m[0][1]) / det;
  w[2].A = (-m[1][0] * m[0][1] + m[0][0] * m[1][1]) / det;
  return w;
}

struct Field
{
  std::array<PlaneWave, 3> waves;
  double T, t0;
  /// Displacement, velocity or acceleration (derivative 0, 1, 2) at x.
  std::array<double, 2> at(const std::array<double, 2>& x, double t,
                           int derivative) const
  {
    std::array<double, 2> u{};
    const double w = std::numbers::pi / T;
    for (const PlaneWave& wave : waves)
    {
      const double tau =
          t - t0 - (wave.p[0] * x[0] + wave.p[1] * x[1]) / wave.c;
      if (tau <= 0 || tau >= T)
        continue;
      const double s = std::sin(w * tau), c = std::cos(w * tau);
      const double f = derivative == 0 ? std::pow(s, 4)
                       : derivative == 1
                           ? 4 * w * s * s * s * c
                           : w * w * (12 * s * s * c * c - 4 * s * s * s * s);
      for (int k = 0; k < 2; ++k)
        u[k] += wave.A * wave.d[k] * f;
    }
    return u;
  }
};

/// The largest difference over the run between the bottom's displacement
/// (nodes with 50 <= x <= 150) and the closed form's, and a perfectly
/// absorbing boundary's field, relative to the incident wave's unit
/// amplitude; the closed form prescribed on the sides and top.
struct ObliqueResult
{
  double error_vs_closed_form, error_vs_absorbing;
};

ObliqueResult run_oblique(double theta_deg)
{
  const double L = 200, H = 100, dt = 5e-4, T = 0.05;
  Model model = rectangle_model(MPI_COMM_WORLD, {0, 0}, {L, H}, {40, 20},
                                [&](const Point& p)
                                { return p[1] < 1e-9 ? bottom : others; });
  const double rho = 2000, mu = 2e9, nu = 0.25;
  const double lambda = 2 * mu * nu / (1 - 2 * nu);
  const double E = mu * 2 * (1 + nu);
  damseis::fem::ElasticModel fe(model, 2, {{tags::dam, {E, nu, rho}}});
  const double theta = theta_deg * std::numbers::pi / 180;
  Field exact{reflected_field(theta, lambda, mu, rho), T, 0.0};
  // Zero in the domain at t = 0: the incident front enters at (0, H).
  exact.t0 = -(exact.waves[0].p[1] * H) / exact.waves[0].c;
  Field absorbing = exact;
  absorbing.waves[1].A = absorbing.waves[2].A = 0.0;

  // The operators without supports (for the lifting of the prescribed
  // nodes' columns by the load), then with the sides and top fixed (the
  // assembly's Dirichlet rows: identity in K, zero in M and C).
  damseis::fem::ElasticModel::Partitioned all =
      fe.assemble_partitioned({}, nullptr);
  PMat K_free = own(all.K), M_free = own(all.M);
  VecDestroy(&all.M_explicit);
  MatDestroy(&all.K_implicit);
  const damseis::fem::ViscousBoundary b_free(fe, *model.facet_tags, {bottom},
                                             {L / 2, 0, 0}, {0.0, 0.0});
  fe.fix({others});
  const damseis::fem::ViscousBoundary b(fe, *model.facet_tags, {bottom},
                                        {L / 2, 0, 0}, {0.0, 0.0});
  PMat K = own(fe.assemble_stiffness()), M = own(fe.assemble_mass(nullptr));
  Mat C_free = b_free.dashpots(), C = b.dashpots();
  const std::int32_t owned = fe.V()->dofmap()->index_map->size_local();
  const std::int64_t first = fe.V()->dofmap()->index_map->local_range()[0];
  const std::vector<double> X = fe.V()->tabulate_dof_coordinates(false);
  std::vector<PetscInt> rows; // owned prescribed nodes, both components
  for (std::int32_t dof : fe.fixed_dofs())
    if (dof / 2 < owned && dof % 2 == 0)
      for (int c = 0; c < 2; ++c)
        rows.push_back(2 * (first + dof / 2) + c);
  std::vector<std::int32_t> watched;
  for (std::int32_t i = 0; i < owned; ++i)
    if (X[3 * i + 1] < 1e-9 && X[3 * i] >= 50 && X[3 * i] <= 150)
      watched.push_back(i);
  dynamics::LinearNewmark newmark(M.mat(), K.mat(), {}, {dt, 0.0},
                                  linalg::Factorization::automatic, {C});
  // f = -(K u_b + M a_b + C v_b) on the free rows, u_b on the prescribed
  // ones (K_eff's rows there are identity: no Rayleigh damping, alpha 0).
  PVec ub = linalg::column_vector(K.mat()), vb = linalg::column_vector(K.mat()),
       ab = linalg::column_vector(K.mat()), f = linalg::column_vector(K.mat()),
       w = linalg::column_vector(K.mat());
  auto load = [&](double t)
  {
    std::array<PVec*, 3> x = {&ub, &vb, &ab};
    for (int d = 0; d < 3; ++d)
    {
      VecSet(x[d]->vec(), 0.0);
      for (std::size_t r = 0; r < rows.size(); r += 2)
      {
        const std::int32_t i = static_cast<std::int32_t>(rows[r] / 2 - first);
        const auto value = exact.at({X[3 * i], X[3 * i + 1]}, t, d);
        VecSetValues(x[d]->vec(), 2, &rows[r], value.data(), INSERT_VALUES);
      }
      VecAssemblyBegin(x[d]->vec());
      VecAssemblyEnd(x[d]->vec());
    }
    MatMult(K_free.mat(), ub.vec(), f.vec());
    MatMultAdd(M_free.mat(), ab.vec(), f.vec(), f.vec());
    MatMultAdd(C_free, vb.vec(), f.vec(), f.vec());
    VecScale(f.vec(), -1.0);
    std::vector<double> u(rows.size());
    VecGetValues(ub.vec(), static_cast<PetscInt>(rows.size()), rows.data(),
                 u.data());
    VecSetValues(f.vec(), static_cast<PetscInt>(rows.size()), rows.data(),
                 u.data(), INSERT_VALUES);
    VecAssemblyBegin(f.vec());
    VecAssemblyEnd(f.vec());
  };
  PVec zero = linalg::column_vector(K.mat());
  load(0.0);
  newmark.set_state(zero.vec(), zero.vec(), zero.vec(), f.vec());
  ObliqueResult r{0.0, 0.0};
  const int steps =
      static_cast<int>(((L + 2 * H) / std::sqrt(mu / rho) + T) / dt);
  for (int k = 1; k <= steps; ++k)
  {
    const double t = k * dt;
    load(t);
    newmark.step(f.vec());
    const double* u = nullptr;
    VecGetArrayRead(newmark.u(), &u);
    for (std::int32_t i : watched)
    {
      const std::array<double, 2> x = {X[3 * i], X[3 * i + 1]};
      const auto e = exact.at(x, t, 0), a = absorbing.at(x, t, 0);
      for (int c = 0; c < 2; ++c)
      {
        r.error_vs_closed_form =
            std::max(r.error_vs_closed_form, std::abs(u[2 * i + c] - e[c]));
        r.error_vs_absorbing =
            std::max(r.error_vs_absorbing, std::abs(u[2 * i + c] - a[c]));
      }
    }
    VecRestoreArrayRead(newmark.u(), &u);
  }
  double out[2] = {r.error_vs_closed_form, r.error_vs_absorbing};
  MPI_Allreduce(MPI_IN_PLACE, out, 2, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return {out[0], out[1]};
}
} // namespace

TEST(ViscousBoundaryOblique, ClosedFormAmplitudes)
{
  // Normal incidence: no reflection; 60 and 70 degrees (nu = 1/4): the
  // energy ratios of Lysmer & Kuhlemeyer's Fig. 2 (0.036, 0.117; computed
  // from the amplitudes here).
  const double mu = 1.0, lambda = 1.0, rho = 1.0; // nu = 1/4
  const auto w0 = reflected_field(0.0, lambda, mu, rho);
  EXPECT_NEAR(w0[1].A, 0.0, 1e-14);
  EXPECT_NEAR(w0[2].A, 0.0, 1e-14);
  for (auto [deg, energy] : {std::pair{60.0, 0.0359}, std::pair{70.0, 0.1172}})
  {
    const double th = deg * std::numbers::pi / 180;
    const auto w = reflected_field(th, lambda, mu, rho);
    const double ph = std::asin(w[2].c / w[0].c * std::sin(th));
    const double ratio = w[1].A * w[1].A + w[2].A * w[2].A * w[2].c *
                                               std::cos(ph) /
                                               (w[0].c * std::cos(th));
    EXPECT_NEAR(ratio, energy, 1e-4) << deg << " degrees";
  }
}

// Measured: the bottom within 3.1e-3 to 3.5e-3 of the closed form (of the
// incident amplitude; P2 at 10 cells per S wavelength of the pulse's 20
// Hz, Newmark at 5e-4 s), and 1.7e-2, 0.23, 0.40 from a perfectly
// absorbing boundary's field at 30, 60, 70 degrees. Asserted: 1e-2, and at
// 60 and 70 degrees the closed form 5 times closer than perfect absorption.
TEST(ViscousBoundaryOblique, BottomMovesAsTheClosedFormReflectionSays)
{
  for (double deg : {30.0, 60.0, 70.0})
  {
    const ObliqueResult r = run_oblique(deg);
    print_metric(fmt("oblique P at ", deg, " degrees: bottom vs closed form ",
                     r.error_vs_closed_form, ", vs perfect absorption ",
                     r.error_vs_absorbing, " (of the incident amplitude)"));
    EXPECT_LT(r.error_vs_closed_form, 1e-2) << deg << " degrees";
    if (deg >= 60.0)
      EXPECT_GT(r.error_vs_absorbing, 5 * r.error_vs_closed_form);
  }
}
