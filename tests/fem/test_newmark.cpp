// Verification tests of the implicit time integrator
// (damseis/dynamics/newmark.h): LinearNewmark (HHT-alpha, alpha = 0 being
// Newmark average acceleration), RayleighDamping and TimeScheme.
//
// The matrices are tiny and, except in the last test, live on
// PETSC_COMM_SELF: under mpirun every rank runs its own serial copy.
// The 3-DOF modal test is also run on PETSC_COMM_WORLD with a distributed
// layout (MUMPS on 2 ranks).
//
// References used (none of them calls the library):
//  * the exact closed form of the discrete trapezoidal rule for an
//    undamped oscillator: u_n = u0 cos(n theta), v_n = -u0 omega sin(n theta),
//    tan(theta/2) = omega dt/2 (amplitude preserved, period elongated);
//  * exact conservation of 0.5 v'Mv + 0.5 u'Ku by the trapezoidal rule;
//  * the continuous closed-form response of a damped oscillator to
//    F0 sin(W t) from rest (transient + steady state);
//  * the asymptotic spectral radius (1 + alpha)/(1 - alpha) of HHT-alpha;
//  * the exact free vibration of a non-proportionally damped chain, the
//    matrix exponential of its first-order form (Eigen);
//  * modal superposition with an independent scalar HHT-alpha written in
//    the "acceleration" (predictor-corrector) form, with a Jacobi
//    eigensolver for the modes.
#include <damseis/dynamics/newmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>
#include <mpi.h>
#include <petscmat.h>
#include <petscvec.h>
#include <unsupported/Eigen/MatrixFunctions>

