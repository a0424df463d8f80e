#include "damseis/material/concrete.h"

#include <Eigen/Dense>
#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace damseis::material
{

namespace
{
const double c23 = std::sqrt(2.0 / 3.0);

/// Principal stresses (descending) from the invariants: cheap, used only to
/// decide whether the trial state is elastic.
std::array<double, 3> principal_fast(const Vector6& s)
{
  const double I1 = s[0] + s[1] + s[2], m = I1 / 3.0;
  const double d0 = s[0] - m, d1 = s[1] - m, d2 = s[2] - m;
  const double J2 = 0.5 * (d0 * d0 + d1 * d1 + d2 * d2) + s[3] * s[3] +
                    s[4] * s[4] + s[5] * s[5];
  if (J2 <= 1e-300)
    return {m, m, m};
  const double J3 = d0 * (d1 * d2 - s[4] * s[4]) -
                    s[3] * (s[3] * d2 - s[4] * s[5]) +
                    s[5] * (s[3] * s[4] - d1 * s[5]);
  const double c3 =
      std::clamp(1.5 * std::sqrt(3.0) * J3 / (J2 * std::sqrt(J2)), -1.0, 1.0);
  const double th = std::acos(c3) / 3.0;
  const double r = 2.0 / std::sqrt(3.0) * std::sqrt(J2);
  constexpr double tpi3 = 2.0 * std::numbers::pi / 3.0;
  return {m + r * std::cos(th), m + r * std::cos(th - tpi3),
          m + r * std::cos(th + tpi3)};
}

/// Small dense LU with partial pivoting (N <= 9), in place.
template <int N>
bool lu_factor(std::array<double, N * N>& a, std::array<int, N>& piv)
{
  for (int k = 0; k < N; ++k)
  {
    int p = k;
    double best = std::abs(a[k * N + k]);
    for (int i = k + 1; i < N; ++i)
      if (std::abs(a[i * N + k]) > best)
      {
        best = std::abs(a[i * N + k]);
        p = i;
      }
    if (!(best > 0.0) || !std::isfinite(best))
      return false;
    piv[k] = p;
    if (p != k)
      for (int j = 0; j < N; ++j)
        std::swap(a[k * N + j], a[p * N + j]);
    const double inv = 1.0 / a[k * N + k];
    for (int i = k + 1; i < N; ++i)
    {
      const double l = a[i * N + k] * inv;
      a[i * N + k] = l;
      if (l != 0.0)
        for (int j = k + 1; j < N; ++j)
          a[i * N + j] -= l * a[k * N + j];
    }
  }
  return true;
}
template <int N>
void lu_solve(const std::array<double, N * N>& a, const std::array<int, N>& piv,
              std::array<double, N>& b)
{
  for (int k = 0; k < N; ++k)
    std::swap(b[k], b[piv[k]]);
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < i; ++j)
      b[i] -= a[i * N + j] * b[j];
  for (int i = N - 1; i >= 0; --i)
  {
    for (int j = i + 1; j < N; ++j)
      b[i] -= a[i * N + j] * b[j];
    b[i] /= a[i * N + i];
  }
}

/// Valid active sets: edge needs the HTC surface; R2 needs R1, R3 needs R2;
/// {HTC, edge, R1, R2} is excluded (its constraints are dependent:
/// sigma1 = sigma2 follows from either pair).
bool valid_set(unsigned s)
{
  if (s == 0 || s >= 32)
    return false;
  if ((s & htc_edge) && !(s & htc_surface))
    return false;
  if ((s & rankine_2) && !(s & rankine_1))
    return false;
  if ((s & rankine_3) && !(s & rankine_2))
    return false;
  if ((s & htc_edge) && (s & rankine_2))
    return false;
  return true;
}

/// Completes a set so that it is valid where possible.
unsigned close_set(unsigned s)
{
  if (s & htc_edge)
    s |= htc_surface;
  if (s & rankine_3)
    s |= rankine_2;
  if (s & rankine_2)
    s |= rankine_1;
  return s;
}

Vector6 outer_vec(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  // symmetric part of a b^T, stress-like Voigt
  return {a[0] * b[0],
          a[1] * b[1],
          a[2] * b[2],
          0.5 * (a[0] * b[1] + a[1] * b[0]),
          0.5 * (a[1] * b[2] + a[2] * b[1]),
          0.5 * (a[0] * b[2] + a[2] * b[0])};
}
} // namespace

std::string active_set_name(unsigned a)
{
  if (a == 0)
    return "elastic";
  std::string s;
  const char* names[5] = {"HTC", "edge", "R1", "R2", "R3"};
  for (int i = 0; i < 5; ++i)
    if (a & (1u << i))
      s += (s.empty() ? "" : "+") + std::string(names[i]);
  return s;
}

