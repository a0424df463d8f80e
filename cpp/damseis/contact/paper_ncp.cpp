#include "paper_ncp.h"
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace damseis::contact
{
PaperResidual paper_residual(const PairLaw& law, const Eigen::Vector3d& q,
                             double g, const Eigen::Vector2d& ds,
                             double theta_k)
{
  PaperResidual r;
  r.B.setZero();
  r.A.setZero();
  const double P_n = q[0], P_t = q[1], theta = q[2];
  const double c = std::cos(theta), s = std::sin(theta);
  // h1 = min(P_n, r_n g): the gap closed where r_n g <= P_n (ties: closed).
  const double sigma_n = P_n - law.r_n * g;
  const bool closed = sigma_n >= 0.0;
  if (closed)
  {
    r.h[0] = law.r_n * g;
    r.A(0, 0) = law.r_n;
  }
  else
  {
    r.h[0] = P_n;
    r.B(0, 0) = 1.0;
  }
  const double x = ds[0] * c + ds[1] * s; // along the force line
  const double y = ds[0] * s - ds[1] * c; // across it
  // h3 = r_t y (dy/dtheta = x, dy/dds = (s, -c)).
  auto slip_on_the_line = [&]()
  {
    r.h[2] = law.r_t * y;
    r.A(2, 1) = law.r_t * s;
    r.A(2, 2) = -law.r_t * c;
    r.B(2, 2) = law.r_t * x;
  };
  // h2 = r_t x (dx/dtheta = -y, dx/dds = (c, s)).
  auto no_slip_along = [&]()
  {
    r.h[1] = law.r_t * x;
    r.A(1, 1) = law.r_t * c;
    r.A(1, 2) = law.r_t * s;
    r.B(1, 2) = -law.r_t * y;
  };
  if (law.keyed)
  {
    no_slip_along();
    slip_on_the_line();
    r.state = closed ? PairState::stick : PairState::open;
    return r;
  }
  const double rho = law.mu * std::max(sigma_n, 0.0);
  if (!closed || rho == 0.0)
  {
    // No friction: P_tau = 0, the direction void (theta frozen).
    r.h[1] = P_t;
    r.B(1, 1) = 1.0;
    r.h[2] = law.r_t * (theta - theta_k);
    r.B(2, 2) = law.r_t;
    r.state = closed ? PairState::slip : PairState::open;
    return r;
  }
  const double t = P_t - law.r_t * x;
  if (std::abs(t) <= rho)
  {
    no_slip_along();
    r.state = PairState::stick;
  }
  else
  {
    // h2 = P_tau - sign(t) rho, rho = mu (P_n - r_n g).
    const double sign = t > 0.0 ? 1.0 : -1.0;
    r.h[1] = P_t - sign * rho;
    r.B(1, 1) = 1.0;
    r.B(1, 0) = -sign * law.mu;
    r.A(1, 0) = sign * law.mu * law.r_n;
    r.state = PairState::slip;
  }
  slip_on_the_line();
  return r;
}

Eigen::Vector3d paper_forces(const Eigen::Vector3d& q)
{
  return {q[0], q[1] * std::cos(q[2]), q[1] * std::sin(q[2])};
}

Eigen::Matrix3d paper_forces_jacobian(const Eigen::Vector3d& q)
{
  const double c = std::cos(q[2]), s = std::sin(q[2]);
  Eigen::Matrix3d D = Eigen::Matrix3d::Zero();
  D(0, 0) = 1.0;
  D(1, 1) = c;
  D(1, 2) = -q[1] * s;
  D(2, 1) = s;
  D(2, 2) = q[1] * c;
  return D;
}

namespace
{
/// theta into (-pi/2, pi/2], P_tau's sign following.
void wrap(Eigen::Ref<Eigen::Vector3d> q)
{
  constexpr double pi = std::numbers::pi;
  q[2] = std::remainder(q[2], 2.0 * pi); // (-pi, pi]
  if (q[2] > pi / 2)
  {
    q[2] -= pi;
    q[1] = -q[1];
  }
  else if (q[2] <= -pi / 2)
  {
    q[2] += pi;
    q[1] = -q[1];
  }
}
} // namespace

Eigen::Vector3d paper_unknowns(const Eigen::Vector3d& p)
{
  Eigen::Vector3d q(p[0], std::hypot(p[1], p[2]), std::atan2(p[2], p[1]));
  wrap(q);
  return q;
}

namespace
{
struct State
{
  Eigen::VectorXd q, p, w, h;
  std::vector<PaperResidual> blocks;
  std::vector<PairState> states;
};

/// p, w and h at q (theta_k: the angles frozen where the direction is
/// void).
State evaluate(const ContactProblem& c, const Eigen::VectorXd& q,
               const Eigen::VectorXd& theta_k)
{
  const Eigen::Index n = static_cast<Eigen::Index>(c.laws.size());
  State st;
  st.q = q;
  st.p.resize(3 * n);
  for (Eigen::Index i = 0; i < n; ++i)
    st.p.segment<3>(3 * i) = paper_forces(q.segment<3>(3 * i));
  st.w = c.w_free + c.W * st.p;
  st.h.resize(3 * n);
  st.blocks.resize(n);
  st.states.resize(n);
  for (Eigen::Index i = 0; i < n; ++i)
  {
    const Eigen::Vector3d wi = st.w.segment<3>(3 * i);
    st.blocks[i] =
        paper_residual(c.laws[i], q.segment<3>(3 * i), c.g0[i] + wi[0],
                       wi.tail<2>() - c.wT_old.segment<2>(2 * i), theta_k[i]);
    st.h.segment<3>(3 * i) = st.blocks[i].h;
    st.states[i] = st.blocks[i].state;
  }
  return st;
}

/// J = B + A W D (dense).
Eigen::MatrixXd jacobian(const ContactProblem& c, const State& st)
{
  const Eigen::Index n = static_cast<Eigen::Index>(c.laws.size());
  Eigen::MatrixXd WD(3 * n, 3 * n);
  for (Eigen::Index j = 0; j < n; ++j)
    WD.middleCols<3>(3 * j) = c.W.middleCols<3>(3 * j) *
                              paper_forces_jacobian(st.q.segment<3>(3 * j));
  Eigen::MatrixXd J(3 * n, 3 * n);
  for (Eigen::Index i = 0; i < n; ++i)
  {
    J.middleRows<3>(3 * i) = st.blocks[i].A * WD.middleRows<3>(3 * i);
    J.block<3, 3>(3 * i, 3 * i) += st.blocks[i].B;
  }
  return J;
}

NcpReport newton(const ContactProblem& c, const Eigen::VectorXd& p0,
                 const NcpSettings& s)
{
  const Eigen::Index n = static_cast<Eigen::Index>(c.laws.size());
  NcpReport rep;
  const double scale = force_scale(c, p0);
  Eigen::VectorXd q(3 * n), theta_k(n);
  for (Eigen::Index i = 0; i < n; ++i)
  {
    q.segment<3>(3 * i) = paper_unknowns(p0.segment<3>(3 * i));
    theta_k[i] = q[3 * i + 2];
  }
  State st = evaluate(c, q, theta_k);
  double psi = 0.5 * st.h.squaredNorm();
  for (rep.iterations = 0; rep.iterations < s.max_iterations; ++rep.iterations)
  {
    rep.residual = st.h.norm() / scale;
    if (rep.residual <= s.tol)
    {
      rep.converged = true;
      break;
    }
    const Eigen::MatrixXd J = jacobian(c, st);
    Eigen::VectorXd d = J.partialPivLu().solve(-st.h);
    if (!d.allFinite() || (J * d + st.h).norm() > 1e-6 * st.h.norm())
    {
      // Singular (the polar map at P_tau = 0): Levenberg-Marquardt.
      const double lm = 1e-8 * std::max(J.norm(), 1e-300);
      d = (J.transpose() * J +
           lm * lm * Eigen::MatrixXd::Identity(3 * n, 3 * n))
              .ldlt()
              .solve(-J.transpose() * st.h);
    }
    auto search = [&](const Eigen::VectorXd& dir) -> bool
    {
      for (double alpha = 1.0; alpha > 1e-6; alpha *= 0.5)
      {
        State trial = evaluate(c, st.q + alpha * dir, theta_k);
        if (0.5 * trial.h.squaredNorm() <= (1.0 - 2e-4 * alpha) * psi)
        {
          st = std::move(trial);
          return true;
        }
        ++rep.line_search_steps;
      }
      return false;
    };
    if (!search(d))
    {
      ++rep.gradient_steps;
      if (!search(-J.transpose() * st.h))
        break;
    }
    for (Eigen::Index i = 0; i < n; ++i)
    {
      wrap(st.q.segment<3>(3 * i));
      theta_k[i] = st.q[3 * i + 2];
    }
    st = evaluate(c, st.q, theta_k);
    psi = 0.5 * st.h.squaredNorm();
  }
  rep.residual = st.h.norm() / scale;
  rep.p = st.p;
  rep.w = st.w;
  rep.states = st.states;
  return rep;
}
} // namespace

NcpReport solve_ncp_paper(const ContactProblem& c, const Eigen::VectorXd& p0,
                          const NcpSettings& s)
{
  // The starts of solve_ncp: the warm start and the stuck forces, the one
  // of smaller residual (measured in formulation A) first.
  for (const PairLaw& law : c.laws)
  {
    if (law.tension > 0.0 || law.cohesion > 0.0)
      throw std::invalid_argument("the paper's NCP formulation has no bonded "
                                  "joints (tension, cohesion)");
  }
  const Eigen::Index n = static_cast<Eigen::Index>(c.laws.size());
  const Eigen::VectorXd stuck = stuck_forces(c);
  auto merit = [&](const Eigen::VectorXd& p)
  {
    Eigen::VectorXd q(3 * n), theta(n);
    for (Eigen::Index i = 0; i < n; ++i)
    {
      q.segment<3>(3 * i) = paper_unknowns(p.segment<3>(3 * i));
      theta[i] = q[3 * i + 2];
    }
    return evaluate(c, q, theta).h.squaredNorm();
  };
  return from_two_starts(merit(p0) <= merit(stuck), [&](bool warm)
                         { return newton(c, warm ? p0 : stuck, s); });
}
} // namespace damseis::contact