namespace
{
using damseis::dynamics::LinearNewmark;
using damseis::dynamics::RayleighDamping;
using damseis::dynamics::TimeScheme;
constexpr double pi = std::numbers::pi;

/// A small dense vector, or an n x n matrix stored row by row.
using Dense = std::vector<double>;

struct OwnedMat
{
  Mat m = nullptr;
  OwnedMat() = default;
  OwnedMat(const OwnedMat&) = delete;
  OwnedMat& operator=(const OwnedMat&) = delete;
  ~OwnedMat() { MatDestroy(&m); }
};

struct OwnedVec
{
  Vec v = nullptr;
  OwnedVec() = default;
  OwnedVec(const OwnedVec&) = delete;
  OwnedVec& operator=(const OwnedVec&) = delete;
  ~OwnedVec() { VecDestroy(&v); }
};

/// An AIJ matrix on `comm` holding the dense n x n matrix `a` (every entry,
/// zeros included, so that M and K share one nonzero pattern).
void make_mat(MPI_Comm comm, const Dense& a, int n, OwnedMat& out)
{
  MatCreate(comm, &out.m);
  MatSetSizes(out.m, PETSC_DECIDE, PETSC_DECIDE, n, n);
  MatSetType(out.m, MATAIJ);
  MatSeqAIJSetPreallocation(out.m, n, nullptr);
  MatMPIAIJSetPreallocation(out.m, n, nullptr, n, nullptr);
  PetscInt r0 = 0, r1 = 0;
  MatGetOwnershipRange(out.m, &r0, &r1);
  std::vector<PetscInt> cols(n);
  for (int j = 0; j < n; ++j)
    cols[j] = j;
  for (PetscInt i = r0; i < r1; ++i)
    MatSetValues(out.m, 1, &i, n, cols.data(), &a[i * n], INSERT_VALUES);
  MatAssemblyBegin(out.m, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(out.m, MAT_FINAL_ASSEMBLY);
}

/// Sets the owned entries of x from the full vector `values`.
void set_values(Vec x, const Dense& values)
{
  PetscInt r0 = 0, r1 = 0;
  VecGetOwnershipRange(x, &r0, &r1);
  PetscScalar* p = nullptr;
  VecGetArray(x, &p);
  for (PetscInt i = r0; i < r1; ++i)
    p[i - r0] = values[i];
  VecRestoreArray(x, &p);
}

/// A vector with the layout of K's columns holding `values`.
void make_vec(Mat K, const Dense& values, OwnedVec& out)
{
  MatCreateVecs(K, &out.v, nullptr);
  set_values(out.v, values);
}

/// The whole of a (possibly distributed) vector, on every rank.
Dense read(Vec x)
{
  PetscInt n = 0;
  VecGetSize(x, &n);
  Dense out(n, 0.0);
  PetscInt r0 = 0, r1 = 0;
  VecGetOwnershipRange(x, &r0, &r1);
  const PetscScalar* p = nullptr;
  VecGetArrayRead(x, &p);
  for (PetscInt i = r0; i < r1; ++i)
    out[i] = p[i - r0];
  VecRestoreArrayRead(x, &p);
  MPI_Comm comm;
  PetscObjectGetComm(reinterpret_cast<PetscObject>(x), &comm);
  MPI_Allreduce(MPI_IN_PLACE, out.data(), static_cast<int>(n), MPI_DOUBLE,
                MPI_SUM, comm);
  return out;
}

/// States (u, v, a) at t = n dt, n = 0..nsteps, as computed by LinearNewmark.
struct History
{
  std::vector<Dense> u, v, a;
};

History simulate(Mat M, Mat K, RayleighDamping damping, TimeScheme scheme,
                 const Dense& u0, const Dense& v0, const Dense& a0,
                 const std::function<Dense(double)>& load, int nsteps)
{
  LinearNewmark nm(M, K, damping, scheme);
  OwnedVec u, v, a, f;
  make_vec(K, u0, u);
  make_vec(K, v0, v);
  make_vec(K, a0, a);
  make_vec(K, load(0.0), f);
  nm.set_state(u.v, v.v, a.v, f.v);
  History h;
  auto record = [&]
  {
    h.u.push_back(read(nm.u()));
    h.v.push_back(read(nm.v()));
    h.a.push_back(read(nm.a()));
  };
  record();
  for (int n = 1; n <= nsteps; ++n)
  {
    set_values(f.v, load(n * scheme.dt));
    nm.step(f.v);
    record();
  }
  return h;
}

Dense zeros(std::size_t n)
{
  return Dense(n, 0.0);
}

/// Independent scalar HHT-alpha step for m a + c v + k u = f, written in
/// the predictor-corrector ("acceleration") form
///   u~ = u + dt v + dt^2 (1/2 - beta) a,  v~ = v + dt (1 - gamma) a,
///   [m + (1+alpha)(gamma dt c + beta dt^2 k)] a' =
///       (1+alpha) f' - alpha f - (1+alpha)(c v~ + k u~) + alpha (c v + k u),
///   u' = u~ + beta dt^2 a',  v' = v~ + gamma dt a'.
struct Sdof
{
  double u, v, a;
};
Sdof hht_scalar_step(Sdof s, double m, double c, double k, double dt,
                     double alpha, double f, double f_next)
{
  const double beta = 0.25 * (1.0 - alpha) * (1.0 - alpha);
  const double gamma = 0.5 - alpha;
  const double ut = s.u + dt * s.v + dt * dt * (0.5 - beta) * s.a;
  const double vt = s.v + dt * (1.0 - gamma) * s.a;
  const double lhs = m + (1.0 + alpha) * (gamma * dt * c + beta * dt * dt * k);
  const double rhs = (1.0 + alpha) * f_next - alpha * f -
                     (1.0 + alpha) * (c * vt + k * ut) +
                     alpha * (c * s.v + k * s.u);
  const double an = rhs / lhs;
  return {ut + beta * dt * dt * an, vt + gamma * dt * an, an};
}

/// Eigenvalues and (column) eigenvectors of a symmetric n x n matrix by
/// cyclic Jacobi rotations.
void jacobi_eigen(Dense A, int n, Dense& evals, Dense& evecs)
{
  evecs.assign(n * n, 0.0);
  for (int i = 0; i < n; ++i)
    evecs[i * n + i] = 1.0;
  for (int sweep = 0; sweep < 100; ++sweep)
  {
    double off = 0.0;
    for (int p = 0; p < n; ++p)
      for (int q = p + 1; q < n; ++q)
        off += A[p * n + q] * A[p * n + q];
    if (off < 1e-30)
      break;
    for (int p = 0; p < n; ++p)
    {
      for (int q = p + 1; q < n; ++q)
      {
        const double apq = A[p * n + q];
        if (apq == 0.0)
          continue;
        const double theta = (A[q * n + q] - A[p * n + p]) / (2.0 * apq);
        const double t = (theta >= 0 ? 1.0 : -1.0) /
                         (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < n; ++k) // A <- A J
        {
          const double akp = A[k * n + p], akq = A[k * n + q];
          A[k * n + p] = c * akp - s * akq;
          A[k * n + q] = s * akp + c * akq;
        }
        for (int k = 0; k < n; ++k) // A <- J^T A
        {
          const double apk = A[p * n + k], aqk = A[q * n + k];
          A[p * n + k] = c * apk - s * aqk;
          A[q * n + k] = s * apk + c * aqk;
        }
        for (int k = 0; k < n; ++k) // V <- V J
        {
          const double vkp = evecs[k * n + p], vkq = evecs[k * n + q];
          evecs[k * n + p] = c * vkp - s * vkq;
          evecs[k * n + q] = s * vkp + c * vkq;
        }
      }
    }
  }
  evals.resize(n);
  for (int i = 0; i < n; ++i)
    evals[i] = A[i * n + i];
}

/// Roots of x^3 + c2 x^2 + c1 x + c0 (Durand-Kerner iteration).
std::array<std::complex<double>, 3> cubic_roots(double c2, double c1, double c0)
{
  using C = std::complex<double>;
  auto p = [&](C x) { return ((x + c2) * x + c1) * x + c0; };
  std::array<C, 3> z = {C(1, 0), C(0.4, 0.9), C(-0.65, 0.72)};
  for (int it = 0; it < 1000; ++it)
  {
    for (int i = 0; i < 3; ++i)
    {
      C d = 1.0;
      for (int j = 0; j < 3; ++j)
        if (j != i)
          d *= z[i] - z[j];
      z[i] -= p(z[i]) / d;
    }
  }
  return z;
}

/// For the recorded test properties (see --gtest_output=xml).
std::string sci(double x)
{
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3e", x);
  return buf;
}

// ---------------------------------------------------------------------------
// 1. SDOF undamped free vibration against the exact discrete solution.
// ---------------------------------------------------------------------------
TEST(NewmarkSdof, UndampedFreeVibrationMatchesDiscreteClosedForm)
{
  const double m = 2.0, k = 50.0, u0 = 0.01;
  const double omega = std::sqrt(k / m), T = 2.0 * pi / omega;
  const double dt = T / 20.0;
  const int nsteps = 1000; // 50 periods
  OwnedMat M, K;
  make_mat(PETSC_COMM_SELF, {m}, 1, M);
  make_mat(PETSC_COMM_SELF, {k}, 1, K);
  const History h = simulate(
      M.m, K.m, {}, {dt, 0.0}, {u0}, {0.0}, {-k * u0 / m},
      [](double) { return zeros(1); }, nsteps);

  // The trapezoidal rule maps (u, v) by a rotation: eigenvalues
  // exp(+-i theta) with tan(theta/2) = omega dt/2. From v0 = 0 and the
  // consistent a0, u1 = u0 (1 - (omega dt/2)^2)/(1 + (omega dt/2)^2)
  // = u0 cos(theta), hence exactly u_n = u0 cos(n theta) and, from
  // u_{n+1} - u_n = dt/2 (v_n + v_{n+1}), v_n = -u0 omega sin(n theta):
  // no amplitude error at all. Tolerance 1e-10 relative: only round-off
  // remains (about 1e-16 per step, amplified ~4/(omega dt) ~ 13 by the
  // a0 (u_{n+1} - u_n) update, over 1000 steps: ~1e-12 at worst).
  const double theta = 2.0 * std::atan(0.5 * omega * dt);
  double max_err_u = 0.0, max_err_v = 0.0, max_err_a = 0.0;
  for (int n = 0; n <= nsteps; ++n)
  {
    max_err_u = std::max(max_err_u,
                         std::abs(h.u[n][0] - u0 * std::cos(n * theta)) / u0);
    max_err_v = std::max(
        max_err_v,
        std::abs(h.v[n][0] + u0 * omega * std::sin(n * theta)) / (u0 * omega));
    max_err_a = std::max(max_err_a, std::abs(h.a[n][0] + k / m * h.u[n][0]) /
                                        (u0 * k / m));
  }
  ::testing::Test::RecordProperty("discrete_err_u", sci(max_err_u));
  ::testing::Test::RecordProperty("discrete_err_v", sci(max_err_v));
  ::testing::Test::RecordProperty("discrete_err_a", sci(max_err_a));
  EXPECT_LT(max_err_u, 1e-10);
  EXPECT_LT(max_err_v, 1e-10);
  EXPECT_LT(max_err_a, 1e-10); // equilibrium holds at every step (alpha = 0)

  // Against the continuous solution u0 cos(omega t): the discrete one is
  // u0 cos(omega_h t), omega_h = theta/dt, so
  //   |u0 cos(omega t) - u0 cos(omega_h t)|
  //       = 2 u0 |sin((omega + omega_h) t/2) sin((omega - omega_h) t/2)|
  //      <= 2 u0 |sin((omega - omega_h) t/2)|,
  // the period-elongation (phase) error; it grows to O(u0) after 50 periods
  // (phase lag ~ 2.6 rad), so the bound is checked step by step (plus the
  // round-off allowance above).
  const double omega_h = theta / dt;
  for (int n = 0; n <= nsteps; ++n)
  {
    const double t = n * dt;
    const double err = std::abs(h.u[n][0] - u0 * std::cos(omega * t));
    const double bound =
        2.0 * u0 * std::abs(std::sin(0.5 * (omega - omega_h) * t));
    ASSERT_LE(err, bound + 1e-10 * u0) << "step " << n;
  }
  // The period, measured from the library's zero crossings (linear
  // interpolation, first and last upward crossings), is the discrete one,
  // T_h = 2 pi dt/theta, and the elongation is Omega^2/12 to leading order
  // (Omega = omega dt; next term -Omega^4/180, i.e. -Omega^2/15 = -0.7 %
  // relative). Interpolation error of a crossing is O(theta^3 dt) and is
  // divided by ~49 periods: 1e-4 relative is safe.
  std::vector<double> up;
  for (int n = 0; n < nsteps; ++n)
  {
    const double a = h.u[n][0], b = h.u[n + 1][0];
    if (a < 0.0 && b >= 0.0)
      up.push_back((n + a / (a - b)) * dt);
  }
  ASSERT_GE(up.size(), 40u);
  const double T_h = (up.back() - up.front()) / (up.size() - 1);
  ::testing::Test::RecordProperty("period_vs_discrete",
                                  sci(T_h / (2.0 * pi * dt / theta) - 1.0));
  ::testing::Test::RecordProperty("elongation", sci(T_h / T - 1.0));
  EXPECT_NEAR(T_h / (2.0 * pi * dt / theta), 1.0, 1e-4);
  const double Omega = omega * dt;
  EXPECT_NEAR((T_h / T - 1.0) / (Omega * Omega / 12.0), 1.0, 0.02);
}

// ---------------------------------------------------------------------------
// 2. Energy conservation (alpha = 0, undamped, no load).
// ---------------------------------------------------------------------------
/// max_n |E_n - E_0|/E_0 with E = 0.5 v'Mv + 0.5 u'Ku (dense M, K).
double energy_drift(const History& h, const Dense& M, const Dense& K, int n)
{
  auto energy = [&](const Dense& u, const Dense& v)
  {
    double e = 0.0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        e += 0.5 * (v[i] * M[i * n + j] * v[j] + u[i] * K[i * n + j] * u[j]);
    return e;
  };
  const double e0 = energy(h.u[0], h.v[0]);
  double drift = 0.0;
  for (std::size_t s = 0; s < h.u.size(); ++s)
    drift = std::max(drift, std::abs(energy(h.u[s], h.v[s]) - e0) / e0);
  return drift;
}

// The trapezoidal rule conserves the energy exactly: with M a_n = -K u_n at
// every step,
//   E_{n+1} - E_n = (v_{n+1}+v_n)'M(v_{n+1}-v_n)/2
//                 + (u_{n+1}+u_n)'K(u_{n+1}-u_n)/2
//                 = dt/4 [(v_{n+1}+v_n)'M(a_n+a_{n+1})
//                         + (u_{n+1}+u_n)'K(v_n+v_{n+1})] = 0.
// Only round-off drifts: 1e-12 relative over 10,000 steps.
TEST(NewmarkEnergy, SdofConservedOverTenThousandSteps)
{
  const double m = 3.0, k = 120.0, u0 = 0.02, v0 = -0.1;
  const double dt = 2.0 * pi / std::sqrt(k / m) / 20.0;
  OwnedMat M, K;
  make_mat(PETSC_COMM_SELF, {m}, 1, M);
  make_mat(PETSC_COMM_SELF, {k}, 1, K);
  const History h = simulate(
      M.m, K.m, {}, {dt, 0.0}, {u0}, {v0}, {-k * u0 / m},
      [](double) { return zeros(1); }, 10000);
  const double drift = energy_drift(h, {m}, {k}, 1);
  ::testing::Test::RecordProperty("sdof_energy_drift", sci(drift));
  EXPECT_LT(drift, 1e-12);
}

TEST(NewmarkEnergy, CoupledTwoDofConservedOverTenThousandSteps)
{
  // Consistent-mass-like coupled M and coupled K, both SPD.
  const Dense m = {2.0, 0.5, 0.5, 1.0};
  const Dense k = {300.0, -100.0, -100.0, 100.0};
  const Dense u0 = {0.01, -0.02}, v0 = {0.05, 0.1};
  // Consistent a0 = -M^{-1} K u0 (Cramer's rule).
  const Dense Ku = {k[0] * u0[0] + k[1] * u0[1], k[2] * u0[0] + k[3] * u0[1]};
  const double det = m[0] * m[3] - m[1] * m[2];
  const Dense a0 = {-(m[3] * Ku[0] - m[1] * Ku[1]) / det,
                    -(-m[2] * Ku[0] + m[0] * Ku[1]) / det};
  OwnedMat M, K;
  make_mat(PETSC_COMM_SELF, m, 2, M);
  make_mat(PETSC_COMM_SELF, k, 2, K);
  // dt = 0.02 s: omega_max dt ~ 0.4, and both modes are excited.
  const History h = simulate(
      M.m, K.m, {}, {0.02, 0.0}, u0, v0, a0, [](double) { return zeros(2); },
      10000);
  const double drift = energy_drift(h, m, k, 2);
  ::testing::Test::RecordProperty("two_dof_energy_drift", sci(drift));
  EXPECT_LT(drift, 1e-12);
}

// ---------------------------------------------------------------------------
// 3./4. Forced damped SDOF: second-order convergence to the exact solution.
// ---------------------------------------------------------------------------
/// m u'' + c u' + k u = F0 sin(W t), u(0) = u'(0) = 0, c = 2 zeta omega m.
/// With r = W/omega, D = (1 - r^2)^2 + (2 zeta r)^2, omega_d =
/// omega sqrt(1 - zeta^2):
///   steady state  u_p = F0/k [(1 - r^2) sin Wt - 2 zeta r cos Wt]/D,
///   transient     u_h = exp(-zeta omega t)(A cos omega_d t + B sin omega_d t),
///   A = -u_p(0) = F0/k 2 zeta r/D,
///   B = (zeta omega A - u_p'(0))/omega_d, u_p'(0) = F0/k (1 - r^2) W/D,
/// and the steady amplitude is X = F0/k / sqrt(D).
struct ForcedSdof
{
  double m = 2.0, T = 0.5, zeta = 0.05, F0 = 3.0, r = 0.5;
  double omega() const { return 2.0 * pi / T; }
  double k() const { return m * omega() * omega(); }
  double W() const { return r * omega(); }
  double D() const
  {
    return (1 - r * r) * (1 - r * r) + (2 * zeta * r) * (2 * zeta * r);
  }
  double X() const { return F0 / k() / std::sqrt(D()); }
  /// Exact (u, v) at t.
  std::array<double, 2> exact(double t) const
  {
    const double w = omega(), wd = w * std::sqrt(1 - zeta * zeta);
    const double s = F0 / k() / D();
    const double A = s * 2 * zeta * r;
    const double B = (zeta * w * A - s * (1 - r * r) * W()) / wd;
    const double e = std::exp(-zeta * w * t);
    const double c = std::cos(wd * t), sn = std::sin(wd * t);
    const double u = s * ((1 - r * r) * std::sin(W() * t) -
                          2 * zeta * r * std::cos(W() * t)) +
                     e * (A * c + B * sn);
    const double v =
        s * ((1 - r * r) * W() * std::cos(W() * t) +
             2 * zeta * r * W() * std::sin(W() * t)) +
        e * (-zeta * w * (A * c + B * sn) + wd * (-A * sn + B * c));
    return {u, v};
  }
};

/// Errors sqrt(e_u^2 + (e_v/omega)^2)/X at t = 10 T for dt = T/20 .. T/160.
/// (The phase-space norm does not vanish at a zero of the displacement
/// error, so the observed order is not spoilt by an unlucky end time.)
std::vector<double> forced_errors(double alpha)
{
  const ForcedSdof p;
  OwnedMat M, K;
  make_mat(PETSC_COMM_SELF, {p.m}, 1, M);
  make_mat(PETSC_COMM_SELF, {p.k()}, 1, K);
  // C = a_mass M = 2 zeta omega m exactly (ratio_at(omega) = zeta).
  const RayleighDamping damping{2.0 * p.zeta * p.omega(), 0.0};
  EXPECT_NEAR(damping.ratio_at(1.0 / p.T), p.zeta, 1e-15);
  std::vector<double> errors;
  for (int per_period : {20, 40, 80, 160})
  {
    const double dt = p.T / per_period;
    const int nsteps = 10 * per_period;
    // From rest with f(0) = 0: a0 = 0.
    const History h = simulate(
        M.m, K.m, damping, {dt, alpha}, {0.0}, {0.0}, {0.0},
        [&](double t) { return Dense{p.F0 * std::sin(p.W() * t)}; }, nsteps);
    const auto ex = p.exact(nsteps * dt);
    const double eu = h.u.back()[0] - ex[0], ev = h.v.back()[0] - ex[1];
    errors.push_back(std::hypot(eu, ev / p.omega()) / p.X());
  }
  return errors;
}

// Observed order log2(e(dt)/e(dt/2)) must be 2 +/- 0.2 for each halving
// (the scheme is second order: at T/20 the pre-asymptotic O(dt^3) part
// shifts it by ~0.04 only), and the error at T/160 below 1e-3 of the steady
// amplitude: the dominant term is the phase error of the transient,
// ~ (omega dt)^2/12 per radian (1.3e-4 at T/160) times omega t e^{-zeta
// omega t} plus the O((W dt)^2) error of the steady state, i.e. ~2e-4.
void check_second_order(double alpha)
{
  const std::vector<double> e = forced_errors(alpha);
  for (std::size_t i = 0; i + 1 < e.size(); ++i)
  {
    const double order = std::log2(e[i] / e[i + 1]);
    ::testing::Test::RecordProperty("order_" + std::to_string(i), sci(order));
    EXPECT_NEAR(order, 2.0, 0.2)
        << "alpha " << alpha << ", dt = T/" << (20 << i) << " -> T/"
        << (40 << i) << ": errors " << e[i] << ", " << e[i + 1];
  }
  EXPECT_LT(e.back(), 1e-3) << "alpha " << alpha;
  ::testing::Test::RecordProperty("error_T160", sci(e.back()));
}

TEST(NewmarkForced, DampedHarmonicLoadConvergesSecondOrder)
{
  check_second_order(0.0);
}

TEST(HHTAlpha, MinusPointOneIsSecondOrder)
{
  check_second_order(-0.1);
}

TEST(HHTAlpha, MinusPointThreeIsSecondOrder)
{
  check_second_order(-0.3);
}

// ---------------------------------------------------------------------------
// 4. HHT-alpha numerical dissipation.
// ---------------------------------------------------------------------------
/// Spectral radius of the one-step amplification matrix of LinearNewmark for
/// an undamped SDOF with omega dt = Omega, measured by stepping each unit
/// state (u, v, a) once with zero load. The eigenvalues are the roots of
/// the characteristic polynomial lambda^3 - I1 lambda^2 + I2 lambda - I3.
double spectral_radius(double Omega, double alpha)
{
  const double dt = 1.0, m = 1.0, k = Omega * Omega;
  OwnedMat M, K;
  make_mat(PETSC_COMM_SELF, {m}, 1, M);
  make_mat(PETSC_COMM_SELF, {k}, 1, K);
  LinearNewmark nm(M.m, K.m, {}, {dt, alpha});
  OwnedVec zero, e1;
  make_vec(K.m, {0.0}, zero);
  make_vec(K.m, {1.0}, e1);
  double A[3][3];
  for (int j = 0; j < 3; ++j)
  {
    nm.set_state(j == 0 ? e1.v : zero.v, j == 1 ? e1.v : zero.v,
                 j == 2 ? e1.v : zero.v, zero.v);
    nm.step(zero.v);
    A[0][j] = read(nm.u())[0];
    A[1][j] = read(nm.v())[0];
    A[2][j] = read(nm.a())[0];
  }
  const double I1 = A[0][0] + A[1][1] + A[2][2];
  const double I2 = A[0][0] * A[1][1] - A[0][1] * A[1][0] + A[0][0] * A[2][2] -
                    A[0][2] * A[2][0] + A[1][1] * A[2][2] - A[1][2] * A[2][1];
  const double I3 = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
                    A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                    A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
  double rho = 0.0;
  for (auto z : cubic_roots(-I1, I2, -I3))
    rho = std::max(rho, std::abs(z));
  return rho;
}

TEST(HHTAlpha, AverageAccelerationIsNotDissipative)
{
  // alpha = 0: |lambda| = 1 for every omega dt (trapezoidal rule is
  // unconditionally stable and non-dissipative). Tolerance: round-off of
  // the 3x3 invariants and the cubic roots, ~1e-12.
  double dev = 0.0;
  for (double Omega : {0.3, 10.0, 1e4})
  {
    const double rho = spectral_radius(Omega, 0.0);
    dev = std::max(dev, std::abs(rho - 1.0));
    EXPECT_NEAR(rho, 1.0, 1e-9) << Omega;
  }
  ::testing::Test::RecordProperty("max_abs_rho_minus_1", sci(dev));
}

TEST(HHTAlpha, DissipatesHighFrequencies)
{
  for (double alpha : {-0.1, -0.3})
  {
    // Low frequency: almost no dissipation (1 - rho = O(Omega^3)).
    const double rho_low = spectral_radius(0.3, alpha);
    EXPECT_LT(rho_low, 1.0);
    EXPECT_GT(rho_low, 0.999);
    // omega dt = 10: the principal roots are damped (0.838 for -0.1,
    // 0.685 for -0.3 by the closed-form characteristic polynomial).
    const double rho10 = spectral_radius(10.0, alpha);
    ::testing::Test::RecordProperty("rho_10_alpha" + std::to_string(alpha),
                                    sci(rho10));
    EXPECT_LT(rho10, 0.9) << alpha;
    // omega dt -> infinity: rho -> (1 + alpha)/(1 - alpha) (0.818...,
    // 0.538...). At omega dt = 1e4 the deviation is O(1/Omega^2) ~ 1e-6,
    // far below the requested 1e-3.
    const double rho_inf = (1.0 + alpha) / (1.0 - alpha);
    const double rho_big = spectral_radius(1e4, alpha);
    ::testing::Test::RecordProperty("rho_1e4_alpha" + std::to_string(alpha),
                                    sci(rho_big));
    EXPECT_NEAR(rho_big, rho_inf, 1e-3) << alpha;
  }
}

TEST(HHTAlpha, StiffModeFreeVibrationDecays)
{
  // Free vibration of a stiff mode (omega dt = 10) from u0, v0 = 0,
  // consistent a0: with alpha = -0.3 the amplitude must drop by at least
  // rho^40 ~ 0.685^40 ~ 3e-7 (we ask 1e-4, leaving room for the transient
  // of the spurious root and the eigenvector conditioning); with alpha = 0
  // it must not decay (|u_n| = u0 |cos(n theta)| peaks near u0).
  const double Omega = 10.0, u0 = 1.0;
  OwnedMat M, K;
  make_mat(PETSC_COMM_SELF, {1.0}, 1, M);
  make_mat(PETSC_COMM_SELF, {Omega * Omega}, 1, K);
  for (double alpha : {0.0, -0.3})
  {
    const History h = simulate(
        M.m, K.m, {}, {1.0, alpha}, {u0}, {0.0}, {-Omega * Omega * u0},
        [](double) { return zeros(1); }, 60);
    double early = 0.0, late = 0.0;
    for (int n = 0; n <= 10; ++n)
      early = std::max(early, std::abs(h.u[n][0]));
    for (int n = 50; n <= 60; ++n)
      late = std::max(late, std::abs(h.u[n][0]));
    ::testing::Test::RecordProperty("late_over_early" + std::to_string(alpha),
                                    sci(late / early));
    if (alpha == 0.0)
      EXPECT_GT(late, 0.9 * early);
    else
      EXPECT_LT(late, 1e-4 * early);
  }
}

// ---------------------------------------------------------------------------
// 5. Rayleigh damping and argument checks.
// ---------------------------------------------------------------------------
TEST(RayleighDamping, FromRatioIsExactAtBothFrequenciesAndLowerBetween)
{
  const double zeta = 0.05;
  for (auto [f1, f2] :
       {std::array<double, 2>{1.0, 10.0}, {10.0, 1.0}, {2.3, 2.4}, {0.1, 50.0}})
  {
    const RayleighDamping d = RayleighDamping::from_ratio(zeta, f1, f2);
    // zeta(f) = (a/w + b w)/2 is exactly zeta at f1, f2 (round-off only).
    EXPECT_NEAR(d.ratio_at(f1), zeta, 1e-15);
    EXPECT_NEAR(d.ratio_at(f2), zeta, 1e-15);
    EXPECT_GT(d.a_mass, 0.0);
    EXPECT_GT(d.b_stiffness, 0.0);
    const double lo = std::min(f1, f2), hi = std::max(f1, f2);
    for (int i = 1; i < 20; ++i)
    {
      const double f = lo + (hi - lo) * i / 20.0;
      EXPECT_LT(d.ratio_at(f), zeta) << f;
    }
    // Minimum at sqrt(f1 f2): 2 sqrt(w1 w2)/(w1 + w2) zeta.
    EXPECT_NEAR(d.ratio_at(std::sqrt(f1 * f2)),
                2.0 * std::sqrt(f1 * f2) / (f1 + f2) * zeta, 1e-15);
    // Outside [f1, f2] it is larger.
    EXPECT_GT(d.ratio_at(0.5 * lo), zeta);
    EXPECT_GT(d.ratio_at(2.0 * hi), zeta);
  }
  // Mass-only and stiffness-only damping.
  EXPECT_NEAR((RayleighDamping{2.0 * 0.05 * 2.0 * pi * 3.0, 0.0}.ratio_at(3.0)),
              0.05, 1e-15);
  EXPECT_NEAR(
      (RayleighDamping{0.0, 2.0 * 0.05 / (2.0 * pi * 3.0)}.ratio_at(3.0)), 0.05,
      1e-15);
}

TEST(RayleighDamping, FromRatioRejectsBadFrequencies)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(RayleighDamping::from_ratio(0.05, 2.0, 2.0),
               std::invalid_argument);
  EXPECT_THROW(RayleighDamping::from_ratio(0.05, 0.0, 2.0),
               std::invalid_argument);
  EXPECT_THROW(RayleighDamping::from_ratio(0.05, 2.0, 0.0),
               std::invalid_argument);
  EXPECT_THROW(RayleighDamping::from_ratio(0.05, -1.0, 2.0),
               std::invalid_argument);
  EXPECT_THROW(RayleighDamping::from_ratio(0.05, 2.0, -1.0),
               std::invalid_argument);
  EXPECT_THROW(RayleighDamping::from_ratio(0.05, nan, 2.0),
               std::invalid_argument);
}

TEST(NewmarkValidation, RejectsBadTimeStepAndAlpha)
{
  OwnedMat M, K;
  make_mat(PETSC_COMM_SELF, {1.0}, 1, M);
  make_mat(PETSC_COMM_SELF, {4.0}, 1, K);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double dt : {0.0, -1e-3, nan})
  {
    EXPECT_THROW(LinearNewmark(M.m, K.m, {}, {dt, 0.0}), std::invalid_argument)
        << dt;
  }
  for (double alpha : {0.01, -0.34, -0.5, -1.0})
  {
    EXPECT_THROW(LinearNewmark(M.m, K.m, {}, {0.01, alpha}),
                 std::invalid_argument)
        << alpha;
  }
  for (double alpha : {0.0, -0.1, -1.0 / 3.0})
  {
    EXPECT_NO_THROW(LinearNewmark(M.m, K.m, {}, {0.01, alpha})) << alpha;
  }
  // TimeScheme's HHT parameters.
  const TimeScheme s{0.01, -0.3};
  EXPECT_NEAR(s.beta(), 0.25 * 1.3 * 1.3, 1e-15);
  EXPECT_NEAR(s.gamma(), 0.8, 1e-15);
}

