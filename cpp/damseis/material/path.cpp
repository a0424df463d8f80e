#include "path.h"

#include <Eigen/Dense>
#include <cmath>
#include <ostream>
#include <stdexcept>

namespace damseis::material
{

namespace
{
struct StepResult
{
  Update update;
  Vector6 d_strain{};
  int outer = 0;
  bool ok = false;
};

/// One step from `old` with prescribed strain increments (strain-controlled
/// components of de) and stress targets (stress-controlled components).
StepResult one_step(const HtcConcrete& model, const State& old,
                    const std::array<Control, 6>& control,
                    const std::array<int, 6>& tie, Vector6 de,
                    const Vector6& sig_target, double dt, double tol,
                    const Matrix6& guess_tangent)
{
  StepResult r;
  int free_idx[6], nf = 0;
  for (int i = 0; i < 6; ++i)
    if (control[i] == Control::stress && tie[i] < 0)
      free_idx[nf++] = i;
  auto apply_ties = [&](Vector6& d)
  {
    for (int i = 0; i < 6; ++i)
      if (tie[i] >= 0)
        d[i] = d[tie[i]];
  };
  apply_ties(de);
  auto solve_free = [&](const Matrix6& T, const Vector6& res, Vector6& d)
  {
    Eigen::MatrixXd A(nf, nf);
    Eigen::VectorXd b(nf);
    for (int a = 0; a < nf; ++a)
    {
      b[a] = -res[free_idx[a]];
      for (int c = 0; c < nf; ++c)
      {
        A(a, c) = T[free_idx[a] * 6 + free_idx[c]];
        for (int i = 0; i < 6; ++i)
          if (tie[i] == free_idx[c])
            A(a, c) += T[free_idx[a] * 6 + i];
      }
    }
    // Minimum-norm solution: at a corner of the surface (e.g. the
    // compressive-meridian edge in uniaxial compression) the flow split
    // between the two surfaces is not fixed by stress control and the
    // free-free block of the tangent is singular; the minimum-norm
    // correction keeps the symmetric split.
    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(A);
    cod.setThreshold(1e-9);
    const Eigen::VectorXd x = cod.solve(b);
    for (int a = 0; a < nf; ++a)
      d[free_idx[a]] += x[a];
    apply_ties(d);
  };
  if (nf > 0)
  {
    // Predictor with the last tangent: T (de) = sigma_target - sigma_old
    // on the free rows.
    Vector6 res{};
    for (int a = 0; a < nf; ++a)
    {
      const int i = free_idx[a];
      double s = old.stress[i] - sig_target[i];
      for (int j = 0; j < 6; ++j)
        if (control[j] == Control::strain && tie[j] < 0)
          s += guess_tangent[i * 6 + j] * de[j];
      res[i] = s;
    }
    for (int a = 0; a < nf; ++a)
      de[free_idx[a]] = 0.0;
    apply_ties(de);
    solve_free(guess_tangent, res, de);
  }
  const double fc0 = model.derived().fc0;
  for (int it = 0; it < 40; ++it)
  {
    r.update = model.integrate(old, de, dt);
    if (!r.update.converged)
      return r;
    Vector6 res{};
    double err = 0;
    for (int a = 0; a < nf; ++a)
    {
      const int i = free_idx[a];
      res[i] = r.update.state.stress[i] - sig_target[i];
      err = std::max(err, std::abs(res[i]));
    }
    if (err <= tol * fc0)
    {
      r.ok = true;
      r.d_strain = de;
      return r;
    }
    ++r.outer;
    solve_free(r.update.tangent, res, de);
  }
  return r;
}
} // namespace

PathResult run_path(const HtcConcrete& model,
                    const std::vector<Segment>& segments, const State& initial,
                    double stress_tolerance)
{
  PathResult out;
  PathPoint p;
  p.state = initial;
  out.points.push_back(p);
  Matrix6 tangent = model.elastic_tangent();
  for (const auto& seg : segments)
  {
    if (!(seg.duration > 0) || seg.steps < 1)
      throw std::invalid_argument("run_path: segment needs duration > 0 and "
                                  "steps >= 1");
    const PathPoint start = out.points.back();
    const double dt = seg.duration / seg.steps;
    for (int k = 1; k <= seg.steps; ++k)
    {
      const PathPoint& prev = out.points.back();
      const double f = double(k) / seg.steps;
      Vector6 de{}, st{};
      for (int i = 0; i < 6; ++i)
      {
        if (seg.control[i] == Control::strain)
          de[i] = start.strain[i] + f * (seg.target[i] - start.strain[i]) -
                  prev.strain[i];
        else
          st[i] = start.state.stress[i] +
                  f * (seg.target[i] - start.state.stress[i]);
      }
      // Try the whole step, then 2, 4, ... sub-steps.
      bool done = false;
      for (int nsub = 1; nsub <= 64 && !done; nsub *= 2)
      {
        State s = prev.state;
        Vector6 total{};
        Matrix6 T = tangent;
        StepResult r;
        bool ok = true;
        int outer = 0;
        for (int j = 1; j <= nsub && ok; ++j)
        {
          Vector6 dej{}, stj{};
          for (int i = 0; i < 6; ++i)
          {
            dej[i] = de[i] / nsub;
            stj[i] = prev.state.stress[i] +
                     double(j) / nsub * (st[i] - prev.state.stress[i]);
          }
          r = one_step(model, s, seg.control, seg.tie, dej, stj, dt / nsub,
                       stress_tolerance, T);
          ok = r.ok;
          if (ok)
          {
            s = r.update.state;
            T = r.update.tangent;
            outer += r.outer;
            for (int i = 0; i < 6; ++i)
              total[i] += r.d_strain[i];
          }
        }
        if (!ok)
          continue;
        done = true;
        PathPoint q;
        q.time = prev.time + dt;
        for (int i = 0; i < 6; ++i)
        {
          q.strain[i] = prev.strain[i] + total[i];
          q.strain_rate[i] = total[i] / dt;
        }
        q.state = s;
        q.active = r.update.active;
        q.local_iterations = r.update.iterations;
        q.outer_iterations = outer;
        out.points.push_back(q);
        tangent = T;
      }
      if (!done)
      {
        out.completed = false;
        out.message = "step at t = " + std::to_string(prev.time + dt) +
                      " did not converge (even with 64 sub-steps)";
        return out;
      }
    }
  }
  return out;
}

void write_csv(std::ostream& o, const PathResult& r)
{
  o << "time,eps11,eps22,eps33,gamma12,gamma23,gamma13,"
       "sig11,sig22,sig33,sig12,sig23,sig13,"
       "kappa_t,kappa_c,kappa_t_rate,kappa_c_rate,eps11_rate,"
       "active,local_iterations,outer_iterations\n";
  o.precision(10);
  for (const auto& p : r.points)
  {
    o << p.time;
    for (double v : p.strain)
      o << ',' << v;
    for (double v : p.state.stress)
      o << ',' << v;
    o << ',' << p.state.kappa_t << ',' << p.state.kappa_c << ','
      << p.state.kappa_t_rate << ',' << p.state.kappa_c_rate << ','
      << p.strain_rate[0] << ',' << active_set_name(p.active) << ','
      << p.local_iterations << ',' << p.outer_iterations << '\n';
  }
}

std::vector<Segment> uniaxial_path(double eps_end, double rate, int steps)
{
  Segment s;
  s.duration = std::abs(eps_end) / rate;
  s.steps = steps;
  s.control.fill(Control::stress);
  s.control[0] = Control::strain;
  s.target = {eps_end, 0, 0, 0, 0, 0};
  s.tie[2] = 1; // axisymmetric: eps33 = eps22
  return {s};
}

} // namespace damseis::material