HtcConcrete::HtcConcrete(const ConcreteParameters& p) : p_(p)
{
  auto require = [](bool ok, const char* what)
  {
    if (!ok)
      throw std::invalid_argument(std::string("HtcConcrete: ") + what);
  };
  require(p.E > 0, "E must be > 0");
  require(p.nu > -1 && p.nu < 0.5, "nu must be in (-1, 0.5)");
  require(p.fc0 > 0 && p.ft0 > 0 && p.ft0 < p.fc0, "need 0 < ft0 < fc0");
  require(p.fbc_ratio > 1.0, "fbc_ratio must be > 1");
  require(p.xi0 > 0 && p.rho0 > 0, "triaxial point must have xi0, rho0 > 0");
  require(p.Gf > 0 && p.Gc > 0, "fracture energies must be > 0");
  require(p.element_size > 0, "element_size must be > 0");
  require(p.htc_tension_offset >= 0, "htc_tension_offset must be >= 0");
  require(p.rho_min > 0 && p.rho_min < p.rho_max, "need 0 < rho_min < rho_max");
  require(p.compressive_floor > 0 && p.compressive_floor < 1,
          "compressive_floor must be in (0, 1)");
  require(p.snap_back_safety > 1.0, "snap_back_safety must be > 1");
  require(p.eta_c >= 0 && p.eta_t >= 0, "viscosities must be >= 0");
  require(p.rate_shift_c > 0 && p.rate_shift_t > 0, "rate shifts must be > 0");
  require(p.dynamic_factor > 0, "dynamic_factor must be > 0");
  require(p.tolerance > 0 && p.max_iterations > 0, "bad Newton settings");

  const double fac = p.dynamic_30_percent ? p.dynamic_factor : 1.0;
  d_.E = fac * p.E;
  d_.nu = p.nu;
  d_.G = d_.E / (2.0 * (1.0 + p.nu));
  d_.lambda = d_.E * p.nu / ((1.0 + p.nu) * (1.0 - 2.0 * p.nu));
  d_.K = d_.E / (3.0 * (1.0 - 2.0 * p.nu));
  d_.fc0 = fac * p.fc0;
  const double ft0 = fac * p.ft0;

  d_.calibration = p.classic_shape ? classic_calibration()
                                   : HtcCalibration{p.ft0 / p.fc0, p.fbc_ratio,
                                                    p.xi0, p.rho0};
  family_ = HtcFamily(d_.calibration.fbc_ratio, d_.calibration.xi0,
                      d_.calibration.rho0);
  // Convexity over the whole range the guard allows (A, B, C >= 0).
  for (int i = 0; i <= 20; ++i)
  {
    const double rho = p.rho_min + (p.rho_max - p.rho_min) * i / 20.0;
    const auto k = family_.at(rho);
    require(k.A >= 0 && k.B >= 0 && k.C >= 0,
            "HTC surface not convex for ft/fc in [rho_min, rho_max]; "
            "narrow the range");
  }

  // Tension: exponential softening Ht = exp(-kappa_t / kappa_tu); in
  // uniaxial tension dkappa_t = sqrt(2/3) deps_p, so the dissipated energy
  // per unit volume is sqrt(3/2) ft0 kappa_tu = Gf / h. The softening
  // modulus at the peak is ft0^2 h / Gf; it must stay below E (no snap-back
  // of the uniaxial stress-strain curve, i.e. h < l_ch = E Gf / ft0^2 for
  // exponential softening; 2 l_ch is the linear-softening limit). If not,
  // ft0 is lowered so that the modulus is E / snap_back_safety: the energy
  // is still Gf / h (algorithms.md 1.3 remedy).
  const double h = p.element_size;
  d_.l_ch = d_.E * p.Gf / (ft0 * ft0);
  d_.ft0 = ft0;
  d_.tension_strength_reduced = false;
  if (ft0 * ft0 * h / p.Gf > d_.E / p.snap_back_safety)
  {
    d_.ft0 = std::sqrt(d_.E * p.Gf / (p.snap_back_safety * h));
    d_.tension_strength_reduced = true;
  }
  d_.kappa_tu = c23 * p.Gf / (h * d_.ft0);

  // Compression: Hc = max(exp(-kappa_c / kappa_cs), floor). In uniaxial
  // compression the flow sits on the compressive-meridian edge (symmetric
  // multipliers); dissipation per unit kappa_c is fc k_c(rho), with k_c from
  // the HTC gradient. kappa_cs is set so that the energy dissipated down to
  // the floor is Gc / h (quadrature over the softening, rho changing with
  // fc). Snap-back: the softening modulus fc0 / (kappa_cs k_c) is limited
  // to E / snap_back_safety by raising kappa_cs (strength kept: for large
  // elements the compressive energy exceeds Gc / h; documented).
  auto rho_of = [&](double fc)
  {
    return std::clamp((1.0 + p.htc_tension_offset) * d_.ft0 / fc,
                      p.rho_min * 1.0, p.rho_max);
  };
  auto k_c = [&](double rho)
  {
    const auto k = family_.at(rho);
    const double dev[3] = {1.0 / 3.0, 1.0 / 3.0, -2.0 / 3.0};
    const double q = 1.0 / std::sqrt(3.0);
    double n[3], nn = 0;
    for (int i = 0; i < 3; ++i)
    {
      n[i] = k.A * dev[i] + k.B * dev[i] / (2.0 * q) + k.D +
             (i < 2 ? 0.5 * k.C : 0.0);
      nn += n[i] * n[i];
    }
    return std::abs(n[2]) / (c23 * std::sqrt(nn));
  };
  d_.uniaxial_compression_dissipation = k_c(rho_of(d_.fc0));
  {
    const double uf = -std::log(p.compressive_floor);
    const int n = 400;
    double I = 0;
    for (int i = 0; i <= n; ++i)
    {
      const double u = uf * i / n;
      const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      I += w * std::exp(-u) * k_c(rho_of(d_.fc0 * std::exp(-u)));
    }
    I *= uf / (3.0 * n);
    d_.kappa_cs = p.Gc / (h * d_.fc0 * I);
  }
  const double kcs_min = p.snap_back_safety * d_.fc0 /
                         (d_.E * d_.uniaxial_compression_dissipation);
  d_.compression_energy_raised = d_.kappa_cs < kcs_min;
  d_.kappa_cs = std::max(d_.kappa_cs, kcs_min);

  // Rate functions. The CEB-FIP DIF is a function of the total axial strain
  // rate; at the peak of a constant-rate uniaxial test sigma_dot = 0, so the
  // axial viscoplastic rate equals the total one and kappa_dot = rate *
  // sqrt(2/3) (Rankine, tension) or rate / k_c (HTC edge, compression).
  // Hence kdot0 = (CEB reference rate) x that factor; the exponent is the
  // CEB one. Checked by single-point simulations (test_material_rate.cpp).
  if (p.rate_law == RateLaw::ceb_fip)
  {
    d_.rate_c = {RateLaw::ceb_fip, ceb_exponent_compression(p.fc0),
                 p.rate_shift_c * ceb_reference_rate_compression /
                     d_.uniaxial_compression_dissipation,
                 0.0};
    d_.rate_t = {RateLaw::ceb_fip, ceb_exponent_tension(p.fc0),
                 p.rate_shift_t * c23 * ceb_reference_rate_tension, 0.0};
  }
  else if (p.rate_law == RateLaw::linear)
  {
    d_.rate_c = {RateLaw::linear, 0.0, 1.0, p.eta_c};
    d_.rate_t = {RateLaw::linear, 0.0, 1.0, p.eta_t};
  }
  rate_on_ = p.mode == Mode::viscoplastic && p.rate_law != RateLaw::none;
  log_c_ = rate_on_ && d_.rate_c.law == RateLaw::ceb_fip;
  log_t_ = rate_on_ && d_.rate_t.law == RateLaw::ceb_fip;
}

