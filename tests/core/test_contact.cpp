// The Coulomb law of a joint pair (contact/alart_curnier), against
// independent references:
//  - the generalised Jacobian blocks B = dF/dp and A = dF/d(g, ds) equal
//    central finite differences of the residual in each branch (open,
//    stick, slip; points away from the kinks; 1e-7 relative);
//  - one pair with an isotropic flexibility W = diag(c_n, c_t, c_t) solved
//    by the damped semismooth Newton method against the closed-form
//    Coulomb solution: a free gap stays open with no force; a penetration
//    delta is closed by P_n = delta / c_n; a small free slip sticks with
//    P_T = -s_free / c_t; a large one slides with |P_T| = mu P_n opposite
//    to the slip, the slip |s_free| - c_t mu P_n along the free slip; a
//    keyed joint never slides; a tangential load turning through 12
//    directions gives a slip opposite to the force each time (algorithms.md
//    2.9, test 2). Tolerance 1e-10 (the iteration's tolerance 1e-12 on the
//    scaled residual);
//  - the condensed problem of many pairs (contact/ncp): uncoupled pairs
//    give the single-pair solutions (1e-10); the assembled Jacobian J = B +
//    A W equals central differences of the residual through W (1e-6);
//    without friction the normal forces equal the solution of the linear
//    complementarity problem found by enumerating every active set
//    (1e-9); with friction and a coupled W every pair meets the Coulomb
//    conditions themselves (no penetration, no tension, complementarity,
//    |P_T| <= mu P_n, no slip below it, slip opposite to P_T at it);
//  - a bonded pair (tension T, cohesion C): the same Jacobian check, and
//    the closed forms of a bond holding below its strength and failing
//    above (opening at P_n = -T; sliding at |P_T| = C + mu P_n);
//  - the impact correction (contact/impact) keeps the normal momentum
//    (round-off), keeps the kinetic energy with e = 1 and leaves the nodes
//    moving together with e = 0 (the inelastic collision of two masses:
//    energy loss m_a m_b v_rel^2 / (2 (m_a + m_b))), and leaves separating
//    nodes alone.
#include "random_contact_problem.h"
#include <cmath>
#include <damseis/contact/alart_curnier.h>
#include <damseis/contact/impact.h>
#include <damseis/contact/ncp.h>
#include <gtest/gtest.h>
#include <random>

