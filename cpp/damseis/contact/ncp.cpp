#include "ncp.h"
#include "paper_ncp.h"
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <stdexcept>

namespace damseis::contact
{
namespace
{
/// The residual at forces p with relative displacements w (3n), the pair
/// blocks of its generalised Jacobian and the states.
Eigen::VectorXd residual_at(const ContactProblem& c, const Eigen::VectorXd& p,
                            const Eigen::VectorXd& w,
                            std::vector<PairState>& states,
                            std::vector<PairResidual>* blocks)
{
  const Eigen::Index n = static_cast<Eigen::Index>(c.laws.size());
  Eigen::VectorXd F(3 * n);
  states.resize(n);
  if (blocks)
    blocks->resize(n);
  for (Eigen::Index i = 0; i < n; ++i)
  {
    const Eigen::Vector3d wi = w.segment<3>(3 * i);
    const PairResidual r =
        alart_curnier(c.laws[i], p.segment<3>(3 * i), c.g0[i] + wi[0],
                      wi.tail<2>() - c.wT_old.segment<2>(2 * i));
    F.segment<3>(3 * i) = r.F;
    states[i] = r.state;
    if (blocks)
      (*blocks)[i] = r;
  }
  return F;
}

/// J = B + A W (dense) from the pair blocks.
Eigen::MatrixXd dense_jacobian(const ContactProblem& c,
                               const std::vector<PairResidual>& blocks)
{
  const Eigen::Index n = static_cast<Eigen::Index>(c.laws.size());
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (Eigen::Index i = 0; i < n; ++i)
  {
    J.block(3 * i, 3 * i, 3, 3) += blocks[i].B;
    J.middleRows(3 * i, 3) += blocks[i].A * c.W.middleRows(3 * i, 3);
  }
  return J;
}

/// The Newton direction d of J d = -F with J = B + A W, found through
/// z = W d: (B W^-1 + A) z = -F. A row whose B row is zero reads
/// A_jj z_j = -F_j (sticking pairs, the normal row of closed pairs, keyed
/// pairs); the others couple through W^-1 and form a dense system of their
/// own size. Returns false if that system is singular.
bool reduced_direction(const ContactProblem& c,
                       const std::vector<PairResidual>& blocks,
                       const Eigen::VectorXd& F, Eigen::VectorXd& d,
                       Eigen::VectorXd& z, int& rows)
{
  const Eigen::Index n3 = F.size();
  z = Eigen::VectorXd::Zero(n3);
  std::vector<Eigen::Index> coupled; // the rows (= components) in the system
  std::vector<Eigen::Index> position(n3, -1);
  for (Eigen::Index j = 0; j < n3; ++j)
  {
    const PairResidual& b = blocks[j / 3];
    const Eigen::Index l = j % 3;
    const bool local = b.B.row(l).isZero(0.0) && b.A(l, l) != 0.0 &&
                       b.A.row(l).cwiseAbs().sum() == std::abs(b.A(l, l));
    if (local)
      z[j] = -F[j] / b.A(l, l);
    else
    {
      position[j] = static_cast<Eigen::Index>(coupled.size());
      coupled.push_back(j);
    }
  }
  rows = static_cast<int>(coupled.size());
  if (!coupled.empty())
  {
    const Eigen::Index m = static_cast<Eigen::Index>(coupled.size());
    Eigen::MatrixXd S(m, m);
    Eigen::VectorXd rhs(m);
    Eigen::RowVectorXd BW(n3);
    for (Eigen::Index r = 0; r < m; ++r)
    {
      const Eigen::Index j = coupled[r], i = j / 3, l = j % 3;
      const PairResidual& b = blocks[i];
      // Row l of B_i times the rows of W^-1 of pair i.
      BW = b.B(l, 0) * c.W_inv.row(3 * i) + b.B(l, 1) * c.W_inv.row(3 * i + 1) +
           b.B(l, 2) * c.W_inv.row(3 * i + 2);
      for (int k = 0; k < 3; ++k)
        BW[3 * i + k] += b.A(l, k);
      double known = 0.0;
      for (Eigen::Index k = 0; k < n3; ++k)
      {
        if (position[k] >= 0)
          S(r, position[k]) = BW[k];
        else
          known += BW[k] * z[k];
      }
      rhs[r] = -F[j] - known;
    }
    Eigen::PartialPivLU<Eigen::MatrixXd> lu(S);
    const Eigen::VectorXd zc = lu.solve(rhs);
    if (!zc.allFinite() || (S * zc - rhs).norm() > 1e-6 * rhs.norm() + 1e-300)
      return false;
    for (Eigen::Index r = 0; r < m; ++r)
      z[coupled[r]] = zc[r];
  }
  d = c.W_inv * z;
  return true;
}
} // namespace

void write_problem(const ContactProblem& c, const Eigen::VectorXd& p0,
                   const std::string& file)
{
  std::ofstream out(file, std::ios::binary);
  auto put = [&](const Eigen::MatrixXd& m)
  {
    const std::int64_t r = m.rows(), k = m.cols();
    out.write(reinterpret_cast<const char*>(&r), sizeof r);
    out.write(reinterpret_cast<const char*>(&k), sizeof k);
    out.write(reinterpret_cast<const char*>(m.data()),
              static_cast<std::streamsize>(sizeof(double) * r * k));
  };
  Eigen::MatrixXd laws(static_cast<Eigen::Index>(c.laws.size()), 4);
  for (std::size_t i = 0; i < c.laws.size(); ++i)
    laws.row(static_cast<Eigen::Index>(i)) << c.laws[i].mu,
        c.laws[i].keyed ? 1.0 : 0.0, c.laws[i].r_n, c.laws[i].r_t;
  for (const Eigen::MatrixXd& m :
       {laws, c.W, c.W_inv, Eigen::MatrixXd(c.w_free),
        Eigen::MatrixXd(c.wT_old), Eigen::MatrixXd(c.g0), Eigen::MatrixXd(p0)})
    put(m);
}

ContactProblem read_problem(const std::string& file, Eigen::VectorXd& p0)
{
  std::ifstream in(file, std::ios::binary);
  auto get = [&]()
  {
    std::int64_t r = 0, k = 0;
    in.read(reinterpret_cast<char*>(&r), sizeof r);
    in.read(reinterpret_cast<char*>(&k), sizeof k);
    Eigen::MatrixXd m(r, k);
    in.read(reinterpret_cast<char*>(m.data()),
            static_cast<std::streamsize>(sizeof(double) * r * k));
    if (!in)
      throw std::runtime_error("cannot read the contact problem " + file);
    return m;
  };
  ContactProblem c;
  const Eigen::MatrixXd laws = get();
  for (Eigen::Index i = 0; i < laws.rows(); ++i)
    c.laws.push_back({laws(i, 0), laws(i, 1) != 0.0, laws(i, 2), laws(i, 3)});
  c.W = get();
  c.W_inv = get();
  c.w_free = get();
  c.wT_old = get();
  c.g0 = get();
  p0 = get();
  return c;
}

Eigen::VectorXd contact_residual(const ContactProblem& c,
                                 const Eigen::VectorXd& p, Eigen::VectorXd& w,
                                 std::vector<PairState>& states,
                                 Eigen::MatrixXd* J)
{
  w = c.w_free + c.W * p;
  std::vector<PairResidual> blocks;
  Eigen::VectorXd F = residual_at(c, p, w, states, J ? &blocks : nullptr);
  if (J)
    *J = dense_jacobian(c, blocks);
  return F;
}

namespace
{
/// The damped semismooth Newton iteration from p0, w0 = w_free + W p0.
NcpReport newton(const ContactProblem& c, const Eigen::VectorXd& p0,
                 const Eigen::VectorXd& w0, const NcpSettings& s)
{
  const Eigen::Index n = static_cast<Eigen::Index>(c.laws.size());
  const bool reduced = c.W_inv.rows() == 3 * n && n > 0;
  NcpReport rep;
  rep.p = p0;
  const double scale = force_scale(c, p0);
  std::vector<PairResidual> blocks;
  rep.w = w0;
  Eigen::VectorXd F = residual_at(c, rep.p, rep.w, rep.states, &blocks);
  double psi = 0.5 * F.squaredNorm();
  for (rep.iterations = 0; rep.iterations < s.max_iterations; ++rep.iterations)
  {
    rep.residual = F.norm() / scale;
    if (rep.residual <= s.tol)
    {
      rep.converged = true;
      break;
    }
    // The direction d (and dw = W d), by the reduced system or densely.
    Eigen::VectorXd d, dw;
    Eigen::MatrixXd J;
    bool found =
        reduced && reduced_direction(c, blocks, F, d, dw, rep.reduced_rows);
    if (!found)
    {
      J = dense_jacobian(c, blocks);
      Eigen::PartialPivLU<Eigen::MatrixXd> lu(J);
      d = lu.solve(-F);
      if (!d.allFinite() || (J * d + F).norm() > 1e-6 * F.norm())
      {
        // A singular generalised Jacobian: Levenberg-Marquardt damping.
        const double lm = 1e-8 * std::max(J.norm(), 1e-300);
        d = (J.transpose() * J +
             lm * lm * Eigen::MatrixXd::Identity(3 * n, 3 * n))
                .ldlt()
                .solve(-J.transpose() * F);
      }
      dw = c.W * d;
    }
    // Armijo line search on psi along (d, dw); w moves linearly with p.
    auto search = [&](const Eigen::VectorXd& dir,
                      const Eigen::VectorXd& dir_w) -> bool
    {
      for (double alpha = 1.0; alpha > 1e-6; alpha *= 0.5)
      {
        std::vector<PairState> st;
        const Eigen::VectorXd trial = rep.p + alpha * dir;
        const Eigen::VectorXd w = rep.w + alpha * dir_w;
        const Eigen::VectorXd Ft = residual_at(c, trial, w, st, nullptr);
        if (0.5 * Ft.squaredNorm() <= (1.0 - 2e-4 * alpha) * psi)
        {
          rep.p = trial;
          return true;
        }
        ++rep.line_search_steps;
      }
      return false;
    };
    if (!search(d, dw))
    {
      ++rep.gradient_steps;
      if (J.size() == 0)
        J = dense_jacobian(c, blocks);
      const Eigen::VectorXd g = -J.transpose() * F;
      if (!search(g, c.W * g))
        break;
    }
    // w afresh from p (no drift from the line search's updates).
    rep.w = c.w_free + c.W * rep.p;
    F = residual_at(c, rep.p, rep.w, rep.states, &blocks);
    psi = 0.5 * F.squaredNorm();
  }
  rep.residual = F.norm() / scale;
  return rep;
}
} // namespace

double force_scale(const ContactProblem& c, const Eigen::VectorXd& p0)
{
  double scale = 1e-300;
  for (std::size_t i = 0; i < c.laws.size(); ++i)
  {
    const Eigen::Index k = static_cast<Eigen::Index>(i);
    scale =
        std::max({scale, c.laws[i].r_n * std::abs(c.g0[k] + c.w_free[3 * k]),
                  c.laws[i].r_t * (c.w_free.segment<2>(3 * k + 1) -
                                   c.wT_old.segment<2>(2 * k))
                                      .norm()});
  }
  return std::max(scale, p0.lpNorm<Eigen::Infinity>());
}

Eigen::VectorXd stuck_forces(const ContactProblem& c)
{
  // F = 0 with every pair closed and stuck: w_n = -g0, w_T = w_T,old, i.e.
  // W p = w_target - w_free.
  const Eigen::Index n = static_cast<Eigen::Index>(c.laws.size());
  Eigen::VectorXd target(3 * n);
  for (Eigen::Index i = 0; i < n; ++i)
    target.segment<3>(3 * i) << -c.g0[i], c.wT_old.segment<2>(2 * i);
  return c.W_inv.rows() == 3 * n
             ? Eigen::VectorXd(c.W_inv * (target - c.w_free))
             : Eigen::VectorXd(c.W.ldlt().solve(target - c.w_free));
}

NcpReport solve_ncp(const ContactProblem& c, const Eigen::VectorXd& p0,
                    const NcpSettings& s)
{
  if (s.formulation == Formulation::paper)
    return solve_ncp_paper(c, p0, s);
  // Two starting points: the warm start (the last step's forces: best when
  // little changes) and the forces of the joints stuck (best after a large
  // change of load: the bonded solution, from which only the pairs in
  // tension open and those past the friction limit slide). Newton starts
  // from the one of smaller residual, and from the other if it fails.
  // (Each start's w = w_free + W p is computed once, for the choice and for
  // Newton.)
  const Eigen::VectorXd stuck = stuck_forces(c);
  const Eigen::VectorXd w_warm = c.w_free + c.W * p0;
  const Eigen::VectorXd w_stuck = c.w_free + c.W * stuck;
  auto merit = [&](const Eigen::VectorXd& p, const Eigen::VectorXd& w)
  {
    std::vector<PairState> st;
    return residual_at(c, p, w, st, nullptr).squaredNorm();
  };
  return from_two_starts(merit(p0, w_warm) <= merit(stuck, w_stuck),
                         [&](bool warm) {
                           return warm ? newton(c, p0, w_warm, s)
                                       : newton(c, stuck, w_stuck, s);
                         });
}

NcpReport from_two_starts(bool warm_first,
                          const std::function<NcpReport(bool warm)>& newton)
{
  NcpReport first = newton(warm_first);
  if (first.converged)
    return first;
  NcpReport second = newton(!warm_first);
  second.iterations += first.iterations;
  second.line_search_steps += first.line_search_steps;
  second.gradient_steps += first.gradient_steps;
  return second.converged || second.residual < first.residual ? second : first;
}
} // namespace damseis::contact