template <class T>
T HtcConcrete::hc(const T& kc) const
{
  using std::exp;
  return vmax(T(exp(-kc / d_.kappa_cs)), T(p_.compressive_floor));
}

template <class T>
void HtcConcrete::surfaces(const std::array<T, 3>& s, const T& kc, const T& kt,
                           const T& kcd, const T& ktd, std::array<T, 5>& phi,
                           std::array<std::array<T, 3>, 5>* n) const
{
  using std::exp;
  using std::sqrt;
  // Rates may be transiently negative inside the Newton iteration; the
  // power law stays smooth for kdot > -kdot0 (always true with the log-rate
  // unknowns), the linear law for any rate.
  const T Rc =
      rate_on_ ? d_.rate_c(vmax(kcd, T(-0.999 * d_.rate_c.kdot0))) : T(1.0);
  const T Rt =
      rate_on_ ? d_.rate_t(vmax(ktd, T(-0.999 * d_.rate_t.kdot0))) : T(1.0);
  const T fc = d_.fc0 * hc(kc) * Rc;
  const T ft = d_.ft0 * exp(-kt / d_.kappa_tu) * Rt;
  const T ftH =
      vmin(vmax(T((1.0 + p_.htc_tension_offset) * ft), T(p_.rho_min * fc)),
           T(p_.rho_max * fc));
  const T ifc = 1.0 / fc;
  const auto X = family_.coefficients(T(ftH * ifc));
  const T I1 = s[0] + s[1] + s[2];
  const T m = I1 / 3.0;
  const std::array<T, 3> dev = {s[0] - m, s[1] - m, s[2] - m};
  const T J2 = 0.5 * (dev[0] * dev[0] + dev[1] * dev[1] + dev[2] * dev[2]);
  const T q = sqrt(J2 + 1e-30 * d_.fc0 * d_.fc0);
  const T common = X[0] * J2 * ifc * ifc + X[1] * q * ifc + X[3] * I1 * ifc;
  const double f0 = d_.fc0;
  phi[0] = f0 * (common + X[2] * s[0] * ifc - 1.0);
  phi[1] = f0 * (common + X[2] * s[1] * ifc - 1.0);
  for (int i = 0; i < 3; ++i)
    phi[2 + i] = s[i] - ft;
  if (n)
  {
    const T a = f0 * (X[0] * ifc * ifc + X[1] * ifc / (2.0 * q));
    const T b = f0 * X[3] * ifc;
    const T c = f0 * X[2] * ifc;
    for (int i = 0; i < 3; ++i)
    {
      const T g = a * dev[i] + b;
      (*n)[0][i] = g;
      (*n)[1][i] = g;
      for (int k = 0; k < 3; ++k)
        (*n)[2 + k][i] = T(i == k ? 1.0 : 0.0);
    }
    (*n)[0][0] += c;
    (*n)[1][1] += c;
  }
}