TEST(NewmarkValidation, RejectsNanAlpha)
{
  // A NaN alpha is not in [-1/3, 0] either, but LinearNewmark's check
  //   if (scheme.alpha < -1.0 / 3.0 - 1e-14 || scheme.alpha > 0.0)
  // is false for NaN (unlike the dt check, written !(dt > 0.0)): the
  // constructor factorises a NaN effective matrix without complaint and
  // every step then returns NaN. Known library bug: this test fails until
  // the check is written as !(alpha >= -1/3 - 1e-14 && alpha <= 0).
  OwnedMat M, K;
  make_mat(PETSC_COMM_SELF, {1.0}, 1, M);
  make_mat(PETSC_COMM_SELF, {4.0}, 1, K);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(LinearNewmark(M.m, K.m, {}, {0.01, nan}), std::invalid_argument);
}

// ---------------------------------------------------------------------------
// 6. 3-DOF shear chain under a base-acceleration pulse vs modal
//    superposition.
// ---------------------------------------------------------------------------
/// Masses m_i and storey springs k_i (k_1 to the fixed base), load
/// f = -M r a_g(t), r = (1, 1, 1), a_g a one-cycle sine pulse. Rayleigh
/// damping 5 % at the first and third natural frequencies.
///
/// Reference: with Rayleigh damping, C = a M + b K is diagonalised by the
/// M-orthonormal modes phi_i (K phi = omega^2 M phi), and the HHT-alpha
/// recurrence is linear with matrix coefficients that are polynomials in
/// M, C, K; so the discrete solution is exactly the superposition of the
/// discrete modal solutions q_i with the same dt and scheme:
///   q_i'' + (a + b omega_i^2) q_i' + omega_i^2 q_i = -Gamma_i a_g(t),
///   Gamma_i = phi_i' M r, u = sum phi_i q_i.
/// Each q_i is integrated with the independent scalar HHT step above; the
/// agreement is limited by round-off (~1e-13), far below the 1e-6 asked.
void check_modal_chain(MPI_Comm comm, double alpha)
{
  const int n = 3;
  const Dense masses = {2.0e5, 1.5e5, 1.0e5};  // [kg]
  const Dense springs = {3.0e8, 2.0e8, 1.0e8}; // [N/m]
  Dense m(n * n, 0.0), k(n * n, 0.0);
  for (int i = 0; i < n; ++i)
  {
    m[i * n + i] = masses[i];
    k[i * n + i] += springs[i];
    if (i + 1 < n)
    {
      k[i * n + i] += springs[i + 1];
      k[i * n + i + 1] = -springs[i + 1];
      k[(i + 1) * n + i] = -springs[i + 1];
    }
  }
  // Modes: A = M^{-1/2} K M^{-1/2} = Y diag(omega^2) Y', phi = M^{-1/2} Y.
  Dense A(n * n), w2, Y;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      A[i * n + j] = k[i * n + j] / std::sqrt(masses[i] * masses[j]);
  jacobi_eigen(A, n, w2, Y);
  std::vector<int> order = {0, 1, 2};
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return w2[a] < w2[b]; });
  Dense omega(n), phi(n * n), gamma(n); // phi column i = mode i
  for (int i = 0; i < n; ++i)
  {
    omega[i] = std::sqrt(w2[order[i]]);
    gamma[i] = 0.0;
    for (int r = 0; r < n; ++r)
    {
      phi[r * n + i] = Y[r * n + order[i]] / std::sqrt(masses[r]);
      gamma[i] += phi[r * n + i] * masses[r];
    }
  }
  const RayleighDamping damping = RayleighDamping::from_ratio(
      0.05, omega[0] / (2 * pi), omega[2] / (2 * pi));

  const double T1 = 2 * pi / omega[0];
  const double dt = T1 / 50.0, t_pulse = 0.5 * T1, ag_max = 0.3 * 9.81;
  const int nsteps = 200; // 4 T1: pulse, then damped free vibration
  auto ag = [&](double t)
  { return t <= t_pulse ? ag_max * std::sin(2 * pi * t / t_pulse) : 0.0; };

  OwnedMat M, K;
  make_mat(comm, m, n, M);
  make_mat(comm, k, n, K);
  const History h = simulate(
      M.m, K.m, damping, {dt, alpha}, zeros(n), zeros(n), zeros(n),
      [&](double t)
      {
        Dense f(n);
        for (int i = 0; i < n; ++i)
          f[i] = -masses[i] * ag(t);
        return f;
      },
      nsteps);

  // Modal reference with the same dt and scheme.
  std::vector<Sdof> q(n, Sdof{0.0, 0.0, 0.0});
  double max_ref = 0.0, max_err_u = 0.0, max_err_v = 0.0, max_ref_v = 0.0;
  for (int s = 1; s <= nsteps; ++s)
  {
    for (int i = 0; i < n; ++i)
    {
      const double c =
          damping.a_mass + damping.b_stiffness * omega[i] * omega[i];
      q[i] =
          hht_scalar_step(q[i], 1.0, c, omega[i] * omega[i], dt, alpha,
                          -gamma[i] * ag((s - 1) * dt), -gamma[i] * ag(s * dt));
    }
    for (int r = 0; r < n; ++r)
    {
      double u = 0.0, v = 0.0;
      for (int i = 0; i < n; ++i)
      {
        u += phi[r * n + i] * q[i].u;
        v += phi[r * n + i] * q[i].v;
      }
      max_ref = std::max(max_ref, std::abs(u));
      max_ref_v = std::max(max_ref_v, std::abs(v));
      max_err_u = std::max(max_err_u, std::abs(h.u[s][r] - u));
      max_err_v = std::max(max_err_v, std::abs(h.v[s][r] - v));
    }
  }
  ASSERT_GT(max_ref, 0.0);
  const std::string tag = "_alpha" + std::to_string(alpha);
  ::testing::Test::RecordProperty("modal_rel_err_u" + tag,
                                  sci(max_err_u / max_ref));
  EXPECT_LT(max_err_u / max_ref, 1e-6) << "alpha " << alpha;
  ::testing::Test::RecordProperty("modal_rel_err_v" + tag,
                                  sci(max_err_v / max_ref_v));
  EXPECT_LT(max_err_v / max_ref_v, 1e-6) << "alpha " << alpha;
}

