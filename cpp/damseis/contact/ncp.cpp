#include "ncp.h"
#include <algorithm>
#include <cmath>

namespace damseis::contact
{
Eigen::VectorXd contact_residual(const ContactProblem& c,
                                 const Eigen::VectorXd& p, Eigen::VectorXd& w,
                                 std::vector<PairState>& states,
                                 Eigen::MatrixXd* J)
{
  const Eigen::Index n = static_cast<Eigen::Index>(c.laws.size());
  w = c.w_free + c.W * p;
  Eigen::VectorXd F(3 * n);
  states.resize(n);
  if (J)
    J->setZero(3 * n, 3 * n);
  for (Eigen::Index i = 0; i < n; ++i)
  {
    const Eigen::Vector3d pi = p.segment<3>(3 * i);
    const Eigen::Vector3d wi = w.segment<3>(3 * i);
    const PairResidual r =
        alart_curnier(c.laws[i], pi, c.g0[i] + wi[0],
                      wi.tail<2>() - c.wT_old.segment<2>(2 * i));
    F.segment<3>(3 * i) = r.F;
    states[i] = r.state;
    if (J)
    {
      // Rows of pair i: B on its own forces, A through all of w.
      J->block(3 * i, 3 * i, 3, 3) += r.B;
      J->middleRows(3 * i, 3) += r.A * c.W.middleRows(3 * i, 3);
    }
  }
  return F;
}

NcpReport solve_ncp(const ContactProblem& c, const Eigen::VectorXd& p0,
                    const NcpSettings& s)
{
  const Eigen::Index n = static_cast<Eigen::Index>(c.laws.size());
  NcpReport rep;
  rep.p = p0;
  // Force scale: the largest force that closes a free gap or stops a free
  // slip, or the warm start's.
  double scale = 1e-300;
  for (Eigen::Index i = 0; i < n; ++i)
  {
    scale =
        std::max({scale, c.laws[i].r_n * std::abs(c.g0[i] + c.w_free[3 * i]),
                  c.laws[i].r_t * (c.w_free.segment<2>(3 * i + 1) -
                                   c.wT_old.segment<2>(2 * i))
                                      .norm()});
  }
  scale = std::max(scale, p0.lpNorm<Eigen::Infinity>());
  Eigen::MatrixXd J;
  Eigen::VectorXd F = contact_residual(c, rep.p, rep.w, rep.states, &J);
  double psi = 0.5 * F.squaredNorm();
  for (rep.iterations = 0; rep.iterations < s.max_iterations; ++rep.iterations)
  {
    rep.residual = F.norm() / scale;
    if (rep.residual <= s.tol)
    {
      rep.converged = true;
      break;
    }
    Eigen::PartialPivLU<Eigen::MatrixXd> lu(J);
    Eigen::VectorXd d = lu.solve(-F);
    if (!d.allFinite() || (J * d + F).norm() > 1e-6 * F.norm())
    {
      // A singular generalised Jacobian: Levenberg-Marquardt damping.
      const double lm = 1e-8 * std::max(J.norm(), 1e-300);
      d = (J.transpose() * J +
           lm * lm * Eigen::MatrixXd::Identity(3 * n, 3 * n))
              .ldlt()
              .solve(-J.transpose() * F);
    }
    auto search = [&](const Eigen::VectorXd& dir) -> bool
    {
      for (double alpha = 1.0; alpha > 1e-6; alpha *= 0.5)
      {
        Eigen::VectorXd w;
        std::vector<PairState> st;
        const Eigen::VectorXd trial = rep.p + alpha * dir;
        const Eigen::VectorXd Ft = contact_residual(c, trial, w, st);
        const double psi_t = 0.5 * Ft.squaredNorm();
        if (psi_t <= (1.0 - 2e-4 * alpha) * psi)
        {
          rep.p = trial;
          return true;
        }
        ++rep.line_search_steps;
      }
      return false;
    };
    if (!search(d))
    {
      ++rep.gradient_steps;
      if (!search(-J.transpose() * F))
        break;
    }
    F = contact_residual(c, rep.p, rep.w, rep.states, &J);
    psi = 0.5 * F.squaredNorm();
  }
  rep.residual = F.norm() / scale;
  return rep;
}
} // namespace damseis::contact