template <class T, int M>
void HtcConcrete::residual(const std::array<T, 5 + M>& x, const int* ids,
                           const std::array<double, 3>& str, double kcn,
                           double ktn, double dt, bool lc, bool lt, bool rates,
                           std::array<T, 5 + M>& r) const
{
  using std::abs;
  using std::exp;
  using std::log;
  using std::sqrt;
  const std::array<T, 3> s = {x[0], x[1], x[2]};
  // Internal variables: kappa itself, or (power rate law) the log-rate
  // y = log(1 + kappa_dot / kdot0), which makes the consistency equation
  // nearly linear in the unknown (R = exp(delta y)); with kappa as unknown
  // the Newton iteration crawls through the logarithmic rate dependence.
  T kc, kt, kcd, ktd;
  if (lc)
  {
    kcd = d_.rate_c.kdot0 * (exp(x[3]) - 1.0);
    kc = kcn + dt * kcd;
  }
  else
  {
    kc = x[3];
    kcd = rates ? T((kc - kcn) / dt) : T(0.0);
  }
  if (lt)
  {
    ktd = d_.rate_t.kdot0 * (exp(x[4]) - 1.0);
    kt = ktn + dt * ktd;
  }
  else
  {
    kt = x[4];
    ktd = rates ? T((kt - ktn) / dt) : T(0.0);
  }
  std::array<T, 5> phi;
  std::array<std::array<T, 3>, 5> n;
  surfaces(s, kc, kt, kcd, ktd, phi, &n);
  std::array<T, 3> eh = {T(0.0), T(0.0), T(0.0)}, er = eh;
  for (int j = 0; j < M; ++j)
  {
    const int k = ids[j];
    const T& lam = x[5 + j];
    if (k < 2)
      for (int i = 0; i < 3; ++i)
        eh[i] += lam * n[k][i];
    else
      er[k - 2] += lam;
  }
  const T tr = eh[0] + eh[1] + eh[2] + er[0] + er[1] + er[2];
  for (int i = 0; i < 3; ++i)
    r[i] = s[i] - str[i] + d_.lambda * tr + 2.0 * d_.G * (eh[i] + er[i]);
  T nh = sqrt(eh[0] * eh[0] + eh[1] * eh[1] + eh[2] * eh[2]);
  T nr = sqrt(er[0] * er[0] + er[1] * er[1] + er[2] * er[2]);
  if (value(nh) == 0.0 || value(nr) == 0.0)
  {
    // At zero multipliers the norm has a kink: use its one-sided derivative
    // for lambda >= 0 (sum of lambda_k |n_k|), same value (zero).
    T sh(0.0), sr(0.0);
    for (int j = 0; j < M; ++j)
    {
      const int k = ids[j];
      const T& lam = x[5 + j];
      if (k < 2)
        sh += lam *
              sqrt(n[k][0] * n[k][0] + n[k][1] * n[k][1] + n[k][2] * n[k][2]);
      else
        sr += lam;
    }
    if (value(nh) == 0.0)
      nh = sh;
    if (value(nr) == 0.0)
      nr = sr;
  }
  // Lee & Fenves stress weight: the tensile share of the HTC flow,
  // w = sum <s_i> / sum |s_i|, with |x| smoothed as sqrt(x^2 + e^2),
  // e = 1e-6 fc0: the kinks at s_i = 0 (uniaxial and biaxial states sit
  // exactly there) would otherwise stall the Newton iteration.
  const double e2 = 1e-12 * d_.fc0 * d_.fc0;
  T sa(0.0), sp(0.0);
  for (int i = 0; i < 3; ++i)
  {
    const T a = sqrt(s[i] * s[i] + e2);
    sa += a;
    sp += 0.5 * (s[i] + a);
  }
  const T w = sp / sa;
  const T dkc = (1.0 - w) * c23 * nh;
  const T dkt = w * c23 * nh + c23 * nr;
  r[3] = lc ? T(x[3] - log(1.0 + dkc / (dt * d_.rate_c.kdot0)))
            : T(kc - kcn - dkc);
  r[4] = lt ? T(x[4] - log(1.0 + dkt / (dt * d_.rate_t.kdot0)))
            : T(kt - ktn - dkt);
  for (int j = 0; j < M; ++j)
    r[5 + j] = phi[ids[j]];
}

