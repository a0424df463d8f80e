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
/// A x for the symmetric A (3n x 3n, dense): from the columns of A at the
/// nonzeros of x when they are few (a Newton direction late in the
/// iteration: only the pairs still changing), else from the lower
/// triangle (half of A read). Memory traffic is the cost here.
Eigen::VectorXd product_with(const Eigen::MatrixXd& A, const Eigen::VectorXd& x)
{
  std::vector<Eigen::Index> nonzero;
  for (Eigen::Index k = 0; k < x.size(); ++k)
    if (x[k] != 0.0)
      nonzero.push_back(k);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(x.size());
  if (4 * nonzero.size() < static_cast<std::size_t>(x.size()))
  {
    for (Eigen::Index k : nonzero)
      y += x[k] * A.col(k);
  }
  else
    y.noalias() = A.selfadjointView<Eigen::Lower>() * x;
  return y;
}

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
/// pairs); the others (open pairs, sliding pairs' tangential rows) couple
/// through W^-1 and form a dense system of their own size. W^-1 is read by
/// columns only (it is symmetric): the columns of the coupled rows' pairs,
/// once. Returns false if that system is singular.
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
    // The pairs of the coupled rows; for each of their components q (3 per
    // pair), column q of W^-1 gives (B W^-1)'s rows: its entries at the
    // coupled rows (Wc.col) and its product with the known z (y).
    std::vector<Eigen::Index> pairs;
    for (Eigen::Index j : coupled)
      if (pairs.empty() || pairs.back() != j / 3)
        pairs.push_back(j / 3);
    const Eigen::Index np = static_cast<Eigen::Index>(pairs.size());
    Eigen::MatrixXd Wc(m, 3 * np);
    Eigen::VectorXd y(3 * np);
    for (Eigen::Index a = 0; a < np; ++a)
    {
      for (Eigen::Index k = 0; k < 3; ++k)
      {
        const auto col = c.W_inv.col(3 * pairs[a] + k);
        for (Eigen::Index r = 0; r < m; ++r)
          Wc(r, 3 * a + k) = col[coupled[r]];
        y[3 * a + k] = col.dot(z); // z is zero at the coupled rows
      }
    }
    // S^T column by column (row r of S = sum_k B(l, k) W^-1 row (3i + k),
    // plus A(l, k) at the pair's own coupled components).
    Eigen::MatrixXd ST(m, m);
    Eigen::VectorXd rhs(m);
    Eigen::Index a = 0;
    for (Eigen::Index r = 0; r < m; ++r)
    {
      const Eigen::Index j = coupled[r], i = j / 3, l = j % 3;
      while (pairs[a] != i)
        ++a;
      const PairResidual& b = blocks[i];
      ST.col(r) = Wc.middleCols<3>(3 * a) * b.B.row(l).transpose();
      double known = b.B.row(l).dot(y.segment<3>(3 * a));
      for (Eigen::Index k = 0; k < 3; ++k)
      {
        if (position[3 * i + k] >= 0)
          ST(position[3 * i + k], r) += b.A(l, k);
        else
          known += b.A(l, k) * z[3 * i + k];
      }
      rhs[r] = -F[j] - known;
    }
    const Eigen::MatrixXd S = ST.transpose();
    Eigen::PartialPivLU<Eigen::MatrixXd> lu(S);
    const Eigen::VectorXd zc = lu.solve(rhs);
    if (!zc.allFinite() || (S * zc - rhs).norm() > 1e-6 * rhs.norm() + 1e-300)
      return false;
    for (Eigen::Index r = 0; r < m; ++r)
      z[coupled[r]] = zc[r];
  }
  d = product_with(c.W_inv, z);
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
/// The damped semismooth Newton iteration from p0, w0 = w_free + W p0
/// (`w0_exact`: computed so; else equal to it to round-off). w moves with p
/// along dw = W d (no product with W in an iteration of the reduced direction,
/// where dw = z); before convergence is accepted, w is computed afresh from p,
/// so no drift of the updates enters the result.
NcpReport newton(const ContactProblem& c, const Eigen::VectorXd& p0,
                 const Eigen::VectorXd& w0, bool w0_exact, const NcpSettings& s)
{
  const Eigen::Index n = static_cast<Eigen::Index>(c.laws.size());
  const bool reduced = c.W_inv.rows() == 3 * n && n > 0;
  NcpReport rep;
  rep.p = p0;
  const double scale = force_scale(c, p0);
  std::vector<PairResidual> blocks;
  rep.w = w0;
  bool w_afresh = w0_exact; // w = w_free + W p computed from p
  Eigen::VectorXd F = residual_at(c, rep.p, rep.w, rep.states, &blocks);
  double psi = 0.5 * F.squaredNorm();
  for (rep.iterations = 0; rep.iterations < s.max_iterations; ++rep.iterations)
  {
    rep.residual = F.norm() / scale;
    if (rep.residual <= s.tol && !w_afresh)
    {
      rep.w = c.w_free + product_with(c.W, rep.p);
      w_afresh = true;
      F = residual_at(c, rep.p, rep.w, rep.states, &blocks);
      psi = 0.5 * F.squaredNorm();
      rep.residual = F.norm() / scale;
    }
    const bool polishing = rep.residual <= s.tol;
    if (polishing && rep.iterations >= s.min_iterations)
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
        const Eigen::VectorXd trial = rep.p + alpha * dir;
        const Eigen::VectorXd w = rep.w + alpha * dir_w;
        std::vector<PairResidual> trial_blocks;
        std::vector<PairState> st;
        const Eigen::VectorXd Ft = residual_at(c, trial, w, st, &trial_blocks);
        const double psi_t = 0.5 * Ft.squaredNorm();
        if (psi_t <= (1.0 - 2e-4 * alpha) * psi)
        {
          rep.p = trial;
          rep.w = w;
          rep.states = std::move(st);
          blocks = std::move(trial_blocks);
          F = Ft;
          psi = psi_t;
          return true;
        }
        ++rep.line_search_steps;
      }
      return false;
    };
    if (search(d, dw))
      w_afresh = false;
    else if (polishing)
    {
      // Within tol already, and round-off allows no further descent.
      rep.converged = true;
      break;
    }
    else
    {
      ++rep.gradient_steps;
      if (J.size() == 0)
        J = dense_jacobian(c, blocks);
      const Eigen::VectorXd g = -J.transpose() * F;
      if (!search(g, c.W * g))
        break;
      w_afresh = false;
    }
  }
  rep.residual = F.norm() / scale;
  return rep;
}
} // namespace