namespace
{
/// Free vibration of the 3-DOF chain (M = I, K tridiagonal) with a dashpot
/// c at its free end given as an extra damping matrix (non-proportional),
/// from u0 = (0, 0, 1), v0 = 0, over 10 s; returns max_t |u - u_exact|
/// with u_exact from exp(A t) of the first-order form
/// A = [0 I; -K -C] (Eigen's Pade scaling and squaring).
double dashpot_chain_error(double dt, double alpha)
{
  const int n = 3;
  const double c = 0.8;
  const Dense m = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const Dense k = {2, -1, 0, -1, 2, -1, 0, -1, 1};
  const Dense cd = {0, 0, 0, 0, 0, 0, 0, 0, c};
  OwnedMat M, K, C;
  make_mat(PETSC_COMM_SELF, m, n, M);
  make_mat(PETSC_COMM_SELF, k, n, K);
  make_mat(PETSC_COMM_SELF, cd, n, C);
  LinearNewmark nm(M.m, K.m, {}, {dt, alpha},
                   damseis::linalg::Factorization::automatic, {C.m});
  OwnedVec u, v, a, f;
  make_vec(K.m, {0, 0, 1}, u);
  make_vec(K.m, {0, 0, 0}, v);
  make_vec(K.m, {0, 1, -1}, a); // a0 = -K u0 - C v0
  make_vec(K.m, {0, 0, 0}, f);
  nm.set_state(u.v, v.v, a.v, f.v);

  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  for (int i = 0; i < n; ++i)
  {
    A(i, n + i) = 1.0;
    for (int j = 0; j < n; ++j)
    {
      A(n + i, j) = -k[i * n + j];
      A(n + i, n + j) = -cd[i * n + j];
    }
  }
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(2 * n);
  x0(2) = 1.0;
  const Eigen::MatrixXd step = (A * dt).exp();
  Eigen::VectorXd x = x0;
  const int steps = static_cast<int>(std::lround(10.0 / dt));
  double error = 0.0;
  for (int s = 0; s < steps; ++s)
  {
    nm.step(f.v);
    x = step * x;
    const Dense un = read(nm.u());
    for (int i = 0; i < n; ++i)
      error = std::max(error, std::abs(un[i] - x(i)));
  }
  return error;
}
} // namespace