template <int M>
bool HtcConcrete::solve_set(unsigned set, const std::array<double, 3>& str,
                            double kcn, double ktn, double kcd_old,
                            double ktd_old, double dt,
                            std::array<double, 9>& xout,
                            std::array<double, 9>& dsig_dtr,
                            int& iterations) const
{
  constexpr int N = 5 + M;
  using D = Dual<N>;
  int ids[M];
  int m = 0;
  for (int k = 0; k < 5; ++k)
    if (set & (1u << k))
      ids[m++] = k;
  // Log-rate unknowns only for the mechanisms of the active set: a rate
  // variable driven by a tiny share of the flow (e.g. kappa_t under HTC flow
  // in compression) is badly scaled in log form and stays plain.
  const bool lc = log_c_ && (set & (htc_surface | htc_edge));
  const bool lt = log_t_ && (set & (rankine_1 | rankine_2 | rankine_3));
  std::array<double, N> x{};
  x[0] = str[0];
  x[1] = str[1];
  x[2] = str[2];
  // Log-rate unknowns start from the rate of the previous step (a good
  // guess under smooth loading); multipliers start at zero.
  // (kcd_old < 0 requests the zero-rate start, used as a retry.)
  x[3] = lc ? std::log1p(std::max(kcd_old, 0.0) / d_.rate_c.kdot0) : kcn;
  x[4] = lt ? std::log1p(std::max(ktd_old, 0.0) / d_.rate_t.kdot0) : ktn;
  const double sS = 1.0 / d_.fc0, sK = d_.E / d_.fc0;
  std::array<D, N> xd, rd;
  std::array<double, N * N> J;
  std::array<int, N> piv;
  std::array<double, N> dx, xt, rt;
  // Damped Newton; on success x is converged (and polished) and J holds the
  // LU factors of the Jacobian there.
  auto newton = [&](bool lcx, bool ltx, bool rates,
                    std::array<double, N>& x) -> bool
  {
    const double c3 = lcx ? 1.0 : sK, c4 = ltx ? 1.0 : sK;
    auto scale = [&](int i) { return i == 3 ? c3 : (i == 4 ? c4 : sS); };
    auto norm = [&](const auto& r)
    {
      double v = 0;
      for (int i = 0; i < N; ++i)
        v = std::max(v, std::abs(value(r[i])) * scale(i));
      return std::isfinite(v) ? v : std::numeric_limits<double>::infinity();
    };
    auto merit = [&](const auto& r)
    {
      double v = 0;
      for (int i = 0; i < N; ++i)
      {
        const double e = value(r[i]) * scale(i);
        v += e * e;
      }
      return std::isfinite(v) ? std::sqrt(v)
                              : std::numeric_limits<double>::infinity();
    };
    for (int it = 0; it < p_.max_iterations; ++it)
    {
      for (int i = 0; i < N; ++i)
        xd[i] = D::variable(x[i], i);
      residual<D, M>(xd, ids, str, kcn, ktn, dt, lcx, ltx, rates, rd);
      const double r0 = norm(rd), m0 = merit(rd);
      for (int i = 0; i < N; ++i)
      {
        dx[i] = -rd[i].v;
        for (int j = 0; j < N; ++j)
          J[i * N + j] = rd[i].d[j];
      }
      if (!lu_factor<N>(J, piv))
        return false;
      lu_solve<N>(J, piv, dx);
      if (r0 < p_.tolerance)
      {
        // One more (polishing) Newton step brings the solution to
        // round-off, so the tangent is the derivative of the returned map.
        for (int i = 0; i < N; ++i)
          x[i] += dx[i];
        return true;
      }
      ++iterations;
      // Backtracking on the scaled residual; log-rate steps limited to 2
      // (a factor e^2 on the rate) per iteration.
      double alpha = 1.0;
      if (lcx && std::abs(dx[3]) > 2.0)
        alpha = std::min(alpha, 2.0 / std::abs(dx[3]));
      if (ltx && std::abs(dx[4]) > 2.0)
        alpha = std::min(alpha, 2.0 / std::abs(dx[4]));
      bool ok = false;
      for (int ls = 0; ls < 30; ++ls)
      {
        for (int i = 0; i < N; ++i)
          xt[i] = x[i] + alpha * dx[i];
        residual<double, M>(xt, ids, str, kcn, ktn, dt, lcx, ltx, rates, rt);
        if (merit(rt) < (1.0 - 1e-4 * alpha) * m0)
        {
          ok = true;
          break;
        }
        alpha *= 0.5;
      }
      if (!ok)
        return false;
      x = xt;
    }
    return false;
  };

  // Viscoplastic: first from the trial state and the old rates (good under
  // smooth loading); if that fails, from the rate-independent return (R = 1)
  // for this set, an upper bound of the viscoplastic increments whose kappa
  // increments give the starting log-rates (from zero multipliers and far
  // rates the logarithmic rate law makes Newton crawl).
  const std::array<double, N> x0 = x;
  if (!newton(lc, lt, rate_on_, x))
  {
    if (!rate_on_ || kcd_old < 0.0)
      return false;
    std::array<double, N> xp{};
    xp[0] = str[0];
    xp[1] = str[1];
    xp[2] = str[2];
    xp[3] = kcn;
    xp[4] = ktn;
    if (!newton(false, false, false, xp))
      return false;
    x = xp;
    x[3] = lc ? std::log1p(std::max(xp[3] - kcn, 0.0) / (dt * d_.rate_c.kdot0))
              : xp[3];
    x[4] = lt ? std::log1p(std::max(xp[4] - ktn, 0.0) / (dt * d_.rate_t.kdot0))
              : xp[4];
    if (x == x0 || !newton(lc, lt, rate_on_, x))
      return false;
  }
  for (int c = 0; c < 3; ++c)
  {
    std::array<double, N> e{};
    e[c] = 1.0;
    lu_solve<N>(J, piv, e);
    for (int i = 0; i < 3; ++i)
      dsig_dtr[i * 3 + c] = e[i];
  }
  for (int i = 0; i < N; ++i)
    xout[i] = x[i];
  if (lc)
    xout[3] = kcn + dt * d_.rate_c.kdot0 * std::expm1(x[3]);
  if (lt)
    xout[4] = ktn + dt * d_.rate_t.kdot0 * std::expm1(x[4]);
  return true;
}