double force_scale(const ContactProblem& c, const Eigen::VectorXd& p0)
{
  // A floor at 1e-3 of the forces of the total relative displacements:
  // when a load changes nothing (the free gaps and slips are round-off,
  // 1e-16 of those displacements), |F| cannot fall below that round-off,
  // which must stay below tol times the scale.
  constexpr double floor = 1e-3;
  double scale = 1e-300;
  for (std::size_t i = 0; i < c.laws.size(); ++i)
  {
    const Eigen::Index k = static_cast<Eigen::Index>(i);
    const PairLaw& l = c.laws[i];
    const Eigen::Vector2d wT = c.w_free.segment<2>(3 * k + 1);
    const Eigen::Vector2d wT_old = c.wT_old.segment<2>(2 * k);
    scale = std::max(
        {scale, l.tension, l.cohesion,
         l.r_n * std::abs(c.g0[k] + c.w_free[3 * k]),
         l.r_t * (wT - wT_old).norm(),
         floor * l.r_n * std::max(std::abs(c.g0[k]), std::abs(c.w_free[3 * k])),
         floor * l.r_t * std::max(wT.norm(), wT_old.norm())});
  }
  return std::max(scale, p0.lpNorm<Eigen::Infinity>());
}

namespace
{
/// The relative displacements with every pair closed and stuck: w_n =
/// -g0, w_T = w_T,old.
Eigen::VectorXd stuck_target(const ContactProblem& c)
{
  const Eigen::Index n = static_cast<Eigen::Index>(c.laws.size());
  Eigen::VectorXd target(3 * n);
  for (Eigen::Index i = 0; i < n; ++i)
    target.segment<3>(3 * i) << -c.g0[i], c.wT_old.segment<2>(2 * i);
  return target;
}
} // namespace

Eigen::VectorXd stuck_forces(const ContactProblem& c)
{
  // F = 0 with every pair closed and stuck: W p = w_target - w_free.
  const Eigen::Index n = static_cast<Eigen::Index>(c.laws.size());
  const Eigen::VectorXd target = stuck_target(c);
  return c.W_inv.rows() == 3 * n
             ? product_with(c.W_inv, target - c.w_free)
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
  const Eigen::VectorXd w_warm = c.w_free + product_with(c.W, p0);
  const Eigen::VectorXd w_stuck = stuck_target(c); // = w_free + W stuck
  auto merit = [&](const Eigen::VectorXd& p, const Eigen::VectorXd& w)
  {
    std::vector<PairState> st;
    return residual_at(c, p, w, st, nullptr).squaredNorm();
  };
  return from_two_starts(merit(p0, w_warm) <= merit(stuck, w_stuck),
                         [&](bool warm)
                         {
                           return warm ? newton(c, p0, w_warm, true, s)
                                       : newton(c, stuck, w_stuck, false, s);
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
