#include "nonlinear_newmark.h"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <damseis/linalg/duplicate_matrix.h>
#include <functional>
#include <string>
#include <vector>

namespace damseis::dynamics
{
namespace
{
double norm(Vec x)
{
  double n = 0.0;
  VecNorm(x, NORM_2, &n);
  return n;
}

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

const bool trace = std::getenv("DAMSEIS_NEWTON_TRACE") != nullptr;

/// Newton iteration on u for R(u) = 0. `residual` evaluates the trial state
/// and R (false: material failure); `jacobian` assembles the consistent
/// matrix of the last trial into J. Directions: the factorised initial
/// matrix while the trial is elastic (exact then, unless shifted), else the
/// tangent solved by `tangent` (GMRES on reused factors, or a new
/// factorisation); backed by the initial matrix's direction if the
/// tangent's finds no decrease. On success u holds the solution and the
/// system's trial state matches it.
/// With a constraint (newton_constraint.h; null: none) its trial force
/// joins the residual, every direction is corrected on the initial matrix
/// J0 (`J0_matrix`, factorised in `initial` and in the constraint), and the
/// iteration converges only with a consistent constraint force.
bool newton(const std::function<bool(Vec, Vec)>& residual,
            const std::function<void(Mat)>& jacobian,
            const NonlinearSystem& system, const linalg::DirectSolver& initial,
            int level, Mat J, TangentSolver& tangent, double reference, Vec u,
            Vec R, Vec du, const NewtonSettings& s, StepReport& report,
            NewtonConstraint* constraint = nullptr, Mat J0_matrix = nullptr)
{
  // Each step starts from the initial matrix's factors as preconditioner
  // (measured: the last step's tangent preconditions worse, since the points
  // that yielded in it mostly unload elastically).
  tangent.forget();
  auto evaluate = [&](Vec x, Vec r)
  {
    const auto t0 = Clock::now();
    const bool ok = residual(x, r);
    if (ok && constraint)
      VecAXPY(r, -1.0, constraint->force());
    report.seconds_residual += since(t0);
    return ok;
  };
  if (constraint)
    constraint->begin();
  if (!evaluate(u, R))
  {
    if (trace)
      std::fprintf(stderr, "newton: material failure at the predictor\n");
    return false;
  }
  Vec u0, R0;
  VecDuplicate(u, &u0);
  VecDuplicate(R, &R0);
  double r = norm(R);
  const double tol = s.rtol * reference;
  if (trace)
    std::fprintf(stderr, "newton: it 0  |R|/|F| %.3e  |F| %.3e\n",
                 r / reference, reference);
  bool converged = false;
  // Non-monotone line search (Grippo, Lampariello & Lucidi 1986): a trial is
  // accepted if it decreases the largest of the last 4 residual norms, so
  // that full Newton steps through active-set changes are not cut back.
  std::vector<double> recent = {r};
  double r_best = r;
  int it_best = 0;
  for (int it = 0;; ++it)
  {
    report.residual = r / reference;
    if (s.monitor)
      s.monitor(it, r / reference);
    if (r <= tol && (!constraint || constraint->consistent()))
    {
      converged = true;
      break;
    }
    if (r < 0.5 * r_best)
    {
      r_best = r;
      it_best = it;
    }
    // Stagnation (e.g. points cycling between loading and unloading on a
    // steep softening branch): give up early, so that the step is cut; the
    // inertia term a0 M of the shorter step regularises the softening.
    if (it == s.max_iterations || !std::isfinite(r) ||
        it - it_best >= s.stagnation_iterations)
    {
      break;
    }
    VecCopy(u, u0);
    VecCopy(R, R0);
    if (constraint)
      constraint->start_iteration();
    bool accepted = false;
    // pass 0: the tangent (skipped while the trial is elastic); pass 1: the
    // initial matrix.
    for (int pass = system.tangent_is_initial() ? 1 : 0; pass < 2 && !accepted;
         ++pass)
    {
      std::string how = "initial matrix";
      if (pass == 0)
      {
        auto t0 = Clock::now();
        jacobian(J);
        report.seconds_tangent += since(t0);
        t0 = Clock::now();
        const Direction d = tangent.solve(J, initial, level, R0, du, 0.1 * tol);
        report.seconds_factorization += tangent.last_factor_seconds();
        report.seconds_solve += since(t0) - tangent.last_factor_seconds();
        report.krylov_iterations += tangent.last_krylov_iterations();
        if (d == Direction::factorized)
          ++report.tangent_factorizations;
        how = "tangent, " + std::to_string(tangent.last_krylov_iterations()) +
              " GMRES" +
              (d == Direction::factorized ? " + factorised"
               : d == Direction::failed   ? " + singular"
                                          : "");
        if (d == Direction::failed)
        {
          if (trace)
            std::fprintf(stderr, "newton:   %s\n", how.c_str());
          continue;
        }
      }
      else
      {
        const auto t0 = Clock::now();
        initial.solve(R0, du);
        report.seconds_solve += since(t0);
      }
      if (constraint)
      {
        // The bulk's iterate u0 - du corrected by the constraint. A
        // constraint problem that cannot be solved at this iterate fails
        // the direction (the next pass, or a cut step), not the run.
        VecWAXPY(u, -1.0, du, u0);
        const auto t0 = Clock::now();
        try
        {
          constraint->correct(J0_matrix, u);
        }
        catch (const StepFailure& e)
        {
          report.seconds_solve += since(t0);
          if (trace)
            std::fprintf(stderr, "newton:   constraint failed (%s): %s\n",
                         how.c_str(), e.what());
          continue;
        }
        report.seconds_solve += since(t0);
        VecWAXPY(du, -1.0, u, u0);
      }
      double dn = 0.0;
      VecNorm(du, NORM_2, &dn);
      if (!std::isfinite(dn))
      {
        if (trace)
          std::fprintf(stderr, "newton:   non-finite direction (%s)\n",
                       how.c_str());
        continue;
      }
      double eta = 1.0;
      const double r_ref = *std::max_element(recent.begin(), recent.end());
      for (int ls = 0; ls < 6; ++ls)
      {
        VecWAXPY(u, -eta, du, u0);
        if (constraint)
          constraint->blend(eta);
        const bool ok = evaluate(u, R);
        const double rt = ok ? norm(R) : INFINITY;
        // (A residual within the tolerance is taken as it is: a start at
        // round-off need not decrease, and with a constraint the step must
        // still reach a consistent constraint force.)
        if (ok && (rt <= (1.0 - 1e-4 * eta) * r_ref || rt <= tol))
        {
          accepted = true;
          r = rt;
          recent.push_back(r);
          if (recent.size() > 4)
            recent.erase(recent.begin());
          if (trace)
          {
            std::fprintf(stderr,
                         "newton: it %d  |R|/|F| %.3e  (%s, eta %.3g)\n",
                         it + 1, r / reference, how.c_str(), eta);
          }
          break;
        }
        if (trace)
        {
          std::fprintf(stderr, "newton:   %s: eta %.3g rejected (%s)\n",
                       how.c_str(), eta,
                       ok ? "no decrease" : "material failure");
        }
        eta *= 0.35;
      }
    }
    ++report.iterations;
    if (!accepted)
      break;
  }
  VecDestroy(&u0);
  VecDestroy(&R0);
  return converged;
}
} // namespace

StepReport solve_static(NonlinearSystem& system, Mat K0, Vec F_from, Vec F_to,
                        int increments, Vec u, const NewtonSettings& settings,
                        linalg::Factorization factorization,
                        const StaticConstraint& constrained)
{
  MPI_Comm comm;
  PetscObjectGetComm(reinterpret_cast<PetscObject>(K0), &comm);
  // The initial matrix K0, or K0 + s M with a shifted constraint.
  const bool shifted = constrained.constraint && constrained.shift > 0.0;
  Mat J0 = K0;
  if (shifted)
  {
    J0 = linalg::duplicate_matrix(K0, MAT_COPY_VALUES);
    MatAXPY(J0, constrained.shift, constrained.M, SUBSET_NONZERO_PATTERN);
  }
  // The tangent may be indefinite (softening): MUMPS' LU pivots.
  linalg::DirectSolver initial(comm, factorization);
  TangentSolver tangent_solver(comm, settings.krylov_rtol,
                               settings.krylov_max_iterations);
  initial.factorize(J0);
  NewtonConstraint* constraint = constrained.constraint;
  if (constraint)
    constraint->factorize(J0);
  Mat J = linalg::duplicate_matrix(K0, MAT_DO_NOT_COPY_VALUES);
  Vec F, R, du, ut, fint;
  for (Vec* x : {&F, &R, &du, &ut, &fint})
    VecDuplicate(u, x);

  StepReport report;
  auto residual = [&](Vec x, Vec r) -> bool
  {
    if (!system.trial(x, 0.0))
      return false;
    system.internal_force(fint);
    VecWAXPY(r, -1.0, F, fint);
    return true;
  };
  auto jacobian = [&](Mat A)
  {
    MatCopy(J0, A, SAME_NONZERO_PATTERN);
    system.add_tangent_change(A, 1.0);
  };
  auto release = [&]
  {
    for (Vec* x : {&F, &R, &du, &ut, &fint})
      VecDestroy(x);
    MatDestroy(&J);
    if (shifted)
      MatDestroy(&J0);
  };

  // Load factors still to reach, solved one after the other; a failed
  // increment is replaced by its two halves.
  std::vector<std::pair<double, int>> todo; // (target factor, cuts)
  for (int i = increments; i >= 1; --i)
    todo.emplace_back(static_cast<double>(i) / increments, 0);
  double done = 0.0;
  while (!todo.empty())
  {
    const auto [target, cuts] = todo.back();
    VecAXPBYPCZ(F, 1.0 - target, target, 0.0, F_from, F_to);
    const double reference = std::max(norm(F), norm(F_to));
    VecCopy(u, ut);
    bool converged = false;
    try
    {
      converged =
          newton(residual, jacobian, system, initial, 0, J, tangent_solver,
                 reference, ut, R, du, settings, report, constraint, J0);
    }
    catch (...)
    {
      if (constraint)
        constraint->reject();
      release();
      throw;
    }
    if (converged && system.accept())
    {
      if (constraint)
        constraint->accept();
      VecCopy(ut, u);
      done = target;
      todo.pop_back();
      continue;
    }
    if (constraint)
      constraint->reject();
    if (cuts >= settings.max_cuts)
    {
      release();
      throw StaticStepFailure(
          "static load step to factor " + std::to_string(target) +
              " did not converge after " + std::to_string(cuts) +
              " halvings (last residual " + std::to_string(report.residual) +
              " of the load)",
          done, report);
    }
    todo.back().second = cuts + 1;
    todo.emplace_back(0.5 * (done + target), cuts + 1);
    ++report.cuts;
  }
  release();
  return report;
}

NonlinearNewmark::NonlinearNewmark(Mat M, Mat K0, RayleighDamping damping,
                                   TimeScheme scheme, NonlinearSystem& system,
                                   NewtonSettings settings,
                                   linalg::Factorization factorization,
                                   Mat extra_damping)
    : _M(M), _K0(K0), _Ce(extra_damping), _damping(damping), _scheme(scheme),
      _system(system), _settings(settings), _factorization(factorization)
{
  if (!(scheme.dt > 0.0 && std::isfinite(scheme.dt)))
    throw std::invalid_argument("time step must be positive");
  if (!(scheme.alpha >= -1.0 / 3.0 - 1e-14 && scheme.alpha <= 0.0))
    throw std::invalid_argument("HHT alpha must lie in [-1/3, 0]");
  for (Vec* x : {&_u,       &_v,       &_a,       &_f,      &_fint,   &_ut,
                 &_vt,      &_at,      &_fint_t,  &_r,      &_g,      &_w1,
                 &_w2,      &_du,      &_tmp,     &_u_prev, &_v_prev, &_a_prev,
                 &_u_start, &_v_start, &_a_start, &_d_p})
  {
    MatCreateVecs(K0, x, nullptr);
    VecSet(*x, 0.0);
  }
  MPI_Comm comm;
  PetscObjectGetComm(reinterpret_cast<PetscObject>(K0), &comm);
  _tangent_solver = std::make_unique<TangentSolver>(
      comm, settings.krylov_rtol, settings.krylov_max_iterations);
  StepReport dummy;
  initial_solver(0, dummy);
}

NonlinearNewmark::~NonlinearNewmark()
{
  for (Vec* x : {&_u,       &_v,       &_a,       &_f,      &_fint,   &_ut,
                 &_vt,      &_at,      &_fint_t,  &_r,      &_g,      &_w1,
                 &_w2,      &_du,      &_tmp,     &_u_prev, &_v_prev, &_a_prev,
                 &_u_start, &_v_start, &_a_start, &_d_p})
  {
    VecDestroy(x);
  }
  for (auto& [level, entry] : _initial)
  {
    entry.solver.reset();
    MatDestroy(&entry.J0);
  }
  if (_J)
    MatDestroy(&_J);
}

const linalg::DirectSolver& NonlinearNewmark::solver() const
{
  return *_initial.at(0).solver;
}

const linalg::DirectSolver& NonlinearNewmark::initial_solver(int level,
                                                             StepReport& report)
{
  auto it = _initial.find(level);
  if (it != _initial.end())
  {
    _level = &it->second;
    return *it->second.solver;
  }
  const double dt = _scheme.dt / std::pow(2.0, level);
  const double beta = _scheme.beta(), gamma = _scheme.gamma();
  const double w = 1.0 + _scheme.alpha;
  const double a0 = 1.0 / (beta * dt * dt), a1 = gamma / (beta * dt);
  // J0 = a0 M + (1 + alpha)(a1 C + K0).
  Mat J0 = linalg::duplicate_matrix(_K0, MAT_COPY_VALUES);
  if (_partition.K_implicit)
  {
    // a0 M + w (a1 (a_M M + b_K K_I) + K0 - K_E), the prescribed rows
    // and columns identity (w = 1 with explicit elements).
    if (_partition.K_explicit)
      MatAXPY(J0, -1.0, _partition.K_explicit, SUBSET_NONZERO_PATTERN);
    MatScale(J0, w);
    MatAXPY(J0, w * a1 * _damping.b_stiffness, _partition.K_implicit,
            SUBSET_NONZERO_PATTERN);
  }
  else
    MatScale(J0, w * (1.0 + a1 * _damping.b_stiffness));
  MatAXPY(J0, a0 + w * a1 * _damping.a_mass, _M, SUBSET_NONZERO_PATTERN);
  if (_Ce)
    MatAXPY(J0, w * a1, _Ce, SUBSET_NONZERO_PATTERN);
  if (_partition.prescribed)
  {
    const std::vector<PetscInt>& rows = _partition.prescribed->rows();
    MatZeroRowsColumns(J0, static_cast<PetscInt>(rows.size()), rows.data(), 1.0,
                       nullptr, nullptr);
  }
  MPI_Comm comm;
  PetscObjectGetComm(reinterpret_cast<PetscObject>(_K0), &comm);
  auto solver = std::make_unique<linalg::DirectSolver>(comm, _factorization);
  solver->factorize(J0);
  if (level > 0)
  {
    ++report.initial_factorizations;
    report.seconds_factorization += solver->factor_seconds();
  }
  auto& entry = _initial[level];
  entry.J0 = J0;
  entry.solver = std::move(solver);
  _level = &entry;
  return *entry.solver;
}

void NonlinearNewmark::set_constraint(NewtonConstraint* constraint)
{
  _constraint = constraint;
  _constraint_level = -1;
}

void NonlinearNewmark::set_partition(Partition partition)
{
  if (_scheme.alpha != 0.0 && partition.K_explicit)
    throw std::invalid_argument("the implicit-explicit partition is "
                                "Newmark's average acceleration: HHT alpha "
                                "must be 0 with explicit elements");
  if (!partition.K_implicit)
    throw std::invalid_argument("a partition needs K_implicit");
  _partition = std::move(partition);
  const std::size_t n =
      _partition.prescribed ? _partition.prescribed->rows().size() : 0;
  _start_values.resize(n);
  _end_values.resize(n);
  _values.resize(n);
  // The initial matrices again, with the partition.
  for (auto& [level, entry] : _initial)
  {
    entry.solver.reset();
    MatDestroy(&entry.J0);
  }
  _initial.clear();
  StepReport dummy;
  initial_solver(0, dummy);
}

void NonlinearNewmark::set_history(const Kinematics& prev, int n)
{
  VecCopy(prev.u, _u_prev);
  VecCopy(prev.v, _v_prev);
  VecCopy(prev.a, _a_prev);
  _n = n;
}

void NonlinearNewmark::set_prescribed(Vec x,
                                      const std::vector<double>& values) const
{
  const std::vector<PetscInt>& rows = _partition.prescribed->rows();
  PetscInt r0 = 0;
  VecGetOwnershipRange(x, &r0, nullptr);
  double* p = nullptr;
  VecGetArray(x, &p);
  for (std::size_t i = 0; i < rows.size(); ++i)
    p[rows[i] - r0] = values[i];
  VecRestoreArray(x, &p);
}

void NonlinearNewmark::prescribed_values(double theta, double dt)
{
  auto lerp = [theta](const std::vector<double>& start,
                      const std::vector<double>& end, std::vector<double>& x)
  {
    for (std::size_t i = 0; i < x.size(); ++i)
      x[i] = start[i] + theta * (end[i] - start[i]);
  };
  lerp(_start_values.u, _end_values.u, _values.u);
  lerp(_start_values.v, _end_values.v, _values.v);
  lerp(_start_values.a, _end_values.a, _values.a);
  _values.predictors(_scheme.beta(), _scheme.gamma(), dt, _predicted_d,
                     _predicted_v);
}

void NonlinearNewmark::correct_velocity(Vec dv)
{
  VecAXPY(_v, 1.0, dv);
}

void NonlinearNewmark::set_state(Vec u, Vec v, Vec a, Vec f, Vec f_int)
{
  VecCopy(u, _u);
  VecCopy(v, _v);
  VecCopy(a, _a);
  VecCopy(f, _f);
  VecCopy(f_int, _fint);
  VecCopy(u, _u_prev);
  VecCopy(v, _v_prev);
  VecCopy(a, _a_prev);
  _n = 0;
}

StepReport NonlinearNewmark::step(Vec f_next)
{
  StepReport report;
  if (_partition.prescribed)
  {
    // The prescribed motion at n + 1 from steps n and n - 1, from that of
    // step n.
    const std::vector<PetscInt>& rows = _partition.prescribed->rows();
    _partition.prescribed->values(_n + 1, {_u, _v, _a}, prev(), _end_values);
    const auto n = static_cast<PetscInt>(rows.size());
    VecGetValues(_u, n, rows.data(), _start_values.u.data());
    VecGetValues(_v, n, rows.data(), _start_values.v.data());
    VecGetValues(_a, n, rows.data(), _start_values.a.data());
  }
  VecCopy(_u, _u_start);
  VecCopy(_v, _v_start);
  VecCopy(_a, _a_start);
  _elapsed = 0.0;
  advance(_scheme.dt, f_next, 0, report);
  VecCopy(_u_start, _u_prev);
  VecCopy(_v_start, _v_prev);
  VecCopy(_a_start, _a_prev);
  ++_n;
  return report;
}

void NonlinearNewmark::advance(double dt, Vec f_next, int level,
                               StepReport& report)
{
  if (solve_step(dt, f_next, level, report))
    return;
  if (level >= _settings.max_cuts)
  {
    throw StepFailure(
        "time step did not converge after " + std::to_string(level) +
        " halvings (dt = " + std::to_string(dt) + " s, last residual " +
        std::to_string(report.residual) + " of the load)");
  }
  // Two halves, the load interpolated linearly.
  Vec f_mid;
  VecDuplicate(f_next, &f_mid);
  VecAXPBYPCZ(f_mid, 0.5, 0.5, 0.0, _f, f_next);
  ++report.cuts;
  try
  {
    advance(0.5 * dt, f_mid, level + 1, report);
    advance(0.5 * dt, f_next, level + 1, report);
  }
  catch (...)
  {
    VecDestroy(&f_mid);
    throw;
  }
  VecDestroy(&f_mid);
}

bool NonlinearNewmark::solve_step(double dt, Vec f_next, int level,
                                  StepReport& report)
{
  const double beta = _scheme.beta(), gamma = _scheme.gamma();
  const double alpha = _scheme.alpha, w = 1.0 + alpha;
  const double a0 = 1.0 / (beta * dt * dt), a1 = gamma / (beta * dt),
               a2 = 1.0 / (beta * dt), a3 = 0.5 / beta - 1.0;
  const double aM = _damping.a_mass, bK = _damping.b_stiffness;
  const linalg::DirectSolver& J0 = initial_solver(level, report);
  if (_partition.prescribed)
    prescribed_values((_elapsed + dt) / _scheme.dt, dt);
  if (!_J)
    _J = linalg::duplicate_matrix(_K0, MAT_DO_NOT_COPY_VALUES);
  if (_constraint && _constraint_level != level)
  {
    // The constraint condensed on this step length's initial matrix (cut
    // steps: again when the step returns to a full length).
    const auto t0 = Clock::now();
    _constraint->factorize(_level->J0);
    if (_constraint_level >= 0)
    {
      ++report.initial_factorizations;
      report.seconds_factorization += since(t0);
    }
    _constraint_level = level;
  }

  // Constant part of the HHT residual:
  // g = -alpha (C v + f_int) - (1 + alpha) f' + alpha f (C with C_e).
  VecCopy(_v, _tmp);
  VecScale(_tmp, -alpha * aM);
  MatMult(_M, _tmp, _g);
  VecCopy(_v, _tmp);
  VecScale(_tmp, -alpha * bK);
  MatMultAdd(_partition.K_implicit ? _partition.K_implicit : _K0, _tmp, _g, _g);
  if (_Ce)
  {
    VecCopy(_v, _tmp);
    VecScale(_tmp, -alpha);
    MatMultAdd(_Ce, _tmp, _g, _g);
  }
  {
    const PetscScalar c[3] = {-alpha, -w, alpha};
    Vec x[3] = {_fint, f_next, _f};
    VecMAXPY(_g, 3, c, x);
  }
  if (_partition.K_explicit && _partition.b_explicit > 0.0)
  {
    // The explicit elements' damping on the predicted velocity (alpha =
    // 0): + b_E K_E v~, v~ = v + (1 - gamma) dt a.
    VecWAXPY(_tmp, dt * (1.0 - gamma), _a, _v);
    if (_partition.prescribed)
      set_prescribed(_tmp, _predicted_v);
    VecScale(_tmp, _partition.b_explicit);
    MatMultAdd(_partition.K_explicit, _tmp, _g, _g);
  }
  const double reference = std::max(norm(f_next), 1e-300);

  // R(u') = M (a' + w aM v') + (w bK K0 + w C_e) v' + w f_int(u') + g, with
  // a' = a0 (u' - u) - a2 v - a3 a and v' = v + dt ((1 - gamma) a + gamma a').
  auto kinematics = [&](Vec ut)
  {
    VecWAXPY(_at, -1.0, _u, ut);
    VecScale(_at, a0);
    VecAXPY(_at, -a2, _v);
    VecAXPY(_at, -a3, _a);
    VecCopy(_v, _vt);
    VecAXPY(_vt, dt * (1.0 - gamma), _a);
    VecAXPY(_vt, dt * gamma, _at);
    if (_partition.prescribed)
    {
      set_prescribed(_at, _values.a);
      set_prescribed(_vt, _values.v);
    }
  };
  auto residual = [&](Vec ut, Vec R) -> bool
  {
    if (!_system.trial(ut, dt))
      return false;
    _system.internal_force(_fint_t);
    kinematics(ut);
    VecWAXPY(_w1, w * aM, _vt, _at);
    MatMult(_M, _w1, R);
    VecCopy(_vt, _w2);
    VecScale(_w2, w * bK);
    MatMultAdd(_partition.K_implicit ? _partition.K_implicit : _K0, _w2, R, R);
    if (_Ce)
    {
      VecCopy(_vt, _w2);
      VecScale(_w2, w);
      MatMultAdd(_Ce, _w2, R, R);
    }
    VecAXPY(R, w, _fint_t);
    VecAXPY(R, 1.0, _g);
    if (_partition.K_explicit)
    {
      // The explicit elements' force at the predictor: - K_E (u' - d~).
      VecWAXPY(_w2, -1.0, _d_p, ut);
      VecScale(_w2, -1.0);
      MatMultAdd(_partition.K_explicit, _w2, R, R);
    }
    if (_partition.prescribed)
    {
      // R = u' - value at the prescribed rows (identity rows of J).
      const std::vector<PetscInt>& rows = _partition.prescribed->rows();
      std::vector<double> r(rows.size());
      VecGetValues(ut, static_cast<PetscInt>(rows.size()), rows.data(),
                   r.data());
      for (std::size_t i = 0; i < r.size(); ++i)
        r[i] -= _values.u[i];
      set_prescribed(R, r);
    }
    return true;
  };
  // Consistent effective matrix: a0 M + (1 + alpha)(a1 C + K_T)
  // = J0 + w (K_T - K0): a copy of J0 (equal patterns) plus the change of
  // the cells whose tangent is not elastic (Koyna, 17,274 cells: 0.2
  // instead of 2.8 ms per matrix for a full assembly of K_T).
  const Mat J0_level = _level->J0;
  auto jacobian = [&](Mat J)
  {
    MatCopy(J0_level, J, SAME_NONZERO_PATTERN);
    _system.add_tangent_change(J, w);
  };

  // Predictor: Newmark's, u' = d~ = u + dt v + dt^2 (1/2 - beta) a (the
  // new acceleration zero; also the explicit elements' state). Measured
  // against u' = u (viscoplastic arch 16 m P1 and Koyna 2D, on both
  // transmitting boundaries): 9% to 24% fewer Newton iterations, the same
  // solution to the Newton tolerance.
  VecWAXPY(_ut, dt, _v, _u);
  VecAXPY(_ut, (0.5 - beta) * dt * dt, _a);
  if (_partition.K_explicit)
  {
    VecCopy(_ut, _d_p);
    if (_partition.prescribed)
      set_prescribed(_d_p, _predicted_d);
  }
  if (_partition.prescribed)
    set_prescribed(_ut, _values.u);
  if (_settings.extrapolated_predictor && !_constraint &&
      _system.set_extrapolation(true))
  {
    // The IMPL-EX solution of the step: its residual is linear in u' with
    // the initial matrix as Jacobian, so one solve gives it.
    const auto t0 = Clock::now();
    const bool ok = residual(_ut, _r);
    _system.set_extrapolation(false);
    report.seconds_residual += since(t0);
    if (ok)
    {
      const auto t1 = Clock::now();
      J0.solve(_r, _du);
      VecAXPY(_ut, -1.0, _du);
      report.seconds_solve += since(t1);
    }
  }
  if (!newton(residual, jacobian, _system, J0, level, _J, *_tangent_solver,
              reference, _ut, _r, _du, _settings, report, _constraint,
              _level->J0))
  {
    if (_constraint)
      _constraint->reject();
    return false;
  }
  // Accept: newton() returns true right after evaluating the residual at
  // the converged _ut, so _vt, _at, _fint_t and the system's trial state
  // belong to it.
  const bool extrapolated = _system.trial_extrapolated();
  if (!_system.accept())
  {
    if (_constraint)
      _constraint->reject();
    return false;
  }
  if (_constraint)
    _constraint->accept();
  if (extrapolated)
  {
    // The implicit stresses' equilibrium error: the step's solution
    // balances the extrapolated ones exactly (to the solver tolerance).
    _system.extrapolation_change(_tmp);
    double e = 0.0;
    VecNorm(_tmp, NORM_2, &e);
    report.extrapolation_error =
        std::max(report.extrapolation_error, w * e / reference);
  }
  VecCopy(_ut, _u);
  VecCopy(_vt, _v);
  VecCopy(_at, _a);
  VecCopy(_fint_t, _fint);
  VecCopy(f_next, _f);
  _elapsed += dt;
  return true;
}
} // namespace damseis::dynamics