// Extra damping matrices (boundary dashpots) beside Rayleigh damping: a
// dashpot at the end of the chain damps it non-proportionally, so no modal
// reference applies; the exact free vibration is exp(A t) x0. Newmark
// average acceleration and HHT-alpha are second order: the error at
// dt = 0.01 s is below 1e-3 of u0 (the period error (w dt)^2 / 12 with
// w <= 2 rad/s accumulates to about 1e-4 over 10 s), and halving dt
// divides it by 4 (asserted 3.5 to 4.5).
TEST(NewmarkExtraDamping, DashpotChainMatchesMatrixExponential)
{
  for (double alpha : {0.0, -0.1})
  {
    const double e1 = dashpot_chain_error(0.01, alpha);
    const double e2 = dashpot_chain_error(0.005, alpha);
    ::testing::Test::RecordProperty("dashpot_error_dt001_alpha" +
                                        std::to_string(alpha),
                                    std::to_string(e1));
    EXPECT_LT(e1, 1e-3) << "alpha " << alpha;
    EXPECT_GT(e1 / e2, 3.5) << "alpha " << alpha;
    EXPECT_LT(e1 / e2, 4.5) << "alpha " << alpha;
  }
}

namespace
{
/// A chain of `nodes` 3D nodes in block (BAIJ, bs 3) storage: masses m I,
/// springs k I between neighbours (the first node held by one more), and
/// dashpots c I at every other node alone: a boundary operator's pattern,
/// half of its block rows empty.
struct BlockChain
{
  OwnedMat M, K, C;
  BlockChain(int nodes, double m, double k, double c)
  {
    for (OwnedMat* A : {&M, &K, &C})
      MatCreateBAIJ(PETSC_COMM_SELF, 3, 3 * nodes, 3 * nodes, 3 * nodes,
                    3 * nodes, 3, nullptr, 0, nullptr, &A->m);
    auto block = [](double x)
    {
      std::array<double, 9> b{};
      b[0] = b[4] = b[8] = x;
      return b;
    };
    for (PetscInt i = 0; i < nodes; ++i)
    {
      MatSetValuesBlocked(M.m, 1, &i, 1, &i, block(m).data(), INSERT_VALUES);
      const double diag = (i == 0 || i + 1 < nodes) ? 2.0 * k : k;
      MatSetValuesBlocked(K.m, 1, &i, 1, &i, block(diag).data(), INSERT_VALUES);
      for (PetscInt j : {i - 1, i + 1})
        if (j >= 0 && j < nodes)
          MatSetValuesBlocked(K.m, 1, &i, 1, &j, block(-k).data(),
                              INSERT_VALUES);
      if (i % 2 == 1)
        MatSetValuesBlocked(C.m, 1, &i, 1, &i, block(c).data(), INSERT_VALUES);
    }
    for (OwnedMat* A : {&M, &K, &C})
    {
      MatAssemblyBegin(A->m, MAT_FINAL_ASSEMBLY);
      MatAssemblyEnd(A->m, MAT_FINAL_ASSEMBLY);
    }
  }
};

double quadratic(Mat A, Vec x, Vec work)
{
  MatMult(A, x, work);
  double q = 0.0;
  VecDot(x, work, &q);
  return q;
}
} // namespace

