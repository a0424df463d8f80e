// Formulation A of the joint contact problem (contact/paper_ncp: the
// paper's eq. 13 in the polar unknowns q = (P_n, P_tau, theta)), against
// independent references:
//  - the pair's generalised Jacobian blocks B = dh/dq and A = dh/d(g, ds)
//    equal central finite differences of h in each branch (open, stick,
//    slip, keyed; points away from the kinks; 1e-7 relative);
//  - the polar map and its Jacobian: p(q(p)) = p and dp/dq = finite
//    differences (1e-8);
//  - h2 equals the paper's own form r_t x + min(0, rho + P_tau - r_t x) +
//    max(0, -rho + P_tau - r_t x) (algorithms.md 2.3; round-off);
//  - whole problems: both formulations solve the same problems (random
//    coupled flexibilities, friction 0.6, and frictionless ones) to the
//    same forces (1e-8 of the largest; the solution is unique for the small
//    coupling used), and the frictionless forces of formulation A solve the
//    LCP the Alart-Curnier test enumerates (through the same comparison).
#include "random_contact_problem.h"
#include <cmath>
#include <damseis/contact/alart_curnier.h>
#include <damseis/contact/ncp.h>
#include <damseis/contact/paper_ncp.h>
#include <gtest/gtest.h>
#include <random>

namespace
{
using namespace damseis::contact;
using Eigen::Vector2d;
using Eigen::Vector3d;

using Point = Eigen::Matrix<double, 6, 1>; // q (3), g, ds (2)

Vector3d h_at(const PairLaw& law, const Point& x, double theta_k)
{
  return paper_residual(law, x.head<3>(), x[3], x.tail<2>(), theta_k).h;
}

TEST(PaperNcp, JacobianMatchesFiniteDifferencesInEveryBranch)
{
  std::mt19937 gen(23);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  PairLaw law;
  law.mu = 0.8;
  law.r_n = 2.0;
  law.r_t = 1.5;
  int tested[4] = {0, 0, 0, 0}; // open, stick, slip, keyed
  for (int trial = 0; trial < 4000; ++trial)
  {
    law.keyed = trial % 4 == 3;
    Point x;
    for (int i = 0; i < 6; ++i)
      x[i] = u(gen);
    x[2] *= 1.5; // theta in (-1.5, 1.5)
    const double theta_k = 0.3;
    const PaperResidual r =
        paper_residual(law, x.head<3>(), x[3], x.tail<2>(), theta_k);
    // Away from the kinks: |sigma_n| and | |P_tau - r_t x| - rho | not
    // small.
    const double sigma_n = x[0] - law.r_n * x[3];
    const double c = std::cos(x[2]), s = std::sin(x[2]);
    const double along = x[4] * c + x[5] * s;
    const double rho = law.mu * std::max(sigma_n, 0.0);
    if (std::abs(sigma_n) < 1e-3 ||
        (!law.keyed && std::abs(std::abs(x[1] - law.r_t * along) - rho) < 1e-3))
      continue;
    Eigen::Matrix<double, 3, 6> fd;
    const double h = 1e-7;
    for (int j = 0; j < 6; ++j)
    {
      Point xp = x, xm = x;
      xp[j] += h;
      xm[j] -= h;
      fd.col(j) = (h_at(law, xp, theta_k) - h_at(law, xm, theta_k)) / (2 * h);
    }
    Eigen::Matrix<double, 3, 6> J;
    J << r.B, r.A;
    EXPECT_LT((J - fd).norm(), 1e-7 * std::max(1.0, J.norm()))
        << "state " << int(r.state) << " keyed " << law.keyed << "\nJ =\n"
        << J << "\nFD =\n"
        << fd;
    ++tested[law.keyed ? 3 : int(r.state)];
  }
  for (int s = 0; s < 4; ++s)
    EXPECT_GT(tested[s], 100) << "branch " << s << " barely sampled";
}

TEST(PaperNcp, PolarMapAndItsJacobian)
{
  std::mt19937 gen(29);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial)
  {
    const Vector3d p(u(gen), u(gen), u(gen));
    const Vector3d q = paper_unknowns(p);
    EXPECT_GT(q[2], -M_PI / 2);
    EXPECT_LE(q[2], M_PI / 2);
    EXPECT_LT((paper_forces(q) - p).norm(), 1e-14);
    Eigen::Matrix3d fd;
    const double h = 1e-7;
    for (int j = 0; j < 3; ++j)
    {
      Vector3d qp = q, qm = q;
      qp[j] += h;
      qm[j] -= h;
      fd.col(j) = (paper_forces(qp) - paper_forces(qm)) / (2 * h);
    }
    EXPECT_LT((paper_forces_jacobian(q) - fd).norm(), 1e-8);
  }
}

TEST(PaperNcp, TangentialResidualIsThePapersForm)
{
  std::mt19937 gen(31);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  PairLaw law;
  law.mu = 0.9;
  law.r_n = 1.3;
  law.r_t = 0.7;
  int compared = 0;
  for (int trial = 0; trial < 1000; ++trial)
  {
    const Vector3d q(u(gen), u(gen), 1.5 * u(gen));
    const double g = u(gen);
    const Vector2d ds(u(gen), u(gen));
    const double rho = law.mu * std::max(q[0] - law.r_n * g, 0.0);
    if (rho == 0.0)
      continue; // the frictionless branch replaces h3; h2 = P_tau there
    const double x = ds[0] * std::cos(q[2]) + ds[1] * std::sin(q[2]);
    const double paper = law.r_t * x + std::min(0.0, rho + q[1] - law.r_t * x) +
                         std::max(0.0, -rho + q[1] - law.r_t * x);
    EXPECT_NEAR(paper_residual(law, q, g, ds, 0.0).h[1], paper, 1e-14);
    ++compared;
  }
  EXPECT_GT(compared, 300);
}

TEST(PaperNcp, SolvesTheProblemsOfTheCartesianForm)
{
  std::mt19937 gen(37);
  NcpSettings paper;
  paper.formulation = Formulation::paper;
  int states[3] = {0, 0, 0};
  for (int trial = 0; trial < 40; ++trial)
  {
    const int n = 6;
    const double mu = trial % 4 == 0 ? 0.0 : 0.6;
    ContactProblem pb = damseis::test::random_problem(n, mu, gen, 2e-4);
    pb.W_inv = pb.W.inverse(); // the reduced Newton direction
    const Eigen::VectorXd p0 = Eigen::VectorXd::Zero(3 * n);
    const NcpReport a = solve_ncp(pb, p0);
    const NcpReport b = solve_ncp(pb, p0, paper);
    ASSERT_TRUE(a.converged) << "trial " << trial;
    ASSERT_TRUE(b.converged) << "trial " << trial << ", residual " << b.residual
                             << " after " << b.iterations;
    const double P = std::max(1.0, a.p.lpNorm<Eigen::Infinity>());
    EXPECT_LT((a.p - b.p).lpNorm<Eigen::Infinity>(), 1e-8 * P)
        << "trial " << trial;
    for (int i = 0; i < n; ++i)
    {
      EXPECT_EQ(int(a.states[i]), int(b.states[i]))
          << "trial " << trial << " pair " << i;
      ++states[int(b.states[i])];
    }
  }
  for (int s = 0; s < 3; ++s)
    EXPECT_GT(states[s], 10) << "state " << s << " barely met";
}
} // namespace