Update HtcConcrete::integrate(const State& old, const Vector6& de,
                              double dt) const
{
  Update u;
  u.state = old;
  const Matrix6 De = elastic_tangent();
  Vector6 tr;
  for (int i = 0; i < 6; ++i)
  {
    double s = old.stress[i];
    for (int j = 0; j < 6; ++j)
      s += De[i * 6 + j] * de[j];
    tr[i] = s;
  }
  u.state.stress = tr;
  u.state.kappa_c_rate = u.state.kappa_t_rate = 0.0;
  u.tangent = De;
  if (p_.mode == Mode::elastic)
    return u;
  if (rate_on_ && !(dt > 0.0))
    throw std::invalid_argument(
        "HtcConcrete::integrate: viscoplastic mode needs dt > 0");

  const double tol_f = p_.tolerance * d_.fc0;
  std::array<double, 5> phi;
  {
    const auto sp = principal_fast(tr);
    surfaces<double>(sp, old.kappa_c, old.kappa_t, 0.0, 0.0, phi, nullptr);
    if (phi[0] <= tol_f && phi[2] <= tol_f)
      return u; // elastic step
  }

  Eigen::Matrix3d S;
  S << tr[0], tr[3], tr[5], tr[3], tr[1], tr[4], tr[5], tr[4], tr[2];
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(S);
  const std::array<double, 3> str = {es.eigenvalues()[2], es.eigenvalues()[1],
                                     es.eigenvalues()[0]};
  const Eigen::Vector3d nv[3] = {es.eigenvectors().col(2),
                                 es.eigenvectors().col(1),
                                 es.eigenvectors().col(0)};
  surfaces<double>(str, old.kappa_c, old.kappa_t, 0.0, 0.0, phi, nullptr);
  unsigned set = 0;
  for (int k = 0; k < 5; ++k)
    if (phi[k] > tol_f)
      set |= 1u << k;
  set = close_set(set);
  if (!valid_set(set))
    set = htc_surface;

  std::array<double, 9> x{}, C{};
  const double tol_viol = 1e-8 * d_.fc0, tol_lam = -1e-13;
  unsigned visited_lo = 0; // bit s: set s already tried
  auto tried = [&](unsigned s) { return (visited_lo >> s) & 1u; };

  // Solves one set and checks the Kuhn-Tucker conditions; returns 0 if
  // consistent, otherwise the next set to try (or 0xff if none).
  auto attempt = [&](unsigned s, bool& consistent) -> unsigned
  {
    consistent = false;
    visited_lo |= 1u << s;
    ++u.passes;
    const int m = std::popcount(s);
    bool ok = false;
    switch (m)
    {
    case 1:
      ok = solve_set<1>(s, str, old.kappa_c, old.kappa_t, old.kappa_c_rate,
                        old.kappa_t_rate, dt, x, C, u.iterations);
      break;
    case 2:
      ok = solve_set<2>(s, str, old.kappa_c, old.kappa_t, old.kappa_c_rate,
                        old.kappa_t_rate, dt, x, C, u.iterations);
      break;
    case 3:
      ok = solve_set<3>(s, str, old.kappa_c, old.kappa_t, old.kappa_c_rate,
                        old.kappa_t_rate, dt, x, C, u.iterations);
      break;
    default:
      ok = solve_set<4>(s, str, old.kappa_c, old.kappa_t, old.kappa_c_rate,
                        old.kappa_t_rate, dt, x, C, u.iterations);
    }
    if (!ok && rate_on_ && (old.kappa_c_rate > 0.0 || old.kappa_t_rate > 0.0))
    {
      // Retry from zero rates (the old rates can be far from this step's).
      switch (m)
      {
      case 1:
        ok = solve_set<1>(s, str, old.kappa_c, old.kappa_t, -1.0, -1.0, dt, x,
                          C, u.iterations);
        break;
      case 2:
        ok = solve_set<2>(s, str, old.kappa_c, old.kappa_t, -1.0, -1.0, dt, x,
                          C, u.iterations);
        break;
      case 3:
        ok = solve_set<3>(s, str, old.kappa_c, old.kappa_t, -1.0, -1.0, dt, x,
                          C, u.iterations);
        break;
      default:
        ok = solve_set<4>(s, str, old.kappa_c, old.kappa_t, -1.0, -1.0, dt, x,
                          C, u.iterations);
      }
    }
    if (!ok)
      return 0xffu;
    // Negative multipliers: drop the most negative one.
    int j = 0, worst = -1;
    double wl = tol_lam;
    for (int k = 0; k < 5; ++k)
      if (s & (1u << k))
      {
        if (x[5 + j] < wl)
        {
          wl = x[5 + j];
          worst = k;
        }
        ++j;
      }
    if (worst >= 0)
    {
      unsigned ns = s & ~(1u << worst);
      if (worst == 0)
        ns &= ~unsigned(htc_edge);
      if (worst == 2)
        ns &= ~unsigned(rankine_2 | rankine_3);
      if (worst == 3)
        ns &= ~unsigned(rankine_3);
      return ns;
    }
    // Violated inactive surfaces: add the most violated one.
    const double kcd = rate_on_ ? (x[3] - old.kappa_c) / dt : 0.0;
    const double ktd = rate_on_ ? (x[4] - old.kappa_t) / dt : 0.0;
    std::array<double, 5> ph;
    surfaces<double>({x[0], x[1], x[2]}, x[3], x[4], kcd, ktd, ph, nullptr);
    int add = -1;
    double wv = tol_viol;
    for (int k = 0; k < 5; ++k)
      if (!(s & (1u << k)) && ph[k] > wv)
      {
        wv = ph[k];
        add = k;
      }
    if (add >= 0)
      return close_set(s | (1u << add));
    consistent = true;
    return 0;
  };

  bool consistent = false;
  for (int pass = 0; pass < 8 && !consistent; ++pass)
  {
    const unsigned next = attempt(set, consistent);
    if (consistent)
      break;
    if (next == 0xffu || !valid_set(next) || tried(next))
      break;
    set = next;
  }
  if (!consistent)
  {
    // Fall-back: every valid set, smallest first.
    for (int size = 1; size <= 4 && !consistent; ++size)
      for (unsigned s = 1; s < 32 && !consistent; ++s)
        if (valid_set(s) && std::popcount(s) == size && !tried(s))
        {
          attempt(s, consistent);
          if (consistent)
            set = s;
        }
  }
  if (!consistent)
  {
    u.converged = false;
    u.active = set;
    return u;
  }

  // New state.
  u.active = set;
  State& ns = u.state;
  ns.stress = {0, 0, 0, 0, 0, 0};
  for (int i = 0; i < 3; ++i)
  {
    const Vector6 E = outer_vec(nv[i], nv[i]);
    for (int a = 0; a < 6; ++a)
      ns.stress[a] += x[i] * E[a];
  }
  ns.kappa_c = x[3];
  ns.kappa_t = x[4];
  ns.kappa_c_rate = dt > 0 ? (x[3] - old.kappa_c) / dt : 0.0;
  ns.kappa_t_rate = dt > 0 ? (x[4] - old.kappa_t) / dt : 0.0;
  {
    Vector6 ds;
    for (int a = 0; a < 6; ++a)
      ds[a] = tr[a] - ns.stress[a];
    const double tr_ds = ds[0] + ds[1] + ds[2];
    for (int a = 0; a < 3; ++a)
      ns.plastic_strain[a] += ((1.0 + d_.nu) * ds[a] - d_.nu * tr_ds) / d_.E;
    for (int a = 3; a < 6; ++a)
      ns.plastic_strain[a] += ds[a] / d_.G;
  }

  // Consistent tangent: d(sigma)/d(sigma_tr) of the coaxial return (the
  // principal part from the converged Jacobian, spin terms from the
  // eigenvalue differences; de Souza Neto et al. 2008, App. A), times D.
  Matrix6 T{};
  double CD[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
    {
      double s = 0;
      for (int k = 0; k < 3; ++k)
        s += C[i * 3 + k] * (d_.lambda + (k == j ? 2.0 * d_.G : 0.0));
      CD[i][j] = s;
    }
  Vector6 Ev[3];
  for (int i = 0; i < 3; ++i)
    Ev[i] = outer_vec(nv[i], nv[i]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int a = 0; a < 6; ++a)
        for (int b = 0; b < 6; ++b)
          T[a * 6 + b] += CD[i][j] * Ev[i][a] * Ev[j][b];
  const int pairs[3][2] = {{0, 1}, {1, 2}, {0, 2}};
  for (const auto& pr : pairs)
  {
    const int i = pr[0], j = pr[1];
    const double dl = str[i] - str[j];
    const double scale = std::abs(str[i]) + std::abs(str[j]) + 1e-3 * d_.fc0;
    const double theta = std::abs(dl) > 1e-9 * scale
                             ? (x[i] - x[j]) / dl
                             : C[i * 3 + i] - C[i * 3 + j];
    Vector6 Mv = outer_vec(nv[i], nv[j]); // (n_i n_j^T + n_j n_i^T)/2
    // normalised M = (n_i n_j^T + n_j n_i^T)/sqrt(2) = sqrt(2) * Mv
    const double f = 2.0 * d_.G * theta * 2.0;
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b)
        T[a * 6 + b] += f * Mv[a] * Mv[b];
  }
  u.tangent = T;
  return u;
}

