#include "alart_curnier.h"
#include <algorithm>
#include <cmath>

namespace damseis::contact
{
PairResidual alart_curnier(const PairLaw& law, const Eigen::Vector3d& p,
                           double g, const Eigen::Vector2d& ds)
{
  PairResidual r;
  r.B.setZero();
  r.A.setZero();
  // Normal: F_n = P_n + T - <sigma_n>, sigma_n = P_n + T - r_n g (T: the
  // bond's tension; the condition P_n + T >= 0 complementary to the gap).
  const double sigma_n = p[0] + law.tension - law.r_n * g;
  const bool closed = sigma_n >= 0.0;
  r.F[0] = p[0] + law.tension - std::max(sigma_n, 0.0);
  if (closed)
    r.A(0, 0) = law.r_n; // dF_n/dP_n = 0, dF_n/dg = r_n
  else
    r.B(0, 0) = 1.0;
  const Eigen::Vector2d PT = p.tail<2>();
  if (law.keyed)
  {
    // No sliding whatever the force: F_T = r_t ds (open or closed).
    r.F.tail<2>() = law.r_t * ds;
    r.A.block<2, 2>(1, 1) = law.r_t * Eigen::Matrix2d::Identity();
    r.state = closed ? PairState::stick : PairState::open;
    return r;
  }
  // Tangential: F_T = P_T - Pi_rho(tau), tau = P_T - r_t ds, rho = C + mu
  // P_n at the solution (sigma_n - T = P_n there). Where rho > 0 its
  // derivatives are those without a bond: mu (P_n), -mu r_n (g).
  const double rho =
      closed ? std::max(law.cohesion + law.mu * (sigma_n - law.tension), 0.0)
             : 0.0;
  const Eigen::Vector2d tau = PT - law.r_t * ds;
  const double nt = tau.norm();
  if (!closed || rho == 0.0)
  {
    r.F.tail<2>() = PT;
    r.B.block<2, 2>(1, 1) = Eigen::Matrix2d::Identity();
    r.state = closed ? PairState::slip : PairState::open;
    return r;
  }
  if (nt <= rho)
  {
    // Stick: F_T = r_t ds.
    r.F.tail<2>() = law.r_t * ds;
    r.A.block<2, 2>(1, 1) = law.r_t * Eigen::Matrix2d::Identity();
    r.state = PairState::stick;
    return r;
  }
  // Slip: F_T = P_T - rho e, e = tau / |tau|.
  const Eigen::Vector2d e = tau / nt;
  const Eigen::Matrix2d Gamma =
      (Eigen::Matrix2d::Identity() - e * e.transpose()) / nt;
  r.F.tail<2>() = PT - rho * e;
  r.B.block<2, 2>(1, 1) = Eigen::Matrix2d::Identity() - rho * Gamma;
  r.B.block<2, 1>(1, 0) = -law.mu * e;           // d/dP_n through rho
  r.A.block<2, 2>(1, 1) = rho * law.r_t * Gamma; // d/d ds
  r.A.block<2, 1>(1, 0) = law.mu * law.r_n * e;  // d/dg through rho
  r.state = PairState::slip;
  return r;
}

PairSolution solve_pair(const PairLaw& law, const Eigen::Matrix3d& W,
                        const Eigen::Vector3d& w_free,
                        const Eigen::Vector2d& w_T_old, double g0,
                        const Eigen::Vector3d& p0, double tol,
                        int max_iterations)
{
  // The residual of p through w = w_free + W p.
  auto evaluate = [&](const Eigen::Vector3d& p, Eigen::Vector3d& w)
  {
    w = w_free + W * p;
    return alart_curnier(law, p, g0 + w[0], w.tail<2>() - w_T_old);
  };
  // Force scale: what closing the free gap or slip would take.
  const double scale = std::max({law.r_n * std::abs(g0 + w_free[0]),
                                 law.r_t * (w_free.tail<2>() - w_T_old).norm(),
                                 p0.norm(), 1e-300});
  PairSolution s;
  s.p = p0;
  PairResidual r = evaluate(s.p, s.w);
  double psi = 0.5 * r.F.squaredNorm();
  for (s.iterations = 0; s.iterations < max_iterations; ++s.iterations)
  {
    if (r.F.norm() <= tol * scale)
    {
      s.converged = true;
      break;
    }
    // J = B + A dw/dp, dw/dp = W (the gap row of A is the w_n row).
    const Eigen::Matrix3d J = r.B + r.A * W;
    Eigen::Vector3d d = J.fullPivLu().solve(-r.F);
    if (!d.allFinite())
      d = -J.transpose() * r.F;
    // Armijo line search on psi, then the gradient direction.
    auto search = [&](const Eigen::Vector3d& dir) -> bool
    {
      for (double alpha = 1.0; alpha > 1e-6; alpha *= 0.5)
      {
        Eigen::Vector3d w;
        const Eigen::Vector3d trial = s.p + alpha * dir;
        const PairResidual rt = evaluate(trial, w);
        const double psi_t = 0.5 * rt.F.squaredNorm();
        if (psi_t <= (1.0 - 2e-4 * alpha) * psi)
        {
          s.p = trial;
          s.w = w;
          r = rt;
          psi = psi_t;
          return true;
        }
      }
      return false;
    };
    if (!search(d) && !search(-J.transpose() * r.F))
      break;
  }
  s.state = r.state;
  return s;
}
} // namespace damseis::contact