// A boundary dashpot in block storage with empty block rows (the 3D
// viscous-spring boundary's pattern): with average acceleration the
// discrete energy obeys
//   E_(n+1) - E_n = -dt/4 (v_n + v_(n+1))' C (v_n + v_(n+1))
// exactly (the trapezoidal rule; E = v'Mv/2 + u'Ku/2), here checked with
// products of the original matrices, not the integrator's images: every
// step to 1e-12 of the initial energy (round-off; measured 1.1e-15). With
// C copied by plain MatDuplicate, PETSc's generic BAIJ product leaves the
// copy's empty rows unset, the image of C u carries M u there, and the
// chain's energy grows 4e166-fold over the 2000 steps (measured).
TEST(NewmarkExtraDamping, BlockDashpotWithEmptyRowsKeepsTheEnergyIdentity)
{
  const int nodes = 40;
  const BlockChain chain(nodes, 2.0, 500.0, 3.0);
  const double dt = 0.01;
  LinearNewmark nm(chain.M.m, chain.K.m, {}, {dt, 0.0},
                   damseis::linalg::Factorization::automatic, {chain.C.m});
  OwnedVec u, v, a, f, w, work, v_old;
  Dense u0(3 * nodes), v0(3 * nodes, 0.0);
  for (int i = 0; i < 3 * nodes; ++i)
    u0[i] = std::sin(0.37 * i) * 1e-2;
  make_vec(chain.K.m, u0, u);
  make_vec(chain.K.m, v0, v);
  make_vec(chain.K.m, v0, f);
  make_vec(chain.K.m, v0, w);
  make_vec(chain.K.m, v0, work);
  make_vec(chain.K.m, v0, v_old);
  // a0 = -M^-1 K u0 (M = 2 I).
  make_vec(chain.K.m, v0, a);
  MatMult(chain.K.m, u.v, a.v);
  VecScale(a.v, -0.5);
  nm.set_state(u.v, v.v, a.v, f.v);
  auto energy = [&]()
  {
    return 0.5 * quadratic(chain.M.m, nm.v(), work.v) +
           0.5 * quadratic(chain.K.m, nm.u(), work.v);
  };
  const double e0 = energy();
  double e = e0, worst = 0.0;
  for (int step = 0; step < 2000; ++step)
  {
    VecCopy(nm.v(), v_old.v);
    nm.step(f.v);
    VecWAXPY(w.v, 1.0, v_old.v, nm.v());
    const double dissipated = dt / 4.0 * quadratic(chain.C.m, w.v, work.v);
    const double e_new = energy();
    worst = std::max(worst, std::abs(e_new - e + dissipated) / e0);
    e = e_new;
  }
  ::testing::Test::RecordProperty("block_dashpot_energy_identity", sci(worst));
  EXPECT_LT(worst, 1e-12);
  EXPECT_LT(e, 0.5 * e0); // the dashpots took energy out
}