Matrix6 HtcConcrete::elastic_tangent() const
{
  Matrix6 D{};
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
      D[i * 6 + j] = d_.lambda;
    D[i * 6 + i] += 2.0 * d_.G;
    D[(i + 3) * 6 + i + 3] = d_.G;
  }
  return D;
}

double HtcConcrete::compressive_strength(double kc, double kcd) const
{
  return d_.fc0 * hc(kc) * (rate_on_ ? d_.rate_c(std::max(kcd, 0.0)) : 1.0);
}

double HtcConcrete::tensile_strength(double kt, double ktd) const
{
  return d_.ft0 * std::exp(-kt / d_.kappa_tu) *
         (rate_on_ ? d_.rate_t(std::max(ktd, 0.0)) : 1.0);
}

HtcCoefficients HtcConcrete::htc_coefficients(double kc, double kt, double kcd,
                                              double ktd) const
{
  const double fc = compressive_strength(kc, kcd);
  const double ft = tensile_strength(kt, ktd);
  const double ftH = std::clamp((1.0 + p_.htc_tension_offset) * ft,
                                p_.rho_min * fc, p_.rho_max * fc);
  return family_.at(ftH / fc);
}

double HtcConcrete::yield_value(const Vector6& stress, double kc, double kt,
                                double kcd, double ktd) const
{
  const auto s = principal_stresses(stress);
  std::array<double, 5> phi;
  surfaces<double>(s, kc, kt, kcd, ktd, phi, nullptr);
  double m = phi[0];
  for (int k = 1; k < 5; ++k)
    m = std::max(m, phi[k]);
  return m / d_.fc0;
}

} // namespace damseis::material