namespace
{
using namespace damseis::contact;
using Eigen::Matrix3d;
using Eigen::Vector2d;
using Eigen::Vector3d;

/// The residual as a function of x = (P_n, P_a, P_b, g, ds_a, ds_b).
Vector3d residual(const PairLaw& law, const Eigen::Matrix<double, 6, 1>& x)
{
  return alart_curnier(law, x.head<3>(), x[3], x.tail<2>()).F;
}

/// B and A against central differences of the residual in each branch,
/// at random points away from the kinks.
void check_jacobian(const PairLaw& law, unsigned seed)
{
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int tested[3] = {0, 0, 0};
  for (int trial = 0; trial < 3000; ++trial)
  {
    Eigen::Matrix<double, 6, 1> x;
    for (int i = 0; i < 6; ++i)
      x[i] = u(gen);
    const PairResidual r = alart_curnier(law, x.head<3>(), x[3], x.tail<2>());
    // Away from the kinks: |sigma_n|, the friction limit and | |tau| - rho |
    // not small.
    const double sigma_n = x[0] + law.tension - law.r_n * x[3];
    const Vector2d tau = x.segment<2>(1) - law.r_t * x.tail<2>();
    const double limit = law.cohesion + law.mu * (sigma_n - law.tension);
    const double rho = sigma_n >= 0.0 ? std::max(limit, 0.0) : 0.0;
    if (std::abs(sigma_n) < 1e-3 || std::abs(tau.norm() - rho) < 1e-3 ||
        tau.norm() < 1e-3 || std::abs(limit) < 1e-3)
      continue;
    Eigen::Matrix<double, 3, 6> fd;
    const double h = 1e-7;
    for (int j = 0; j < 6; ++j)
    {
      Eigen::Matrix<double, 6, 1> xp = x, xm = x;
      xp[j] += h;
      xm[j] -= h;
      fd.col(j) = (residual(law, xp) - residual(law, xm)) / (2 * h);
    }
    Eigen::Matrix<double, 3, 6> J;
    J << r.B, r.A;
    EXPECT_LT((J - fd).norm(), 1e-7 * std::max(1.0, J.norm()))
        << "state " << int(r.state) << "\nJ =\n"
        << J << "\nFD =\n"
        << fd;
    ++tested[int(r.state)];
  }
  for (int s = 0; s < 3; ++s)
    EXPECT_GT(tested[s], 100) << "branch " << s << " barely sampled";
}

TEST(Contact, JacobianMatchesFiniteDifferencesInEveryBranch)
{
  PairLaw law;
  law.mu = 0.8;
  law.r_n = 2.0;
  law.r_t = 1.5;
  check_jacobian(law, 7);
  // A bonded pair: tension and cohesion shift the branches.
  law.tension = 0.3;
  law.cohesion = 0.2;
  check_jacobian(law, 11);
}

/// An isotropic pair: W = diag(cn, ct, ct).
Matrix3d flexibility(double cn, double ct)
{
  return Vector3d(cn, ct, ct).asDiagonal();
}

TEST(Contact, PairSolutionsMatchTheClosedForms)
{
  const double cn = 2e-9, ct = 5e-9; // m/N
  PairLaw law;
  law.mu = 1.0;
  law.r_n = 1.0 / cn;
  law.r_t = 1.0 / ct;
  const Matrix3d W = flexibility(cn, ct);
  const Vector2d zero2 = Vector2d::Zero();
  // Free opening: no force.
  {
    const auto s = solve_pair(law, W, Vector3d(1e-4, 2e-4, 0), zero2, 0.0);
    ASSERT_TRUE(s.converged);
    EXPECT_EQ(s.state, PairState::open);
    EXPECT_LT(s.p.norm(), 1e-10 * 1e-4 / cn);
  }
  // Penetration delta, no tangential load: P_n = delta / cn, gap 0.
  const double delta = 1e-3;
  {
    const auto s = solve_pair(law, W, Vector3d(-delta, 0, 0), zero2, 0.0);
    ASSERT_TRUE(s.converged);
    EXPECT_NEAR(s.p[0], delta / cn, 1e-10 * delta / cn);
    EXPECT_NEAR(s.w[0], 0.0, 1e-10 * delta);
  }
  const double Pn = delta / cn;
  // Stick: a free slip needing |P_T| = 0.5 mu P_n.
  {
    const Vector2d s_free = 0.5 * law.mu * Pn * ct * Vector2d(0.6, 0.8);
    const auto s =
        solve_pair(law, W, Vector3d(-delta, s_free[0], s_free[1]), zero2, 0.0);
    ASSERT_TRUE(s.converged);
    EXPECT_EQ(s.state, PairState::stick);
    EXPECT_LT((s.p.tail<2>() + s_free / ct).norm(), 1e-10 * Pn);
    EXPECT_LT(s.w.tail<2>().norm(), 1e-10 * s_free.norm());
  }
  // Slip: a free slip needing 3 mu P_n; |P_T| = mu P_n opposite to the
  // slip, which is |s_free| - ct mu P_n along the free slip.
  {
    const Vector2d e(0.6, 0.8);
    const Vector2d s_free = 3.0 * law.mu * Pn * ct * e;
    const auto s =
        solve_pair(law, W, Vector3d(-delta, s_free[0], s_free[1]), zero2, 0.0);
    ASSERT_TRUE(s.converged);
    EXPECT_EQ(s.state, PairState::slip);
    EXPECT_NEAR(s.p[0], Pn, 1e-10 * Pn);
    EXPECT_LT((s.p.tail<2>() + law.mu * Pn * e).norm(), 1e-10 * Pn);
    const Vector2d slip = s.w.tail<2>();
    EXPECT_LT((slip - (s_free.norm() - ct * law.mu * Pn) * e).norm(),
              1e-10 * s_free.norm());
    // A keyed joint does not slide, whatever the load.
    PairLaw keyed = law;
    keyed.keyed = true;
    const auto k = solve_pair(keyed, W, Vector3d(-delta, s_free[0], s_free[1]),
                              zero2, 0.0);
    ASSERT_TRUE(k.converged);
    EXPECT_LT(k.w.tail<2>().norm(), 1e-10 * s_free.norm());
    EXPECT_LT((k.p.tail<2>() + s_free / ct).norm(), 1e-10 * s_free.norm() / ct);
  }
  // A tangential load turning through 12 directions, from the last state
  // (the slip measured from the last step's tangential displacement): the
  // slip is opposite to the force each time.
  {
    Vector3d p = Vector3d::Zero();
    Vector2d wT_old = Vector2d::Zero();
    for (int k = 0; k < 12; ++k)
    {
      const double a = 2 * M_PI * k / 12;
      const Vector2d load = 2.0 * law.mu * Pn * ct * Vector2d(cos(a), sin(a));
      const Vector2d free = wT_old + load;
      const auto s = solve_pair(law, W, Vector3d(-delta, free[0], free[1]),
                                wT_old, 0.0, p);
      ASSERT_TRUE(s.converged) << "direction " << k;
      const Vector2d slip = s.w.tail<2>() - wT_old;
      const Vector2d PT = s.p.tail<2>();
      EXPECT_EQ(s.state, PairState::slip) << "direction " << k;
      EXPECT_NEAR(PT.norm(), law.mu * s.p[0], 1e-10 * Pn);
      EXPECT_NEAR(slip.normalized().dot(PT.normalized()), -1.0, 1e-10)
          << "direction " << k;
      p = s.p;
      wT_old = s.w.tail<2>();
    }
  }
}

// A bonded pair (tension T, cohesion C) with W = diag(cn, ct, ct), closed
// forms: a free opening d holds closed with P_n = -d / cn while d / cn <
// T, and beyond opens with P_n = -T and gap d - cn T (the bond failed); a
// compressed pair (P_n = delta / cn) sticks under a free slip needing
// 0.9 (C + mu P_n) and slides at |P_T| = C + mu P_n under one needing 1.1
// times that (the bond failed). Tolerance 1e-10 (the iteration's 1e-12).
TEST(Contact, BondedPairHoldsUpToItsStrength)
{
  const double cn = 2e-9, ct = 5e-9; // m/N
  PairLaw law;
  law.mu = 0.75;
  law.r_n = 1.0 / cn;
  law.r_t = 1.0 / ct;
  law.tension = 2e5;  // N
  law.cohesion = 3e5; // N
  const Matrix3d W = flexibility(cn, ct);
  const Vector2d zero2 = Vector2d::Zero();
  for (double f : {0.9, 1.1})
  {
    const double d = f * law.tension * cn;
    const auto s = solve_pair(law, W, Vector3d(d, 0, 0), zero2, 0.0);
    ASSERT_TRUE(s.converged);
    if (f < 1.0)
    {
      EXPECT_EQ(s.state, PairState::stick);
      EXPECT_NEAR(s.p[0], -d / cn, 1e-10 * law.tension);
      EXPECT_NEAR(s.w[0], 0.0, 1e-10 * d);
    }
    else
    {
      EXPECT_EQ(s.state, PairState::open);
      EXPECT_NEAR(s.p[0], -law.tension, 1e-10 * law.tension);
      EXPECT_NEAR(s.w[0], d - cn * law.tension, 1e-10 * d);
    }
    EXPECT_EQ(bond_failed(law, s.state), f > 1.0);
  }
  const double delta = 1e-4, Pn = delta / cn;
  const double strength = law.cohesion + law.mu * Pn;
  const Vector2d e(0.6, 0.8);
  for (double f : {0.9, 1.1})
  {
    const Vector2d s_free = f * strength * ct * e;
    const auto s =
        solve_pair(law, W, Vector3d(-delta, s_free[0], s_free[1]), zero2, 0.0);
    ASSERT_TRUE(s.converged);
    EXPECT_NEAR(s.p[0], Pn, 1e-10 * Pn);
    if (f < 1.0)
    {
      EXPECT_EQ(s.state, PairState::stick);
      EXPECT_LT((s.p.tail<2>() + s_free / ct).norm(), 1e-10 * strength);
    }
    else
    {
      EXPECT_EQ(s.state, PairState::slip);
      EXPECT_LT((s.p.tail<2>() + strength * e).norm(), 1e-10 * strength);
      EXPECT_LT((s.w.tail<2>() - (s_free.norm() - ct * strength) * e).norm(),
                1e-10 * s_free.norm());
    }
    EXPECT_EQ(bond_failed(law, s.state), f > 1.0);
  }
  // Without a bond nothing fails.
  EXPECT_FALSE(bond_failed(PairLaw{}, PairState::open));
}

using damseis::test::random_problem;

TEST(ContactNcp, UncoupledPairsGiveTheSinglePairSolutions)
{
  std::mt19937 gen(11);
  ContactProblem pb = random_problem(6, 0.7, gen);
  // Block-diagonal W: every pair alone.
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      if (i != j)
        pb.W.block<3, 3>(3 * i, 3 * j).setZero();
  const NcpReport r = solve_ncp(pb, Eigen::VectorXd::Zero(18));
  ASSERT_TRUE(r.converged);
  for (int i = 0; i < 6; ++i)
  {
    const auto s =
        solve_pair(pb.laws[i], pb.W.block<3, 3>(3 * i, 3 * i),
                   pb.w_free.segment<3>(3 * i), Vector2d::Zero(), 0.0);
    ASSERT_TRUE(s.converged);
    EXPECT_LT((r.p.segment<3>(3 * i) - s.p).norm(),
              1e-10 * std::max(1.0, s.p.norm()))
        << "pair " << i;
  }
}

TEST(ContactNcp, JacobianMatchesFiniteDifferences)
{
  std::mt19937 gen(5);
  const ContactProblem pb = random_problem(5, 0.8, gen);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int trial = 0; trial < 20; ++trial)
  {
    Eigen::VectorXd p(15);
    for (int i = 0; i < 15; ++i)
      p[i] = 1e6 * u(gen);
    Eigen::VectorXd w;
    std::vector<PairState> st;
    Eigen::MatrixXd J;
    contact_residual(pb, p, w, st, &J);
    const double h = 1e-3; // N, on forces of 1e6 N
    Eigen::MatrixXd fd(15, 15);
    bool kink = false;
    for (int j = 0; j < 15; ++j)
    {
      Eigen::VectorXd pp = p, pm = p;
      pp[j] += h;
      pm[j] -= h;
      std::vector<PairState> sp, sm;
      Eigen::VectorXd wp, wm;
      fd.col(j) = (contact_residual(pb, pp, wp, sp) -
                   contact_residual(pb, pm, wm, sm)) /
                  (2 * h);
      kink = kink || sp != st || sm != st;
    }
    if (kink)
      continue;
    EXPECT_LT((J - fd).norm(), 1e-6 * J.norm());
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

TEST(ContactNcp, FrictionlessNormalForcesSolveTheLcp)
{
  std::mt19937 gen(3);
  for (int trial = 0; trial < 20; ++trial)
  {
    const int n = 4;
    const ContactProblem pb = random_problem(n, 0.0, gen);
    const NcpReport r = solve_ncp(pb, Eigen::VectorXd::Zero(3 * n));
    ASSERT_TRUE(r.converged) << "trial " << trial;
    // Frictionless: P_T = 0, and the normal forces solve the LCP
    // p >= 0, w_n = w_free_n + Wnn p >= 0, p . w_n = 0 (enumerated).
    Eigen::MatrixXd Wnn(n, n);
    Eigen::VectorXd q(n);
    for (int i = 0; i < n; ++i)
    {
      q[i] = pb.w_free[3 * i];
      for (int j = 0; j < n; ++j)
        Wnn(i, j) = pb.W(3 * i, 3 * j);
    }
    int solutions = 0;
    Eigen::VectorXd ref(n);
    for (int set = 0; set < (1 << n); ++set)
    {
      std::vector<int> act;
      for (int i = 0; i < n; ++i)
        if (set & (1 << i))
          act.push_back(i);
      Eigen::VectorXd pn = Eigen::VectorXd::Zero(n);
      if (!act.empty())
      {
        Eigen::MatrixXd A(act.size(), act.size());
        Eigen::VectorXd b(act.size());
        for (std::size_t a = 0; a < act.size(); ++a)
        {
          b[a] = -q[act[a]];
          for (std::size_t c = 0; c < act.size(); ++c)
            A(a, c) = Wnn(act[a], act[c]);
        }
        const Eigen::VectorXd x = A.ldlt().solve(b);
        for (std::size_t a = 0; a < act.size(); ++a)
          pn[act[a]] = x[a];
      }
      const Eigen::VectorXd wn = q + Wnn * pn;
      if ((pn.array() >= -1e-12 * pn.norm()).all() &&
          (wn.array() >= -1e-15).all())
      {
        ++solutions;
        ref = pn;
      }
    }
    ASSERT_EQ(solutions, 1) << "trial " << trial;
    for (int i = 0; i < n; ++i)
    {
      EXPECT_NEAR(r.p[3 * i], ref[i], 1e-9 * std::max(1.0, ref.norm()));
      EXPECT_LT(r.p.segment<2>(3 * i + 1).norm(),
                1e-9 * std::max(1.0, ref.norm()));
    }
  }
}

TEST(ContactNcp, FrictionalSolutionsMeetTheCoulombConditions)
{
  std::mt19937 gen(17);
  int states[3] = {0, 0, 0};
  for (int trial = 0; trial < 30; ++trial)
  {
    const int n = 6;
    const ContactProblem pb = random_problem(n, 0.6, gen);
    const NcpReport r = solve_ncp(pb, Eigen::VectorXd::Zero(3 * n));
    ASSERT_TRUE(r.converged)
        << "trial " << trial << ", iterations " << r.iterations;
    const double P = std::max(1.0, r.p.lpNorm<Eigen::Infinity>());
    const double G = 1e-3; // displacement scale of w_free
    for (int i = 0; i < n; ++i)
    {
      const double Pn = r.p[3 * i], g = r.w[3 * i];
      const Vector2d PT = r.p.segment<2>(3 * i + 1);
      const Vector2d slip = r.w.segment<2>(3 * i + 1); // wT_old = 0
      EXPECT_GE(Pn, -1e-9 * P);
      EXPECT_GE(g, -1e-9 * G);
      EXPECT_LT(std::abs(Pn * g), 1e-9 * P * G);
      EXPECT_LE(PT.norm(), pb.laws[i].mu * Pn + 1e-9 * P);
      if (PT.norm() < pb.laws[i].mu * Pn - 1e-6 * P)
        EXPECT_LT(slip.norm(), 1e-9 * G) << "stick pair " << i;
      else if (slip.norm() > 1e-9 * G && Pn > 1e-9 * P)
        EXPECT_NEAR(slip.normalized().dot(PT.normalized()), -1.0, 1e-8)
            << "slip pair " << i;
      ++states[int(r.states[i])];
    }
  }
  for (int s = 0; s < 3; ++s)
    EXPECT_GT(states[s], 5) << "state " << s << " barely met";
}

TEST(ContactImpact, MomentumKeptEnergyByRestitution)
{
  std::mt19937 gen(23);
  std::uniform_real_distribution<double> m(10.0, 1000.0), v(-2.0, 2.0);
  for (int trial = 0; trial < 100; ++trial)
  {
    const double ma = m(gen), mb = m(gen);
    NormalVelocities in{v(gen), v(gen)};
    if (in.b - in.a >= 0.0)
      std::swap(in.a, in.b); // approaching
    const double momentum = ma * in.a + mb * in.b;
    const double energy = 0.5 * (ma * in.a * in.a + mb * in.b * in.b);
    const double rel = in.b - in.a;
    const auto elastic = impact(ma, mb, in, 1.0);
    EXPECT_NEAR(ma * elastic.a + mb * elastic.b, momentum,
                1e-12 * (ma + mb) * 2.0);
    EXPECT_NEAR(0.5 * (ma * elastic.a * elastic.a + mb * elastic.b * elastic.b),
                energy, 1e-12 * (ma + mb) * 4.0);
    EXPECT_NEAR(elastic.b - elastic.a, -rel, 1e-12);
    const auto plastic = impact(ma, mb, in, 0.0);
    EXPECT_NEAR(ma * plastic.a + mb * plastic.b, momentum,
                1e-12 * (ma + mb) * 2.0);
    EXPECT_NEAR(plastic.b, plastic.a, 1e-12);
    EXPECT_NEAR(energy - 0.5 * (ma * plastic.a * plastic.a +
                                mb * plastic.b * plastic.b),
                ma * mb * rel * rel / (2.0 * (ma + mb)),
                1e-10 * (ma + mb) * 4.0);
    // Separating nodes: unchanged.
    const NormalVelocities out{in.b, in.a};
    const auto same = impact(ma, mb, out, 1.0);
    EXPECT_EQ(same.a, out.a);
    EXPECT_EQ(same.b, out.b);
  }
}
} // namespace

// The Newton direction through z = W d (ContactProblem::W_inv: the rows of
// sticking pairs solved at once, a dense system on the open and sliding
// rows only) is the dense direction: the same iterates, the same solution
// (1e-9: the two linear-algebra routes differ by round-off times the
// condition number of W, about 1e2 here), with keyed pairs too.
TEST(ContactNcp, ReducedNewtonMatchesTheDenseOne)
{
  std::mt19937 gen(23);
  int reduced_smaller = 0;
  for (int trial = 0; trial < 30; ++trial)
  {
    const int n = 8;
    ContactProblem pb = random_problem(n, trial % 3 == 0 ? 0.0 : 0.5, gen);
    if (trial % 4 == 1)
      pb.laws[trial % n].keyed = true;
    const NcpReport dense = solve_ncp(pb, Eigen::VectorXd::Zero(3 * n));
    pb.W_inv = pb.W.inverse();
    const NcpReport red = solve_ncp(pb, Eigen::VectorXd::Zero(3 * n));
    ASSERT_TRUE(dense.converged && red.converged) << "trial " << trial;
    EXPECT_EQ(dense.iterations, red.iterations) << "trial " << trial;
    EXPECT_LT((dense.p - red.p).norm(), 1e-9 * std::max(1.0, dense.p.norm()))
        << "trial " << trial;
    EXPECT_EQ(dense.states, red.states) << "trial " << trial;
    reduced_smaller += red.reduced_rows < 3 * n;
  }
  EXPECT_GT(reduced_smaller, 10);
}