// The extra damping enters exactly like Rayleigh damping: C_e = a M + b K
// given as an extra matrix reproduces RayleighDamping{a, b} to round-off:
// each step recovers K u' from the solved equation, (rhs - c_M M u') / c_K
// with c_M / c_K about 8e3 here, a cancellation that loses about 1e-12 per
// step; 1e-10 of the unit amplitude over 2000 steps is asserted (measured
// 1.1e-11).
TEST(NewmarkExtraDamping, RayleighAsExtraMatrixIsRayleigh)
{
  const int n = 3;
  const double am = 0.3, bk = 0.02;
  const Dense m = {1, 0, 0, 0, 2, 0, 0, 0, 1};
  const Dense k = {2, -1, 0, -1, 2, -1, 0, -1, 1};
  Dense cd(9);
  for (int i = 0; i < 9; ++i)
    cd[i] = am * m[i] + bk * k[i];
  OwnedMat M, K, C;
  make_mat(PETSC_COMM_SELF, m, n, M);
  make_mat(PETSC_COMM_SELF, k, n, K);
  make_mat(PETSC_COMM_SELF, cd, n, C);
  LinearNewmark rayleigh(M.m, K.m, {am, bk}, {0.01, -0.05});
  LinearNewmark extra(M.m, K.m, {}, {0.01, -0.05},
                      damseis::linalg::Factorization::automatic, {C.m});
  OwnedVec u, v, a, f;
  make_vec(K.m, {0.5, -0.2, 1}, u);
  make_vec(K.m, {0, 0.3, 0}, v);
  make_vec(K.m, {0, 0, 0}, a);
  make_vec(K.m, {0, 0, 0}, f);
  for (LinearNewmark* nm : {&rayleigh, &extra})
    nm->set_state(u.v, v.v, a.v, f.v);
  double diff = 0.0;
  for (int s = 0; s < 2000; ++s)
  {
    set_values(f.v, {std::sin(0.01 * s), 0, 0});
    rayleigh.step(f.v);
    extra.step(f.v);
    const Dense x = read(rayleigh.u()), y = read(extra.u());
    for (int i = 0; i < n; ++i)
      diff = std::max(diff, std::abs(x[i] - y[i]));
  }
  EXPECT_LT(diff, 1e-10);
}

TEST(NewmarkModal, ThreeDofChainMatchesModalSuperposition)
{
  for (double alpha : {0.0, -0.2})
    check_modal_chain(PETSC_COMM_SELF, alpha);
}

TEST(NewmarkModal, ThreeDofChainDistributedMatchesModalSuperposition)
{
  // Same on PETSC_COMM_WORLD: rows split over the ranks (auto on 2 ranks:
  // the redundant factorisation, below 10^5 unknowns; the arch MPI tests
  // cover MUMPS).
  int size = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  {
    OwnedMat M, K;
    make_mat(PETSC_COMM_WORLD, {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0}, 3,
             M);
    make_mat(PETSC_COMM_WORLD,
             {2.0, -1.0, 0.0, -1.0, 2.0, -1.0, 0.0, -1.0, 1.0}, 3, K);
    LinearNewmark nm(M.m, K.m, {}, {0.01, 0.0});
    EXPECT_EQ(nm.solver_name(),
              size == 1 ? "petsc-cholesky-nd" : "redundant-petsc-lu-nd");
  }
  for (double alpha : {0.0, -0.2})
    check_modal_chain(PETSC_COMM_WORLD, alpha);
}
} // namespace
