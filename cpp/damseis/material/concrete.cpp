#include "concrete.h"

#include <Eigen/Dense>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <type_traits>

namespace damseis::material
{

namespace
{
const double c23 = std::sqrt(2.0 / 3.0);

/// Principal stresses (descending) from the invariants: cheap, used only to
/// decide whether the trial state is elastic.
std::array<double, 3> principal_fast(const Vector6& s)
{
  if (s[4] == 0.0 && s[5] == 0.0)
  {
    // Plane states (no yz, zx shear): the in-plane pair in closed form and
    // sigma_zz, sorted; no trigonometry (this test runs at every point of
    // a 2D model in every Newton iteration).
    const double c = 0.5 * (s[0] + s[1]), h = 0.5 * (s[0] - s[1]);
    const double r = std::sqrt(h * h + s[3] * s[3]); // stresses: no overflow
    std::array<double, 3> p = {c + r, c - r, s[2]};
    if (p[2] > p[1])
      std::swap(p[1], p[2]);
    if (p[1] > p[0])
      std::swap(p[0], p[1]);
    return p;
  }
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

/// Principal values (descending) and unit directions of a symmetric tensor
/// (Voigt). Plane states (no yz, zx shear: every point of a 2D model) in
/// closed form, the in-plane direction without cancellation (plastic plane
/// points ~9% faster than with the iterative solver); otherwise Eigen's QL
/// iteration (~0.3 us for a 3D state).
void principal_axes(const Vector6& s, std::array<double, 3>& val,
                    Eigen::Vector3d vec[3])
{
  if (s[4] == 0.0 && s[5] == 0.0)
  {
    const double c = 0.5 * (s[0] + s[1]), h = 0.5 * (s[0] - s[1]);
    const double r = std::hypot(h, s[3]);
    // (h - r) x + s12 y = 0 for the eigenvalue c + r
    double x = 1.0, y = 0.0;
    if (r > 0.0)
    {
      x = h >= 0.0 ? h + r : s[3];
      y = h >= 0.0 ? s[3] : r - h;
      const double n = std::hypot(x, y);
      x /= n;
      y /= n;
    }
    val = {c + r, c - r, s[2]};
    vec[0] = {x, y, 0.0};
    vec[1] = {-y, x, 0.0};
    vec[2] = {0.0, 0.0, 1.0};
    if (val[2] > val[1])
    {
      std::swap(val[1], val[2]);
      std::swap(vec[1], vec[2]);
      if (val[1] > val[0])
      {
        std::swap(val[0], val[1]);
        std::swap(vec[0], vec[1]);
      }
    }
    return;
  }
  Eigen::Matrix3d S;
  S << s[0], s[3], s[5], s[3], s[1], s[4], s[5], s[4], s[2];
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(S);
  for (int i = 0; i < 3; ++i)
  {
    val[i] = es.eigenvalues()[2 - i];
    vec[i] = es.eigenvectors().col(2 - i);
  }
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
/// {HTC, edge, R1, R2, R3} is excluded. In {HTC, edge, R1, R2} the
/// constraints are dependent (sigma1 = sigma2 follows from either pair): the
/// two HTC branches there share their multiplier equally (the centroid of
/// the subdifferential, as at the apex) and the Rankine planes carry the
/// difference between the two directions.
bool valid_set(unsigned s)
{
  if (s == htc_apex)
    return true;
  if (s == 0 || s >= 32)
    return false;
  if ((s & htc_edge) && !(s & htc_surface))
    return false;
  if ((s & rankine_2) && !(s & rankine_1))
    return false;
  if ((s & rankine_3) && !(s & rankine_2))
    return false;
  if ((s & htc_edge) && (s & rankine_3))
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

/// The nonzero components of a Voigt vector (index, value).
struct Sparse6
{
  int n = 0;
  int idx[6];
  double v[6];
  Sparse6() = default;
  explicit Sparse6(const Vector6& x)
  {
    for (int a = 0; a < 6; ++a)
      if (x[a] != 0.0)
      {
        idx[n] = a;
        v[n++] = x[a];
      }
  }
};

/// The stress sum_i x_i n_i n_i^T (Voigt) of principal values x along the
/// directions dir.
Vector6 from_principal(const double* x,
                       const std::array<std::array<double, 3>, 3>& dir)
{
  Vector6 s = {0, 0, 0, 0, 0, 0};
  for (int i = 0; i < 3; ++i)
  {
    const Eigen::Vector3d n(dir[i][0], dir[i][1], dir[i][2]);
    const Vector6 E = outer_vec(n, n);
    for (int a = 0; a < 6; ++a)
      s[a] += x[i] * E[a];
  }
  return s;
}

/// The first iterate of the Rankine multiplier of a crack opening: the old
/// step's kappa_t rate over this step (-1, none, if it was not opening).
double old_rate_multiplier(const State& old, double dt)
{
  return dt > 0.0 && old.kappa_t_rate > 0.0 ? old.kappa_t_rate * dt / c23
                                            : -1.0;
}

/// The elastic trial stress old + De de.
Vector6 trial_stress(const Vector6& old, const Matrix6& De, const Vector6& de)
{
  Vector6 tr;
  for (int i = 0; i < 6; ++i)
  {
    double s = old[i];
    for (int j = 0; j < 6; ++j)
      s += De[i * 6 + j] * de[j];
    tr[i] = s;
  }
  return tr;
}

/// Adds the plastic strain of a return, D^-1 (trial - returned stress)
/// (engineering shear), to ep.
void add_plastic_strain(Vector6& ep, const Vector6& tr, const Vector6& s,
                        double E, double nu, double G)
{
  Vector6 ds;
  for (int a = 0; a < 6; ++a)
    ds[a] = tr[a] - s[a];
  const double tr_ds = ds[0] + ds[1] + ds[2];
  for (int a = 0; a < 3; ++a)
    ep[a] += ((1.0 + nu) * ds[a] - nu * tr_ds) / E;
  for (int a = 3; a < 6; ++a)
    ep[a] += ds[a] / G;
}
} // namespace

std::string to_string(TensionSoftening s)
{
  switch (s)
  {
  case TensionSoftening::crack_band_keep_strength:
    return "crack_band_keep_strength";
  case TensionSoftening::none:
    return "none";
  default:
    return "crack_band";
  }
}

std::string active_set_name(unsigned a)
{
  if (a == 0)
    return "elastic";
  std::string s;
  const char* names[6] = {"HTC", "edge", "R1", "R2", "R3", "apex"};
  for (int i = 0; i < 6; ++i)
    if (a & (1u << i))
    {
      if (!s.empty())
        s += '+';
      s += names[i];
    }
  return s;
}

HtcConcrete::HtcConcrete(const ConcreteParameters& p) : _p(p)
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
  require(p.max_substeps >= 1, "max_substeps must be >= 1");

  const double fac = p.dynamic_30_percent ? p.dynamic_factor : 1.0;
  _d.E = fac * p.E;
  _d.nu = p.nu;
  _d.G = _d.E / (2.0 * (1.0 + p.nu));
  _d.lambda = _d.E * p.nu / ((1.0 + p.nu) * (1.0 - 2.0 * p.nu));
  _d.K = _d.E / (3.0 * (1.0 - 2.0 * p.nu));
  _d.fc0 = fac * p.fc0;
  const double ft0 = fac * p.ft0;

  _d.calibration = p.classic_shape ? classic_calibration()
                                   : HtcCalibration{p.ft0 / p.fc0, p.fbc_ratio,
                                                    p.xi0, p.rho0};
  _family = HtcFamily(_d.calibration.fbc_ratio, _d.calibration.xi0,
                      _d.calibration.rho0);
  // Convexity over the whole range the guard allows (A, B, C >= 0).
  for (int i = 0; i <= 20; ++i)
  {
    const double rho = p.rho_min + (p.rho_max - p.rho_min) * i / 20.0;
    const auto k = _family.at(rho);
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
  // either ft0 is lowered so that the modulus is E / snap_back_safety: the
  // energy is still Gf / h (algorithms.md 1.3 remedy); or ft0 is kept and
  // the modulus set to E / snap_back_safety: the energy per unit volume is
  // then snap_back_safety ft0^2 / E > Gf / h (as in compression below); or
  // there is no softening at all.
  const double h = p.element_size;
  _d.l_ch = _d.E * p.Gf / (ft0 * ft0);
  _d.ft0 = ft0;
  _d.tension_strength_reduced = false;
  _d.tension_energy_raised = false;
  double Gf = p.Gf;
  if (p.tension_softening != TensionSoftening::none &&
      ft0 * ft0 * h / p.Gf > _d.E / p.snap_back_safety)
  {
    if (p.tension_softening == TensionSoftening::crack_band)
    {
      _d.ft0 = std::sqrt(_d.E * p.Gf / (p.snap_back_safety * h));
      _d.tension_strength_reduced = true;
    }
    else
    {
      Gf = p.snap_back_safety * ft0 * ft0 * h / _d.E;
      _d.tension_energy_raised = true;
    }
  }
  // No softening: Ht = exp(-kappa_t / inf) = 1 and its derivative 0.
  _d.kappa_tu = p.tension_softening == TensionSoftening::none
                    ? HUGE_VAL
                    : c23 * Gf / (h * _d.ft0);

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
    return std::clamp((1.0 + p.htc_tension_offset) * _d.ft0 / fc,
                      p.rho_min * 1.0, p.rho_max);
  };
  auto k_c = [&](double rho)
  {
    const auto k = _family.at(rho);
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
  _d.uniaxial_compression_dissipation = k_c(rho_of(_d.fc0));
  {
    const double uf = -std::log(p.compressive_floor);
    const int n = 400;
    double I = 0;
    for (int i = 0; i <= n; ++i)
    {
      const double u = uf * i / n;
      const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      I += w * std::exp(-u) * k_c(rho_of(_d.fc0 * std::exp(-u)));
    }
    I *= uf / (3.0 * n);
    _d.kappa_cs = p.Gc / (h * _d.fc0 * I);
  }
  const double kcs_min = p.snap_back_safety * _d.fc0 /
                         (_d.E * _d.uniaxial_compression_dissipation);
  _d.compression_energy_raised = _d.kappa_cs < kcs_min;
  _d.kappa_cs = std::max(_d.kappa_cs, kcs_min);

  // Rate functions. The CEB-FIP DIF is a function of the total axial strain
  // rate; at the peak of a constant-rate uniaxial test sigma_dot = 0, so the
  // axial viscoplastic rate equals the total one and kappa_dot = rate *
  // sqrt(2/3) (Rankine, tension) or rate / k_c (HTC edge, compression).
  // Hence kdot0 = (CEB reference rate) x that factor; the exponent is the
  // CEB one. Checked by single-point simulations (test_material_rate.cpp).
  if (p.rate_law == RateLaw::ceb_fip)
  {
    _d.rate_c = {RateLaw::ceb_fip, ceb_exponent_compression(p.fc0),
                 p.rate_shift_c * ceb_reference_rate_compression /
                     _d.uniaxial_compression_dissipation,
                 0.0};
    _d.rate_t = {RateLaw::ceb_fip, ceb_exponent_tension(p.fc0),
                 p.rate_shift_t * c23 * ceb_reference_rate_tension, 0.0};
  }
  else if (p.rate_law == RateLaw::linear)
  {
    _d.rate_c = {RateLaw::linear, 0.0, 1.0, p.eta_c};
    _d.rate_t = {RateLaw::linear, 0.0, 1.0, p.eta_t};
  }
  _rate_on = p.mode == Mode::viscoplastic && p.rate_law != RateLaw::none;
  _log_c = _rate_on && _d.rate_c.law == RateLaw::ceb_fip;
  _log_t = _rate_on && _d.rate_t.law == RateLaw::ceb_fip;
  // admissible()'s untouched point (_virgin_ifc is 0 until then).
  rest_strengths(0.0, 0.0, _virgin_ft, _virgin_ifc, _virgin_htc);
}

void HtcConcrete::rest_strengths(double kc, double kt, double& ft, double& ifc,
                                 std::array<double, 4>& X) const
{
  if (kc == 0.0 && kt == 0.0 && _virgin_ifc > 0.0)
  {
    ft = _virgin_ft;
    ifc = _virgin_ifc;
    X = _virgin_htc;
    return;
  }
  // surfaces() with R = 1 (its zero-rate case), by the same expressions.
  const double fc = _d.fc0 * hc(kc);
  ft = _d.ft0 * std::exp(-kt / _d.kappa_tu);
  ifc = 1.0 / fc;
  X = htc_of(ft, fc, ifc);
}

template <class T>
std::array<T, 4> HtcConcrete::htc_of(const T& ft, const T& fc,
                                     const T& ifc) const
{
  const T ftH =
      vmin(vmax(T((1.0 + _p.htc_tension_offset) * ft), T(_p.rho_min * fc)),
           T(_p.rho_max * fc));
  return _family.coefficients(T(ftH * ifc));
}

template <class T>
T HtcConcrete::hc(const T& kc) const
{
  using std::exp;
  return vmax(T(exp(-kc / _d.kappa_cs)), T(_p.compressive_floor));
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
  // R(0) = 1 exactly: no pow for the zero rates of the elastic-trial test
  // and the active-set prediction (plain values only; a Dual zero rate has
  // derivatives).
  auto rate = [&](const RateFunction& f, const T& kd) -> T
  {
    if (!_rate_on)
      return T(1.0);
    if constexpr (std::is_same_v<T, double>)
      if (kd == 0.0)
        return 1.0;
    return f(vmax(kd, T(-0.999 * f.kdot0)));
  };
  const T Rc = rate(_d.rate_c, kcd), Rt = rate(_d.rate_t, ktd);
  const T fc = _d.fc0 * hc(kc) * Rc;
  const T ft = _d.ft0 * exp(-kt / _d.kappa_tu) * Rt;
  const T ifc = 1.0 / fc;
  surfaces_at(s, ft, ifc, htc_of(ft, fc, ifc), phi, n);
}

template <class T>
void HtcConcrete::surfaces_at(const std::array<T, 3>& s, const T& ft,
                              const T& ifc, const std::array<T, 4>& X,
                              std::array<T, 5>& phi,
                              std::array<std::array<T, 3>, 5>* n) const
{
  using std::sqrt;
  const T I1 = s[0] + s[1] + s[2];
  const T m = I1 / 3.0;
  const std::array<T, 3> dev = {s[0] - m, s[1] - m, s[2] - m};
  const T J2 = 0.5 * (dev[0] * dev[0] + dev[1] * dev[1] + dev[2] * dev[2]);
  const T q = sqrt(J2 + 1e-30 * _d.fc0 * _d.fc0);
  const T common = X[0] * J2 * ifc * ifc + X[1] * q * ifc + X[3] * I1 * ifc;
  const double f0 = _d.fc0;
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
void HtcConcrete::reduced(const T* y, const int* ids, const T* str, double kcn,
                          double ktn, double dt, bool lc, bool lt, bool rates,
                          T* r, T* sig) const
{
  using std::exp;
  using std::sqrt;
  // Internal variables: kappa itself, or (power rate law) the log-rate
  // y = log(1 + kappa_dot / kdot0), which makes the consistency equation
  // nearly linear in the unknown: R = (1 + kappa_dot / kdot0)^delta =
  // exp(delta y) (no pow; surfaces() clamps 1 + kappa_dot / kdot0 at 1e-3,
  // the same here), and e^-y of the rate row is 1 / e^y.
  T kc, kt, Rc(1.0), Rt(1.0), iec(1.0), iet(1.0);
  auto log_rate =
      [&](const RateFunction& f, const T& yk, double kn, T& k, T& R, T& ie)
  {
    const T ey = exp(yk);
    k = kn + (dt * f.kdot0) * (ey - 1.0);
    if (rates)
      R = value(ey) >= 1.0 - 0.999 ? T(exp(f.delta * yk))
                                   : T(std::pow(1.0 - 0.999, f.delta));
    ie = 1.0 / ey;
  };
  auto plain = [&](const RateFunction& f, const T& yk, double kn, T& k, T& R)
  {
    k = yk;
    if (rates)
      R = f(vmax(T((k - kn) / dt), T(-0.999 * f.kdot0)));
  };
  if (lc)
    log_rate(_d.rate_c, y[M], kcn, kc, Rc, iec);
  else
    plain(_d.rate_c, y[M], kcn, kc, Rc);
  if (lt)
    log_rate(_d.rate_t, y[M + 1], ktn, kt, Rt, iet);
  else
    plain(_d.rate_t, y[M + 1], ktn, kt, Rt);
  // Strengths and the HTC coefficients (as in surfaces()).
  const T fc = _d.fc0 * hc(kc) * Rc;
  const T ft = _d.ft0 * exp(-kt / _d.kappa_tu) * Rt;
  const T ifc = 1.0 / fc;
  const auto X = htc_of(ft, fc, ifc);
  const double f0 = _d.fc0, G2 = 2.0 * _d.G, K = _d.K;
  // Gradient of the HTC branch k: n_k = a(q) s + b 1 + c e_k with
  // a(q) = alpha + beta / q, q = sqrt(J2).
  const T alpha = f0 * X[0] * ifc * ifc, beta = 0.5 * f0 * X[1] * ifc;
  const T b = f0 * X[3] * ifc, c = f0 * X[2] * ifc;
  T lam(0.0), lh0(0.0), lh1(0.0), la(0.0);
  std::array<T, 3> er = {T(0.0), T(0.0), T(0.0)};
  bool any_h = false, any_r = false, apex = false;
  for (int j = 0; j < M; ++j)
  {
    const int k = ids[j];
    if (k < 2)
    {
      (k == 0 ? lh0 : lh1) = y[j];
      lam += y[j];
      any_h = true;
    }
    else if (k == 5)
    {
      // Apex of the HTC: the sigma_max term flows along the centroid of
      // its subdifferential, (e1 + e2 + e3) / 3, the deviator entirely.
      la = y[j] / 3.0;
      lam += y[j];
      any_h = apex = true;
    }
    else
    {
      er[k - 2] = y[j];
      any_r = true;
    }
  }
  // sigma = sigma_tr - D (lam (a s + b 1) + v), v = c (l0 e1 + l1 e2) + er:
  // the deviator is s = S* / (1 + 2G lam a(q)), S* = dev(sigma_tr - 2G v),
  // so q (1 + 2G lam alpha) + 2G lam beta = q* (closed form); q <= 0 means
  // the return reaches the HTC apex (s = 0).
  const std::array<T, 3> v = {c * (lh0 + la) + er[0], c * (lh1 + la) + er[1],
                              c * la + er[2]};
  const T trv = v[0] + v[1] + v[2];
  const T ptr = (str[0] + str[1] + str[2]) / 3.0;
  std::array<T, 3> Ss;
  for (int i = 0; i < 3; ++i)
    Ss[i] = str[i] - ptr - G2 * (v[i] - trv / 3.0);
  const T qs2 = 0.5 * (Ss[0] * Ss[0] + Ss[1] * Ss[1] + Ss[2] * Ss[2]);
  const T p = ptr - K * (3.0 * lam * b + trv);
  std::array<T, 3> ds = {T(0.0), T(0.0), T(0.0)}, ed = ds;
  T q(0.0);
  const double tiny = 1e-30 * f0 * f0;
  const bool pos = value(qs2) > tiny;
  const T qs = pos ? sqrt(qs2) : T(0.0);
  if (!any_h)
    ds = Ss; // Rankine planes only: linear
  else if (!apex && pos && value(qs - G2 * lam * beta) > 0.0)
  {
    const T den = 1.0 + G2 * lam * alpha;
    q = (qs - G2 * lam * beta) / den;
    const T fs = q / qs, fe = lam * (alpha * qs + beta) / (den * qs);
    for (int i = 0; i < 3; ++i)
    {
      ds[i] = Ss[i] * fs;
      ed[i] = Ss[i] * fe; // lam a(q) s, without cancellation
    }
  }
  else if (pos)
    for (int i = 0; i < 3; ++i)
      ed[i] = Ss[i] / G2; // apex: the whole deviator flows
  for (int i = 0; i < 3; ++i)
    sig[i] = p + ds[i];
  // Yield functions of the active set, scaled by 1/fc0.
  const T I1 = 3.0 * p, J2 = q * q;
  const T common = X[0] * J2 * ifc * ifc + X[1] * q * ifc + X[3] * I1 * ifc;
  // {HTC, edge, R1, R2}: the edge branch equation is implied by the others
  // (sigma1 = sigma2 = ft); its row sets the two HTC multipliers equal.
  bool split = false;
  for (int j = 0; j < M; ++j)
    split = split || ids[j] == 3;
  for (int j = 0; j < M; ++j)
  {
    const int k = ids[j];
    if (k == 1 && split)
      r[j] = (lh0 - lh1) * (_d.E / f0);
    else
      r[j] = k < 2 || k == 5
                 ? T(common + X[2] * sig[k == 5 ? 0 : k] * ifc - 1.0)
                 : T((sig[k - 2] - ft) / f0);
  }
  // Flow of the HTC branches and of the Rankine planes.
  std::array<T, 3> eh;
  for (int i = 0; i < 3; ++i)
    eh[i] = ed[i] + lam * b;
  eh[0] += c * (lh0 + la);
  eh[1] += c * (lh1 + la);
  eh[2] += c * la;
  T nh(0.0), nr(0.0);
  if (any_h)
  {
    nh = sqrt(eh[0] * eh[0] + eh[1] * eh[1] + eh[2] * eh[2]);
    if (value(nh) == 0.0)
    {
      // Kink of the norm at zero multipliers: one-sided derivative
      // sum lambda_k |n_k| (same value, zero).
      const T a0 = pos ? T(alpha + beta / qs) : T(0.0);
      T sh(0.0);
      for (int br = 0; br < 2; ++br)
      {
        T n2(0.0);
        for (int i = 0; i < 3; ++i)
        {
          const T g = a0 * Ss[i] + b + (i == br ? c : T(0.0));
          n2 += g * g;
        }
        sh += (br == 0 ? lh0 : lh1) * sqrt(n2);
      }
      nh = sh;
    }
    else if (value(lam) < 0.0)
      nh = -nh; // signed: no spurious roots with negative multipliers
  }
  if (any_r)
  {
    nr = sqrt(er[0] * er[0] + er[1] * er[1] + er[2] * er[2]);
    if (value(nr) == 0.0)
      nr = er[0] + er[1] + er[2];
    else if (value(er[0] + er[1] + er[2]) < 0.0)
      nr = -nr;
  }
  // Lee & Fenves stress weight (|x| smoothed with 1e-6 fc0).
  const double e2 = 1e-12 * f0 * f0;
  T sa(0.0), sp(0.0);
  for (int i = 0; i < 3; ++i)
  {
    const T a = sqrt(sig[i] * sig[i] + e2);
    sa += a;
    sp += 0.5 * (sig[i] + a);
  }
  const T w = sp / sa;
  const T dkc = (1.0 - w) * c23 * nh;
  const T dkt = w * c23 * nh + c23 * nr;
  const double sK = _d.E / f0;
  // Rate equations of the log-rate unknowns, y = log(1 + dk / (dt kdot0)),
  // in the form delta (1 - (1 + dk / (dt kdot0)) e^-y): scaled by the
  // exponent (near the root, the relative error of R, like the other rows),
  // defined for any sign of dk, and linear in the multipliers wherever dk is
  // (Rankine flow), so that Newton on (multipliers, y) takes the steps of
  // Newton on the consistency condition in y alone (concave: no overshoot
  // from the right). The log form y - log(...) made the step leave the
  // domain of the logarithm and crawl.
  if (lc)
  {
    const T arg = 1.0 + dkc / (dt * _d.rate_c.kdot0);
    r[M] = T(_d.rate_c.delta * (1.0 - arg * iec));
  }
  else
    r[M] = (kc - kcn - dkc) * sK;
  if (lt)
  {
    const T arg = 1.0 + dkt / (dt * _d.rate_t.kdot0);
    r[M + 1] = T(_d.rate_t.delta * (1.0 - arg * iet));
  }
  else
    r[M + 1] = (kt - ktn - dkt) * sK;
}

template <class T, int M>
void HtcConcrete::residual_full(const std::array<T, 5 + M>& x, const int* ids,
                                const std::array<double, 3>& str, double kcn,
                                double ktn, double dt, bool lc, bool lt,
                                bool rates, std::array<T, 5 + M>& r) const
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
    kcd = _d.rate_c.kdot0 * (exp(x[3]) - 1.0);
    kc = kcn + dt * kcd;
  }
  else
  {
    kc = x[3];
    kcd = rates ? T((kc - kcn) / dt) : T(0.0);
  }
  if (lt)
  {
    ktd = _d.rate_t.kdot0 * (exp(x[4]) - 1.0);
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
    r[i] = s[i] - str[i] + _d.lambda * tr + 2.0 * _d.G * (eh[i] + er[i]);
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
  const double e2 = 1e-12 * _d.fc0 * _d.fc0;
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
  r[3] = lc ? T(x[3] - log(1.0 + dkc / (dt * _d.rate_c.kdot0)))
            : T(kc - kcn - dkc);
  r[4] = lt ? T(x[4] - log(1.0 + dkt / (dt * _d.rate_t.kdot0)))
            : T(kt - ktn - dkt);
  for (int j = 0; j < M; ++j)
    r[5 + j] = phi[ids[j]];
}

template <int M>
bool HtcConcrete::solve_full(unsigned set, const std::array<double, 3>& str,
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
  const bool lc = _log_c && (set & (htc_surface | htc_edge));
  const bool lt = _log_t && (set & (rankine_1 | rankine_2 | rankine_3));
  std::array<double, N> x{};
  x[0] = str[0];
  x[1] = str[1];
  x[2] = str[2];
  // Log-rate unknowns start from the rate of the previous step (a good
  // guess under smooth loading); multipliers start at zero.
  // (kcd_old < 0 requests the zero-rate start, used as a retry.)
  x[3] = lc ? std::log1p(std::max(kcd_old, 0.0) / _d.rate_c.kdot0) : kcn;
  x[4] = lt ? std::log1p(std::max(ktd_old, 0.0) / _d.rate_t.kdot0) : ktn;
  const double sS = 1.0 / _d.fc0, sK = _d.E / _d.fc0;
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
    for (int it = 0; it < _p.max_iterations; ++it)
    {
      for (int i = 0; i < N; ++i)
        xd[i] = D::variable(x[i], i);
      residual_full<D, M>(xd, ids, str, kcn, ktn, dt, lcx, ltx, rates, rd);
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
      if (r0 < _p.tolerance)
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
        residual_full<double, M>(xt, ids, str, kcn, ktn, dt, lcx, ltx, rates,
                                 rt);
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
  if (!newton(lc, lt, _rate_on, x))
  {
    if (!_rate_on || kcd_old < 0.0)
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
    x[3] = lc ? std::log1p(std::max(xp[3] - kcn, 0.0) / (dt * _d.rate_c.kdot0))
              : xp[3];
    x[4] = lt ? std::log1p(std::max(xp[4] - ktn, 0.0) / (dt * _d.rate_t.kdot0))
              : xp[4];
    if (x == x0 || !newton(lc, lt, _rate_on, x))
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
    xout[3] = kcn + dt * _d.rate_c.kdot0 * std::expm1(x[3]);
  if (lt)
    xout[4] = ktn + dt * _d.rate_t.kdot0 * std::expm1(x[4]);
  return true;
}

double HtcConcrete::rankine_1_multiplier(double s1, double ktn, double dt,
                                         bool rates, double modulus,
                                         double guess, double* ft_out) const
{
  // sigma_1 = s1 - a mu = ft0 exp(-(ktn + sqrt(2/3) mu) / kt_u)
  // R(sqrt(2/3) mu / dt), a = lambda + 2G (3D) or E / (1 - nu^2) (plane
  // stress): one root, as the softening modulus is below E. The power law
  // R = (1 + q mu)^delta enters as exp(delta log1p(q mu)), one exp and one
  // log1p per iteration instead of an exp and a pow.
  const double a = modulus > 0.0 ? modulus : _d.lambda + 2.0 * _d.G,
               c = c23 / _d.kappa_tu;
  const double q = rates ? c23 / (dt * _d.rate_t.kdot0) : 0.0;
  const double dl = _d.rate_t.delta, e0 = _d.ft0 * std::exp(-ktn / _d.kappa_tu);
  double lo = 0.0, hi = std::max(s1, 0.0) / a;
  double mu = std::clamp(guess >= 0.0 ? guess : (s1 - e0) / a, lo, hi);
  auto strength = [&](double m)
  { return e0 * std::exp(rates ? dl * std::log1p(q * m) - c * m : -c * m); };
  double ft = strength(mu);
  for (int it = 0; it < 60; ++it)
  {
    const double g = s1 - a * mu - ft;
    if (std::abs(g) <= 1e-14 * _d.fc0)
      break;
    (g > 0.0 ? lo : hi) = mu;
    const double dg = -a + ft * (c - (rates ? dl * q / (1.0 + q * mu) : 0.0));
    double next = mu - g / dg;
    if (!(next > lo && next < hi))
      next = 0.5 * (lo + hi);
    mu = next;
    ft = strength(mu);
  }
  if (ft_out)
    *ft_out = ft;
  return mu;
}

template <int M>
bool HtcConcrete::solve_set(unsigned set, const std::array<double, 3>& str,
                            double kcn, double ktn, double kcd_old,
                            double ktd_old, double dt, bool patient,
                            unsigned warm_set,
                            const std::array<double, 9>& warm,
                            std::array<double, 9>& xout,
                            std::array<double, 9>& dsig_dtr, int& iterations,
                            bool probe_edge, bool& edge_left) const
{
  edge_left = false;
  constexpr int N = M + 2;
  using D = Dual<N>;
  int ids[M];
  int m = 0;
  for (int k = 0; k < 6; ++k)
    if (set & (1u << k))
      ids[m++] = k;
  (void)m;
  const D strd[3] = {D(str[0]), D(str[1]), D(str[2])};
  std::array<D, N> yd, rd, rdt;
  std::array<double, N * N> J;
  std::array<int, N> piv;
  std::array<double, N> dy, yt, rt;
  double sig[3];
  D sigd[3];
  const double lmax =
      10.0 * (std::abs(str[0]) + std::abs(str[1]) + std::abs(str[2]) + _d.fc0) /
      _d.E; // bound on any multiplier (strain units)

  // Damped Newton on the reduced system; on success y is converged.
  // (tol: scaled residual tolerance, _p.tolerance unless given.)
  auto newton = [&](bool lc, bool lt, bool rates, std::array<double, N>& y,
                    double tol = -1.0) -> bool
  {
    if (tol < 0.0)
      tol = _p.tolerance;
    auto merit = [&](const auto& r)
    {
      double v = 0;
      for (int i = 0; i < N; ++i)
        v += value(r[i]) * value(r[i]);
      return std::isfinite(v) ? v : std::numeric_limits<double>::infinity();
    };
    // The first trial point of each line search is evaluated with its
    // derivatives: it is usually accepted, and then it is the next iterate
    // (fresh: rd holds the residual and the Jacobian at y).
    auto eval_jacobian =
        [&](const std::array<double, N>& x, std::array<D, N>& r)
    {
      for (int i = 0; i < N; ++i)
        yd[i] = D::variable(x[i], i);
      reduced<D, M>(yd.data(), ids, strd, kcn, ktn, dt, lc, lt, rates, r.data(),
                    sigd);
    };
    bool fresh = false;
    double hist[4] = {0, 0, 0, 0}; // merit of the last iterations
    for (int it = 0; it < _p.max_iterations; ++it)
    {
      if (!fresh)
        eval_jacobian(y, rd);
      fresh = false;
      double r0 = 0;
      for (int i = 0; i < N; ++i)
        r0 = std::max(r0, std::abs(rd[i].v));
      if (!std::isfinite(r0))
        return false;
      if (r0 < tol)
        return true;
      const double m0 = merit(rd);
      // A set without a solution makes the iteration stall: give up when
      // the merit has not halved over four iterations (the caller tries
      // other sets, and all of them patiently if needed).
      if (!patient && it >= 4 && m0 > 0.5 * hist[it % 4])
        return false;
      hist[it % 4] = m0;
      for (int i = 0; i < N; ++i)
      {
        dy[i] = -rd[i].v;
        for (int j = 0; j < N; ++j)
          J[i * N + j] = rd[i].d[j];
      }
      if (!lu_factor<N>(J, piv))
        return false;
      lu_solve<N>(J, piv, dy);
      ++iterations;
      // Step limits: log-rates by 2 (a factor e^2 on the rate), multipliers
      // and plain kappas within a bound of the whole return.
      double alpha = 1.0;
      for (int i = 0; i < N; ++i)
      {
        const bool logv = (i == M && lc) || (i == M + 1 && lt);
        const double lim = logv ? 2.0 : lmax;
        if (std::abs(dy[i]) > lim)
          alpha = std::min(alpha, lim / std::abs(dy[i]));
      }
      auto wnorm = [&](const std::array<double, N>& d)
      {
        double v = 0;
        for (int i = 0; i < N; ++i)
        {
          const double w = i == M && lc       ? _d.rate_c.delta
                           : i == M + 1 && lt ? _d.rate_t.delta
                                              : _d.E / _d.fc0;
          v += (w * d[i]) * (w * d[i]);
        }
        return std::sqrt(v);
      };
      bool ok = false;
      for (int ls = 0; ls < 40; ++ls)
      {
        for (int i = 0; i < N; ++i)
          yt[i] = y[i] + alpha * dy[i];
        if (ls == 0)
        {
          eval_jacobian(yt, rdt);
          for (int i = 0; i < N; ++i)
            rt[i] = rdt[i].v;
        }
        else
        {
          double st[3] = {str[0], str[1], str[2]};
          reduced<double, M>(yt.data(), ids, st, kcn, ktn, dt, lc, lt, rates,
                             rt.data(), sig);
        }
        const double mt = merit(rt);
        if (mt <= (1.0 - 1e-4 * alpha) * m0)
        {
          ok = true;
          fresh = ls == 0;
          break;
        }
        if (std::isfinite(mt))
        {
          // Natural monotonicity test (Deuflhard): the simplified Newton
          // correction -J^-1 r(y + alpha dy) with the current Jacobian must
          // shrink (affine invariant: unaffected by how nonlinear the
          // residual rows are in the multipliers).
          std::array<double, N> db;
          for (int i = 0; i < N; ++i)
            db[i] = -rt[i];
          lu_solve<N>(J, piv, db);
          if (wnorm(db) <= (1.0 - 0.25 * alpha) * wnorm(dy))
          {
            ok = true;
            fresh = ls == 0;
            break;
          }
        }
        // Quadratic model of the merit along the step (slope -2 m0).
        const double an = m0 * alpha * alpha / (mt - m0 + 2.0 * m0 * alpha);
        alpha = std::isfinite(mt) ? std::clamp(an, 0.1 * alpha, 0.5 * alpha)
                                  : 0.25 * alpha;
      }
      if (!ok)
        return false;
      y = yt;
      if (fresh)
        std::swap(rd, rdt);
    }
    return false;
  };

  const bool rates = _rate_on;
  bool lc = false, lt = false;
  std::array<double, N> y{};
  y[M] = kcn;
  y[M + 1] = ktn;
  // Log-rate unknowns (power law) from given kappa rates.
  auto from = [&](const std::array<double, N>& src, double rc, double rt2)
  {
    y = src;
    lc = _log_c;
    lt = _log_t;
    if (lc)
      y[M] = std::log1p(std::max(rc, 0.0) / _d.rate_c.kdot0);
    if (lt)
      y[M + 1] = std::log1p(std::max(rt2, 0.0) / _d.rate_t.kdot0);
  };
  // The Rankine plane sigma_1 <= ft alone (tensile points): the start is
  // the solution of the scalar equation of its return (the reduced
  // iteration only confirms it and gives the Jacobian), unless the rate
  // law is linear.
  const bool r1 = set == rankine_1 && (!rates || _log_t);
  bool ok = false;
  if (!rates)
  {
    if (r1)
    {
      const double mu = rankine_1_multiplier(str[0], ktn, dt, false);
      y[0] = mu;
      y[M + 1] = ktn + c23 * mu;
      ok = newton(false, false, false, y);
      if (!ok)
      {
        y = {};
        y[M] = kcn;
        y[M + 1] = ktn;
      }
    }
    if (!ok)
      ok = newton(false, false, false, y);
  }
  else
  {
    // Starts, from zero multipliers: (a) the rate-independent return of the
    // set (R = 1), whose increments give the starting log-rates (an upper
    // bound of the viscoplastic increments: from the right, where Newton
    // does not overshoot as long as the softening over the step is small);
    // (b) the old rates; (c) zero rates. Sets of Rankine planes alone try
    // (b) first: there the kappa_t softening over the rate-independent
    // increment makes (a) overshoot and stall (half of the tensile points
    // of bench_return_map), while (b) converges in a few iterations.
    const std::array<double, N> y0 = y;
    const bool old_first = !(set & (htc_surface | htc_edge | htc_apex));
    if (old_first)
    {
      // Multipliers from the closed-form return to the Rankine planes
      // frozen at the old strength and rate: (lambda 1 1^T + 2G I) mu =
      // sigma_k^tr - ft (one iteration fewer of the 4-5 from zero).
      from(y0, kcd_old, ktd_old);
      if (r1)
      {
        const double mu = rankine_1_multiplier(str[0], ktn, dt, true);
        y[0] = mu;
        y[M] = lc ? 0.0 : kcn; // no kappa_c flow
        y[M + 1] = std::log1p(c23 * mu / (dt * _d.rate_t.kdot0));
        ok = newton(lc, lt, true, y);
        if (!ok)
          from(y0, kcd_old, ktd_old);
      }
      if (!ok)
      {
        const double ft = tensile_strength(ktn, ktd_old);
        double sum = 0.0;
        for (int j = 0; j < M; ++j)
          sum += str[ids[j] - 2] - ft;
        sum /= 2.0 * _d.G + M * _d.lambda;
        for (int j = 0; j < M; ++j)
          y[j] = std::max(
              (str[ids[j] - 2] - ft - _d.lambda * sum) / (2.0 * _d.G), 0.0);
        ok = newton(lc, lt, true, y);
      }
    }
    // Edge sets: when the start (a) stalls with a negative multiplier, the
    // viscoplastic return has left the edge (the rate-independent one needed
    // it) and the reduced iteration crawls towards lam_HTC + lam_edge = 0,
    // where the signed flow norm jumps; (b) and (c) crawl there too (8% of
    // the viscoplastic points of bench_return_map, ~25 iterations each). They
    // are skipped: the full system (solve_full) finds the negative
    // multiplier and the drop/add loop removes the edge.
    bool crossed = false;
    if (!ok)
    {
      std::array<double, N> yp = y0;
      // Only a start: converged to 1e-6 (its last quadratic step,
      // 1e-6 -> 1e-12, does not change the viscoplastic root).
      if (newton(false, false, false, yp, std::max(_p.tolerance, 1e-6)))
      {
        // A small edge share of the rate-independent flow: the
        // viscoplastic return (less flow) most likely leaves the edge
        // (measured on bench_return_map: edge share >= 0.34 where the
        // edge stays active, mostly < 0.3 where it does not); the caller
        // tries the HTC alone first.
        if (probe_edge && set == (htc_surface | htc_edge) &&
            yp[1] < 0.3 * (yp[0] + yp[1]))
        {
          edge_left = true;
          return false;
        }
        from(yp, (yp[M] - kcn) / dt, (yp[M + 1] - ktn) / dt);
        ok = newton(lc, lt, true, y);
        if (!ok && (set & htc_edge))
          for (int j = 0; j < M; ++j)
            crossed = crossed || y[j] < 0.0;
      }
    }
    if (!ok && !old_first && !crossed)
    {
      from(y0, kcd_old, ktd_old);
      ok = newton(lc, lt, true, y);
    }
    if (!ok && !crossed && (kcd_old > 0.0 || ktd_old > 0.0))
    {
      from(y0, 0.0, 0.0);
      ok = newton(lc, lt, true, y);
    }
  }
  if (!ok && warm_set)
  {
    // Warm start from the solution of a neighbouring active set (the
    // drop/add loop changes one surface at a time): multipliers of the
    // common surfaces and its internal variables.
    std::array<double, N> yw{};
    int jw = 0;
    for (int k = 0; k < 6; ++k)
      if (warm_set & (1u << k))
      {
        for (int j = 0; j < M; ++j)
          if (ids[j] == k)
            yw[j] = std::max(warm[5 + jw], 0.0);
        ++jw;
      }
    lc = rates && _log_c;
    lt = rates && _log_t;
    yw[M] =
        lc ? std::log1p(std::max(warm[3] - kcn, 0.0) / (dt * _d.rate_c.kdot0))
           : warm[3];
    yw[M + 1] =
        lt ? std::log1p(std::max(warm[4] - ktn, 0.0) / (dt * _d.rate_t.kdot0))
           : warm[4];
    y = yw;
    ok = newton(lc, lt, rates, y);
  }
  if (!ok)
    return false;

  // Polishing step and consistent tangent. rd and sigd hold the residual,
  // the stresses and their derivatives with respect to y at the converged
  // y (the last evaluation of newton); one more evaluation, at fixed y with
  // the trial principal stresses as the variables, gives the derivatives
  // with respect to those (3 directions instead of N + 3).
  using DS = Dual<3>;
  std::array<DS, N> yS, rS;
  DS sS[3], sigS[3];
  for (int i = 0; i < N; ++i)
    yS[i] = DS(y[i]);
  for (int i = 0; i < 3; ++i)
    sS[i] = DS::variable(str[i], i);
  reduced<DS, M>(yS.data(), ids, sS, kcn, ktn, dt, lc, lt, rates, rS.data(),
                 sigS);
  for (int i = 0; i < N; ++i)
  {
    dy[i] = -rd[i].v;
    for (int j = 0; j < N; ++j)
      J[i * N + j] = rd[i].d[j];
  }
  if (!lu_factor<N>(J, piv))
    return false;
  lu_solve<N>(J, piv, dy);
  for (int i = 0; i < N; ++i)
    y[i] += dy[i];
  for (int c = 0; c < 3; ++c)
  {
    std::array<double, N> e;
    for (int i = 0; i < N; ++i)
      e[i] = rS[i].d[c];
    lu_solve<N>(J, piv, e); // dy/dstr_c = -e
    for (int i = 0; i < 3; ++i)
    {
      double s = sigS[i].d[c];
      for (int j = 0; j < N; ++j)
        s -= sigd[i].d[j] * e[j];
      dsig_dtr[i * 3 + c] = s;
    }
  }
  // Stresses at the polished y to first order (the step is ~tolerance: the
  // second-order term is far below round-off).
  xout = {};
  for (int i = 0; i < 3; ++i)
  {
    double s = sigd[i].v;
    for (int j = 0; j < N; ++j)
      s += sigd[i].d[j] * dy[j];
    xout[i] = s;
  }
  xout[3] = lc ? kcn + dt * _d.rate_c.kdot0 * std::expm1(y[M]) : y[M];
  xout[4] = lt ? ktn + dt * _d.rate_t.kdot0 * std::expm1(y[M + 1]) : y[M + 1];
  for (int j = 0; j < M; ++j)
    xout[5 + j] = y[j];
  return true;
}

unsigned
HtcConcrete::predict_set(const std::array<double, 3>& str, double kc, double kt,
                         const std::array<double, 5>& phi,
                         const std::array<std::array<double, 3>, 5>& n) const
{
  // Frozen surfaces (old internal variables, static rates): one
  // cutting-plane step per mechanism, closed form for the Rankine planes.
  const double tol = _p.tolerance * _d.fc0;
  const bool vh = phi[0] > tol, vr = phi[2] > tol;
  const double ft = str[0] - phi[2];
  const double a = _d.lambda + 2.0 * _d.G, l = _d.lambda;
  // Rankine return: number of planes and the returned stresses.
  unsigned rset = rankine_1;
  std::array<double, 3> sr;
  {
    const double mu = (str[0] - ft) / a;
    sr = {ft, str[1] - l * mu, str[2] - l * mu};
    if (sr[1] > ft)
    {
      rset |= rankine_2;
      // sigma_1 = sigma_2 = ft: mu1 + mu2 = (s1 + s2 - 2 ft) / (a + l)
      const double ms = (str[0] + str[1] - 2.0 * ft) / (a + l);
      sr = {ft, ft, str[2] - l * ms};
      if (sr[2] > ft)
      {
        rset |= rankine_3;
        sr = {ft, ft, ft};
      }
    }
  }
  // HTC cutting plane: Lambda = phi / (n . D n); edge if sigma_1 < sigma_2.
  unsigned hset = htc_surface;
  std::array<double, 3> sh = str;
  {
    const auto& g = n[0];
    const double tr = g[0] + g[1] + g[2];
    double Dn[3], nDn = 0;
    for (int i = 0; i < 3; ++i)
    {
      Dn[i] = l * tr + 2.0 * _d.G * g[i];
      nDn += g[i] * Dn[i];
    }
    const double lam = nDn > 0.0 ? std::max(phi[0], 0.0) / nDn : 0.0;
    for (int i = 0; i < 3; ++i)
      sh[i] = str[i] - lam * Dn[i];
    if (sh[0] < sh[1])
      hset |= htc_edge;
  }
  if (vr && !vh)
    return rset;
  if (vh && !vr)
    return hset;
  // Both violated: the Rankine return if it satisfies the HTC, the HTC
  // return if it satisfies the Rankine planes, else both.
  std::array<double, 5> ph;
  surfaces<double>(sr, kc, kt, 0.0, 0.0, ph, nullptr);
  if (std::max(ph[0], ph[1]) <= tol)
    return rset;
  const double sm = std::max(sh[0], sh[1]);
  if (sm <= ft)
    return hset;
  return hset & htc_edge ? (hset | rankine_1) : (htc_surface | rankine_1);
}

Update HtcConcrete::integrate(const State& old, const Vector6& de,
                              double dt) const
{
  Update u = integrate_step(old, de, dt);
  if (u.converged)
    return u;
  // Optional fall-back for the rare increments the single backward-Euler
  // step cannot solve (very large strain increments from softened states):
  // n equal sub-steps of de and dt, n = 2, 4, ..., max_substeps. The tangent of
  // the composite map is taken by central differences of the whole sub-stepped
  // map.
  auto substepped = [&](const Vector6& e, int n, Update& out) -> bool
  {
    Vector6 de_n;
    for (int i = 0; i < 6; ++i)
      de_n[i] = e[i] / n;
    State s = old;
    out.iterations = out.passes = 0;
    for (int k = 0; k < n; ++k)
    {
      const Update v = integrate_step(s, de_n, dt / n);
      out.iterations += v.iterations;
      out.passes += v.passes;
      if (!v.converged)
        return false;
      s = v.state;
      out.active |= v.active;
      out.tangent = v.tangent;
    }
    out.state = s;
    return true;
  };
  for (int n = 2; n <= _p.max_substeps; n *= 2)
  {
    Update w;
    if (!substepped(de, n, w))
    {
      u.iterations += w.iterations;
      u.passes += w.passes;
      continue;
    }
    w.iterations += u.iterations;
    w.passes += u.passes;
    w.substeps = n;
    double scale = 0;
    for (int i = 0; i < 6; ++i)
      scale = std::max(scale, std::abs(de[i]));
    const double h = 1e-6 * std::max(scale, 1e-6);
    bool fd_ok = true;
    for (int j = 0; j < 6 && fd_ok; ++j)
    {
      Vector6 ep = de, em = de;
      ep[j] += h;
      em[j] -= h;
      Update a, b;
      fd_ok = substepped(ep, n, a) && substepped(em, n, b);
      for (int i = 0; i < 6 && fd_ok; ++i)
        w.tangent[i * 6 + j] =
            (a.state.stress[i] - b.state.stress[i]) / (2.0 * h);
    }
    w.converged = true;
    return w;
  }
  return u;
}

Update HtcConcrete::integrate_step(const State& old, const Vector6& de,
                                   double dt) const
{
  Update u;
  u.state = old;
  const Matrix6 De = elastic_tangent();
  const Vector6 tr = trial_stress(old.stress, De, de);
  u.state.stress = tr;
  u.state.kappa_c_rate = u.state.kappa_t_rate = 0.0;
  u.tangent = De;
  if (_p.mode == Mode::elastic)
    return u;
  if (_rate_on && !(dt > 0.0))
    throw std::invalid_argument(
        "HtcConcrete::integrate: viscoplastic mode needs dt > 0");

  if (admissible(tr, old.kappa_c, old.kappa_t))
    return u; // elastic step
  std::array<double, 5> phi;

  std::array<double, 3> str;
  Eigen::Vector3d nv[3];
  principal_axes(tr, str, nv);
  std::array<std::array<double, 3>, 3> dir;
  for (int i = 0; i < 3; ++i)
    dir[i] = {nv[i][0], nv[i][1], nv[i][2]};
  std::array<std::array<double, 3>, 5> ng;
  surfaces<double>(str, old.kappa_c, old.kappa_t, 0.0, 0.0, phi, &ng);
  const unsigned set0 = predict_set(str, old.kappa_c, old.kappa_t, phi, ng);
  if (set0 == rankine_1)
  {
    // A crack opening: the return to the Rankine plane alone in closed form
    // where it is the answer (solve_set's start for this set, which its
    // Newton iteration confirms without an iteration).
    if (rankine_1_closed_form(old, tr, str, dir, dt, u))
    {
      u.passes = 1;
      return u;
    }
  }
  unsigned set = set0;

  std::array<double, 9> x{}, C{};
  const double tol_viol = 1e-8 * _d.fc0, tol_lam = -1e-13;
  std::uint64_t visited = 0; // bit s: set s already tried
  unsigned warm_set = 0;     // last set solved, and its solution
  std::array<double, 9> warm{};
  auto tried = [&](unsigned s) { return (visited >> s) & 1u; };
  bool probe_edge = _rate_on; // see solve_set

  // Solves one set and checks the Kuhn-Tucker conditions; returns 0 if
  // consistent, otherwise the next set to try (or 0xff if none).
  auto attempt = [&](unsigned s, bool patient, bool& consistent) -> unsigned
  {
    consistent = false;
    visited |= 1ull << s;
    ++u.passes;
    const int m = std::popcount(s);
    bool ok = false;
    const double kc = old.kappa_c, kt = old.kappa_t;
    const double kcd = old.kappa_c_rate, ktd = old.kappa_t_rate;
    const bool probe = probe_edge && !patient;
    bool edge_left = false;
    switch (m)
    {
    case 1:
      ok = solve_set<1>(s, str, kc, kt, kcd, ktd, dt, patient, warm_set, warm,
                        x, C, u.iterations, probe, edge_left);
      break;
    case 2:
      ok = solve_set<2>(s, str, kc, kt, kcd, ktd, dt, patient, warm_set, warm,
                        x, C, u.iterations, probe, edge_left);
      break;
    case 3:
      ok = solve_set<3>(s, str, kc, kt, kcd, ktd, dt, patient, warm_set, warm,
                        x, C, u.iterations, probe, edge_left);
      break;
    default:
      ok = solve_set<4>(s, str, kc, kt, kcd, ktd, dt, patient, warm_set, warm,
                        x, C, u.iterations, probe, edge_left);
    }
    if (edge_left)
    {
      // The HTC alone first; the edge set stays untried (the Kuhn-Tucker
      // check adds it back, then solved without the probe).
      probe_edge = false;
      visited &= ~(1ull << s);
      return unsigned(htc_surface);
    }
    const bool dependent =
        s == (htc_surface | htc_edge | rankine_1 | rankine_2);
    if (!ok && s != htc_apex && !dependent)
    {
      // Second line: the full (stresses, kappas, multipliers) system from
      // the old rates, then from zero rates.
      for (int a = 0; a < 2 && !ok; ++a)
      {
        const double c = a == 0 ? kcd : -1.0, t = a == 0 ? ktd : -1.0;
        switch (m)
        {
        case 1:
          ok = solve_full<1>(s, str, kc, kt, c, t, dt, x, C, u.iterations);
          break;
        case 2:
          ok = solve_full<2>(s, str, kc, kt, c, t, dt, x, C, u.iterations);
          break;
        case 3:
          ok = solve_full<3>(s, str, kc, kt, c, t, dt, x, C, u.iterations);
          break;
        default:
          ok = solve_full<4>(s, str, kc, kt, c, t, dt, x, C, u.iterations);
        }
        if (!_rate_on || (kcd <= 0.0 && ktd <= 0.0))
          break;
      }
    }
    if (!ok)
      return 0xffu;
    warm_set = s;
    warm = x;
    // Negative multipliers: drop the most negative one.
    int j = 0, worst = -1;
    double wl = tol_lam;
    for (int k = 0; k < 6; ++k)
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
    const double kcdn = _rate_on ? (x[3] - old.kappa_c) / dt : 0.0;
    const double ktdn = _rate_on ? (x[4] - old.kappa_t) / dt : 0.0;
    std::array<double, 5> ph;
    surfaces<double>({x[0], x[1], x[2]}, x[3], x[4], kcdn, ktdn, ph, nullptr);
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
  bool apex_tried = false;
  for (int pass = 0; pass < 6 && !consistent; ++pass)
  {
    unsigned next = attempt(set, false, consistent);
    if (consistent)
      break;
    if (next == 0xffu && (set & htc_edge) && !apex_tried)
    {
      // The edge set is singular at the apex (a near-hydrostatic tensile
      // trial state on a softened HTC): the apex set.
      next = htc_apex;
      apex_tried = true;
    }
    else if (next == 0xffu || !valid_set(next) || tried(next))
      break;
    set = next;
  }
  if (!consistent)
  {
    // Fall-back: every valid set, the likely ones first, without the early
    // exit of the Newton iteration.
    static constexpr unsigned order[11] = {
        rankine_1,
        htc_surface,
        htc_apex,
        htc_surface | htc_edge,
        rankine_1 | rankine_2,
        rankine_1 | rankine_2 | rankine_3,
        htc_surface | rankine_1,
        htc_surface | htc_edge | rankine_1,
        htc_surface | htc_edge | rankine_1 | rankine_2,
        htc_surface | rankine_1 | rankine_2,
        htc_surface | rankine_1 | rankine_2 | rankine_3};
    visited = 0;
    for (unsigned s : order)
    {
      attempt(s, true, consistent);
      if (consistent)
      {
        set = s;
        break;
      }
    }
  }
  if (!consistent)
  {
    u.converged = false;
    u.active = set0;
    return u;
  }

  // New state.
  u.active = set;
  State& ns = u.state;
  ns.stress = from_principal(x.data(), dir);
  ns.kappa_c = x[3];
  ns.kappa_t = x[4];
  ns.kappa_c_rate = dt > 0 ? (x[3] - old.kappa_c) / dt : 0.0;
  ns.kappa_t_rate = dt > 0 ? (x[4] - old.kappa_t) / dt : 0.0;
  add_plastic_strain(ns.plastic_strain, tr, ns.stress, _d.E, _d.nu, _d.G);

  // Consistent tangent: d(sigma)/d(sigma_tr) of the coaxial return (the
  // principal part from the converged Jacobian), times D.
  u.tangent = coaxial_tangent(C, str, x.data(), dir);
  return u;
}

Matrix6 HtcConcrete::coaxial_tangent(
    const std::array<double, 9>& C, const std::array<double, 3>& str,
    const double* x, const std::array<std::array<double, 3>, 3>& dir) const
{
  Eigen::Vector3d nv[3];
  for (int i = 0; i < 3; ++i)
    nv[i] = {dir[i][0], dir[i][1], dir[i][2]};
  Matrix6 T{};
  double CD[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
    {
      double s = 0;
      for (int k = 0; k < 3; ++k)
        s += C[i * 3 + k] * (_d.lambda + (k == j ? 2.0 * _d.G : 0.0));
      CD[i][j] = s;
    }
  // The rank-one terms over the nonzero components only (in-plane
  // directions have 4 of 6 components zero; skipping them only leaves out
  // additions of zero).
  Sparse6 Ev[3];
  for (int i = 0; i < 3; ++i)
    Ev[i] = Sparse6(outer_vec(nv[i], nv[i]));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int ka = 0; ka < Ev[i].n; ++ka)
      {
        const double fa = CD[i][j] * Ev[i].v[ka];
        double* row = &T[Ev[i].idx[ka] * 6];
        for (int kb = 0; kb < Ev[j].n; ++kb)
          row[Ev[j].idx[kb]] += fa * Ev[j].v[kb];
      }
  // Spin terms from the eigenvalue differences (de Souza Neto et al. 2008,
  // App. A).
  const int pairs[3][2] = {{0, 1}, {1, 2}, {0, 2}};
  for (const auto& pr : pairs)
  {
    const int i = pr[0], j = pr[1];
    const double dl = str[i] - str[j];
    const double scale = std::abs(str[i]) + std::abs(str[j]) + 1e-3 * _d.fc0;
    const double theta = std::abs(dl) > 1e-9 * scale
                             ? (x[i] - x[j]) / dl
                             : C[i * 3 + i] - C[i * 3 + j];
    const Sparse6 Mv(outer_vec(nv[i], nv[j])); // (n_i n_j^T + n_j n_i^T)/2
    // normalised M = (n_i n_j^T + n_j n_i^T)/sqrt(2) = sqrt(2) * Mv
    const double f = 2.0 * _d.G * theta * 2.0;
    for (int ka = 0; ka < Mv.n; ++ka)
    {
      const double fa = f * Mv.v[ka];
      double* row = &T[Mv.idx[ka] * 6];
      for (int kb = 0; kb < Mv.n; ++kb)
        row[Mv.idx[kb]] += fa * Mv.v[kb];
    }
  }
  return T;
}

bool HtcConcrete::rankine_1_tangent(
    double ft, double mu, double dt, const std::array<double, 3>& str,
    const double* x, const std::array<std::array<double, 3>, 3>& dir,
    Matrix6& T) const
{
  // sigma = str - mu D n1 with mu of the scalar consistency equation, which
  // only sigma_1's trial moves: d mu / d str_1 = 1 / (lambda + 2G +
  // dft/dmu).
  const double a1 = _d.lambda + 2.0 * _d.G, lam = _d.lambda;
  const double dft =
      ft *
      (-c23 / _d.kappa_tu +
       (_rate_on ? _d.rate_t.delta * c23 / (dt * _d.rate_t.kdot0 + c23 * mu)
                 : 0.0));
  const double den = a1 + dft;
  if (!(den > 0.0))
    return false;
  const std::array<double, 9> C = {
      1.0 - a1 / den, 0.0, 0.0, -lam / den, 1.0, 0.0, -lam / den, 0.0, 1.0};
  T = coaxial_tangent(C, str, x, dir);
  return true;
}

bool HtcConcrete::rankine_1_others_hold(const std::array<double, 3>& x,
                                        double kc, double ft) const
{
  // surfaces() at kappa_c = kc with zero rate and the kappa_t (and rate) of
  // strength ft; the HTC branches and sigma_2, sigma_3 <= ft within
  // integrate_step's tol_viol.
  const double tol_viol = 1e-8 * _d.fc0;
  std::array<double, 5> ph;
  const double fc = _d.fc0 * hc(kc), ifc = 1.0 / fc;
  surfaces_at<double>(x, ft, ifc, htc_of(ft, fc, ifc), ph, nullptr);
  return ph[0] <= tol_viol && ph[1] <= tol_viol && ph[3] <= tol_viol &&
         ph[4] <= tol_viol;
}

bool HtcConcrete::rankine_1_closed_form(
    const State& old, const Vector6& tr, const std::array<double, 3>& str,
    const std::array<std::array<double, 3>, 3>& dir, double dt, Update& u) const
{
  if (!_p.closed_form_tension || (_rate_on && (!(dt > 0.0) || !_log_t)))
    return false;
  const double lam = _d.lambda, a1 = lam + 2.0 * _d.G;
  const double kt0 = old.kappa_t, kc0 = old.kappa_c;
  double ft = 0.0;
  const double mu = rankine_1_multiplier(str[0], kt0, dt, _rate_on, 0.0,
                                         old_rate_multiplier(old, dt), &ft);
  if (!(mu > 0.0) || !std::isfinite(mu))
    return false;
  const std::array<double, 3> x = {str[0] - a1 * mu, str[1] - lam * mu,
                                   str[2] - lam * mu};
  // The Kuhn-Tucker check of integrate_step: converged to tol, the other
  // surfaces hold.
  if (std::abs(x[0] - ft) > _p.tolerance * _d.fc0 || x[1] > x[0] ||
      !rankine_1_others_hold(x, kc0, ft))
  {
    return false;
  }
  Matrix6 T;
  if (!rankine_1_tangent(ft, mu, dt, str, x.data(), dir, T))
    return false;
  u.state = old;
  State& ns = u.state;
  ns.stress = from_principal(x.data(), dir);
  ns.kappa_t = kt0 + c23 * mu;
  ns.kappa_t_rate = dt > 0.0 ? (ns.kappa_t - kt0) / dt : 0.0;
  ns.kappa_c_rate = 0.0;
  add_plastic_strain(ns.plastic_strain, tr, ns.stress, _d.E, _d.nu, _d.G);
  u.tangent = T;
  u.active = rankine_1;
  u.iterations = 0;
  u.converged = true;
  return true;
}

bool HtcConcrete::plane_stress_tension(const State& old, Vector6& de, double dt,
                                       Update& u) const
{
  if (_p.mode == Mode::elastic || old.stress[4] != 0.0 ||
      old.stress[5] != 0.0 || de[4] != 0.0 || de[5] != 0.0)
  {
    return false;
  }
  if (_rate_on && (!(dt > 0.0) || !_log_t))
    return false;
  const double E = _d.E, nu = _d.nu, lam = _d.lambda, G = _d.G;
  // In-plane trial with sigma_33 = 0 throughout (plane-stress elasticity).
  const double Ep = E / (1.0 - nu * nu);
  const double sx = old.stress[0] + Ep * (de[0] + nu * de[1]);
  const double sy = old.stress[1] + Ep * (nu * de[0] + de[1]);
  const double txy = old.stress[3] + G * de[3];
  const double c = 0.5 * (sx + sy), h = 0.5 * (sx - sy);
  const double r = std::hypot(h, txy);
  const double s1 = c + r, s2 = c - r;
  const double kt0 = old.kappa_t, kc0 = old.kappa_c;
  // The plane sigma_1 <= ft must be violated at the old strength (the
  // elastic-trial test decides elasticity; here only the set).
  const double ft_old = tensile_strength(kt0, 0.0);
  const double tol = _p.tolerance * _d.fc0;
  if (!(s1 - ft_old > tol) || s1 <= 0.0)
    return false;
  // First iterate: the old rate's multiplier (the crack opens at a
  // steady rate over a few steps; 3.9 instead of 5.8 iterations in the
  // Koyna viscoplastic run).
  double ft = 0.0;
  const double mu = rankine_1_multiplier(s1, kt0, dt, _rate_on, Ep,
                                         old_rate_multiplier(old, dt), &ft);
  if (!(mu > 0.0) || !std::isfinite(mu))
    return false;
  const double kt = kt0 + c23 * mu;
  const double ktd = dt > 0.0 ? (kt - kt0) / dt : 0.0;
  const double x1 = s1 - Ep * mu, x2 = s2 - nu * Ep * mu;
  // The consistency equation's residual (rankine_1_multiplier converges to
  // 1e-14 fc0) and the other surfaces at the result, as integrate_step's
  // Kuhn-Tucker check (tol_viol).
  if (std::abs(x1 - ft) > tol)
    return false;
  // (The principal stresses with sigma_33 = 0, descending.)
  if (!rankine_1_others_hold({x1, std::max(x2, 0.0), std::min(x2, 0.0)}, kc0,
                             ft))
  {
    return false;
  }

  // Tangent of the 3D return at this eps_33 (rankine_1_tangent): the trial
  // principal stresses (sigma_1, sigma_2, sigma_33) + mu D n1 n1.
  const double a1 = lam + 2.0 * G;
  const std::array<double, 3> str = {x1 + a1 * mu, x2 + lam * mu, lam * mu};
  // Direction of sigma_1 in the plane (as principal_axes), eps_33 and the
  // 3D trial at it: the stresses of the 3D return to the same plane.
  double nx = 1.0, ny = 0.0;
  if (r > 0.0)
  {
    nx = h >= 0.0 ? h + r : txy;
    ny = h >= 0.0 ? txy : r - h;
    const double n = std::hypot(nx, ny);
    nx /= n;
    ny /= n;
  }
  const std::array<double, 3> x3 = {x1, x2, 0.0};
  const std::array<std::array<double, 3>, 3> dir = {
      {{nx, ny, 0.0}, {-ny, nx, 0.0}, {0.0, 0.0, 1.0}}};
  Matrix6 T;
  if (!rankine_1_tangent(ft, mu, dt, str, x3.data(), dir, T))
    return false;
  // sigma_33 = lambda (tr de - mu) + 2G de_33 + sigma_33,old = 0 (the flow
  // n1 n1 has no 33 part and trace 1).
  de[2] = -(lam * (de[0] + de[1] - mu) + old.stress[2]) / (lam + 2.0 * G);
  const Vector6 tr = trial_stress(old.stress, elastic_tangent(), de);
  u = Update{};
  State& ns = u.state;
  ns = old;
  const double c2 = nx * nx, s2n = ny * ny, cs = nx * ny;
  ns.stress = {
      x1 * c2 + x2 * s2n, x1 * s2n + x2 * c2, 0.0, (x1 - x2) * cs, 0.0, 0.0};
  ns.kappa_t = kt;
  ns.kappa_c = kc0;
  ns.kappa_t_rate = ktd;
  ns.kappa_c_rate = 0.0;
  add_plastic_strain(ns.plastic_strain, tr, ns.stress, E, nu, G);
  u.tangent = T;
  u.active = rankine_1;
  u.iterations = 0;
  u.passes = 1;
  u.converged = true;
  return true;
}

bool HtcConcrete::admissible(const Vector6& stress, double kappa_c,
                             double kappa_t) const
{
  if (_p.mode == Mode::elastic)
    return true;
  const double tol_f = _p.tolerance * _d.fc0;
  double ft, ifc;
  std::array<double, 4> X;
  rest_strengths(kappa_c, kappa_t, ft, ifc, X);
  std::array<double, 5> phi;
  surfaces_at<double>(principal_fast(stress), ft, ifc, X, phi, nullptr);
  return phi[0] <= tol_f && phi[2] <= tol_f;
}

double HtcConcrete::admissible_radius(const Vector6& stress, double kappa_c,
                                      double kappa_t) const
{
  if (_p.mode == Mode::elastic)
    return HUGE_VAL;
  // The surfaces admissible() tests.
  double ft, ifc;
  std::array<double, 4> X;
  rest_strengths(kappa_c, kappa_t, ft, ifc, X);
  const std::array<double, 3> s = principal_fast(stress);
  std::array<double, 5> phi;
  surfaces_at<double>(s, ft, ifc, X, phi, nullptr);
  const double f0 = _d.fc0, tol_f = _p.tolerance * f0;
  const double I1 = s[0] + s[1] + s[2], m = I1 / 3.0;
  const double J2 = 0.5 * ((s[0] - m) * (s[0] - m) + (s[1] - m) * (s[1] - m) +
                           (s[2] - m) * (s[2] - m));
  const double q = std::sqrt(J2 + 1e-30 * f0 * f0);
  // Room to the surfaces admissible() tests (phi_HTC of sigma_1, and
  // sigma_1 - ft), less a guard of 1e-9 of the size of their terms for the
  // round-off of both evaluations.
  const double size = std::abs(X[0]) * J2 * ifc * ifc +
                      std::abs(X[1]) * q * ifc + std::abs(X[2] * s[0] * ifc) +
                      std::abs(X[3] * I1 * ifc) + 1.0;
  const double gH = tol_f - phi[0] - 1e-9 * f0 * size;
  const double gR = tol_f - phi[2] - 1e-9 * (std::abs(s[0]) + ft + f0);
  if (!(gH > 0.0 && gR > 0.0))
    return 0.0;
  // For |Delta|_F <= r: |Delta sigma_1| <= r (Weyl), |Delta I1| <= sqrt(3) r,
  // |Delta sqrt(J2 + eps)| <= r / sqrt(2) (its gradient is s / (2 q)), and
  // J2(sigma + Delta) - J2(sigma) <= sqrt(2 J2) r + r^2 / 2 (J2 = |s|^2 / 2,
  // the deviatoric part of Delta no longer than Delta). So phi_HTC grows by
  // at most a r^2 + b r, and sigma_1 - ft by at most r.
  const double a = 0.5 * f0 * std::abs(X[0]) * ifc * ifc;
  const double b = f0 * ifc *
                   (std::abs(X[0]) * ifc * std::sqrt(2.0 * J2) +
                    std::abs(X[1]) / std::sqrt(2.0) + std::abs(X[2]) +
                    std::sqrt(3.0) * std::abs(X[3]));
  const double rH = 2.0 * gH / (b + std::sqrt(b * b + 4.0 * a * gH));
  return (1.0 - 1e-9) * std::min(rH, gR);
}

Matrix6 HtcConcrete::elastic_tangent() const
{
  Matrix6 D{};
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
      D[i * 6 + j] = _d.lambda;
    D[i * 6 + i] += 2.0 * _d.G;
    D[(i + 3) * 6 + i + 3] = _d.G;
  }
  return D;
}

double HtcConcrete::compressive_strength(double kc, double kcd) const
{
  return _d.fc0 * hc(kc) * (_rate_on ? _d.rate_c(std::max(kcd, 0.0)) : 1.0);
}

double HtcConcrete::tensile_strength(double kt, double ktd) const
{
  return _d.ft0 * std::exp(-kt / _d.kappa_tu) *
         (_rate_on ? _d.rate_t(std::max(ktd, 0.0)) : 1.0);
}

HtcCoefficients HtcConcrete::htc_coefficients(double kc, double kt, double kcd,
                                              double ktd) const
{
  const double fc = compressive_strength(kc, kcd);
  const double ft = tensile_strength(kt, ktd);
  const double ftH = std::clamp((1.0 + _p.htc_tension_offset) * ft,
                                _p.rho_min * fc, _p.rho_max * fc);
  return _family.at(ftH / fc);
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
  return m / _d.fc0;
}

} // namespace damseis::material
