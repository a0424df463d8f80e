#include "spectrum.h"
#include "message.h"
#include "record.h"
#include <algorithm>
#include <climits>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace damseis::motion
{
Sdof::Sdof(double period, double damping, double dt)
{
  require_argument(period > 0 && std::isfinite(period),
                   "SDOF period " + number_text(period) + " s must be > 0");
  require_argument(damping >= 0 && damping < 1, "damping ratio " +
                                                    number_text(damping) +
                                                    " must be in [0, 1)");
  require_argument(dt > 0 && std::isfinite(dt),
                   "time step " + number_text(dt) + " s must be > 0");
  // Nigam & Jennings (1969), "Calculation of response spectra from
  // strong-motion earthquake records", BSSA 59(2): the exact solution over
  // a step of u'' + 2 zeta w u' + w^2 u = -a(t), a linear in the step.
  const double w = 2.0 * std::numbers::pi / period, z = damping;
  w_ = w;
  zeta_ = z;
  const double s = std::sqrt(1.0 - z * z), wd = w * s;
  const double e = std::exp(-z * w * dt);
  const double sn = std::sin(wd * dt), cs = std::cos(wd * dt);
  const double w2 = w * w, w3 = w2 * w;
  a11 = e * (z / s * sn + cs);
  a12 = e * sn / wd;
  a21 = -w / s * e * sn;
  a22 = e * (cs - z / s * sn);
  const double c1 = (2 * z * z - 1) / (w2 * dt), c2 = 2 * z / (w3 * dt);
  b11 = e * ((c1 + z / w) * sn / wd + (c2 + 1 / w2) * cs) - c2;
  b12 = -e * (c1 * sn / wd + c2 * cs) - 1 / w2 + c2;
  b21 = e * ((c1 + z / w) * (cs - z / s * sn) -
             (c2 + 1 / w2) * (wd * sn + z * w * cs)) +
        1 / (w2 * dt);
  b22 = -e * (c1 * (cs - z / s * sn) - c2 * (wd * sn + z * w * cs)) -
        1 / (w2 * dt);
}

void Sdof::respond(std::span<const double> a, std::vector<double>& u,
                   std::vector<double>& v) const
{
  const std::size_t n = a.size();
  u.assign(n, 0.0);
  v.assign(n, 0.0);
  for (std::size_t k = 0; k + 1 < n; ++k)
  {
    u[k + 1] = a11 * u[k] + a12 * v[k] + b11 * a[k] + b12 * a[k + 1];
    v[k + 1] = a21 * u[k] + a22 * v[k] + b21 * a[k] + b22 * a[k + 1];
  }
}

long Sdof::advance(const double* x, long k0, long k_last, int substeps,
                   long stop, double& u, double& v, double* peak,
                   long* at) const
{
  long index = k0 * substeps;
  for (long k = k0; k < k_last && index < stop; ++k)
  {
    const double slope = (x[k + 1] - x[k]) / substeps;
    double a0 = x[k];
    for (int j = 1; j <= substeps && index < stop; ++j)
    {
      const double a1 = j == substeps ? x[k + 1] : x[k] + slope * j;
      const double un = a11 * u + a12 * v + b11 * a0 + b12 * a1;
      v = a21 * u + a22 * v + b21 * a0 + b22 * a1;
      u = un;
      a0 = a1;
      ++index;
      if (peak && std::abs(u) > *peak)
      {
        *peak = std::abs(u);
        *at = index;
      }
    }
  }
  return index;
}

double Sdof::peak_displacement(std::span<const double> a, int substeps) const
{
  double u = 0, v = 0, peak = 0;
  long at = 0;
  advance(a.data(), 0, static_cast<long>(a.size()) - 1, substeps, LONG_MAX, u,
          v, &peak, &at);
  // After the record the input is zero: free vibration from the last
  // state (records end at rest; a nonzero last sample is taken to drop to
  // zero, as a step).
  const double period = 2.0 * std::numbers::pi / w_;
  return std::max(peak, free_vibration_peak(u, v, period, zeta_));
}

int substeps_for(double period, double dt, int samples_per_period)
{
  const double wanted = std::ceil(samples_per_period * dt / period);
  require_argument(wanted <= 1e4, "period " + number_text(period) +
                                      " s is too short for the record's step " +
                                      number_text(dt) +
                                      " s; expected at least dt / 150");
  return std::max(1, static_cast<int>(wanted));
}

double free_vibration_peak(double u0, double v0, double period, double damping)
{
  const double w = 2.0 * std::numbers::pi / period, z = damping;
  const double s = std::sqrt(1.0 - z * z), wd = w * s;
  // u(t) = e^{-z w t} (u0 cos wd t + B sin wd t), B = (v0 + z w u0) / wd;
  // v(t) = e^{-z w t} (v0 cos wd t - (w u0 + z v0) / s sin wd t).
  const double b = (v0 + z * w * u0) / wd;
  const double c = (w * u0 + z * v0) / s;
  // First t > 0 with v = 0: tan(wd t) = v0 / c, in (0, pi / wd].
  double phase = std::atan2(v0, c);
  if (phase <= 0)
    phase += std::numbers::pi;
  const double t = phase / wd;
  const double ut =
      std::exp(-z * w * t) * (u0 * std::cos(wd * t) + b * std::sin(wd * t));
  return std::max(std::abs(u0), std::abs(ut));
}

Spectrum response_spectrum(std::span<const double> a, double dt,
                           std::span<const double> periods, double damping,
                           int samples_per_period)
{
  require_argument(samples_per_period >= 1, "samples per period must be >= 1");
  require_argument(dt > 0 && std::isfinite(dt),
                   "time step " + number_text(dt) + " s must be > 0");
  require_argument(damping >= 0 && damping < 1, "damping ratio " +
                                                    number_text(damping) +
                                                    " must be in [0, 1)");
  Spectrum s;
  double pga = 0;
  for (double x : a)
    pga = std::max(pga, std::abs(x));
  for (double period : periods)
  {
    require_argument(period >= 0 && std::isfinite(period),
                     "period " + number_text(period) + " s must be >= 0");
    s.period.push_back(period);
    if (period == 0)
    {
      s.sd.push_back(0);
      s.psv.push_back(0);
      s.psa.push_back(pga);
      continue;
    }
    const double w = 2.0 * std::numbers::pi / period;
    const int substeps = substeps_for(period, dt, samples_per_period);
    const double d =
        Sdof(period, damping, dt / substeps).peak_displacement(a, substeps);
    s.sd.push_back(d);
    s.psv.push_back(w * d);
    s.psa.push_back(w * w * d);
  }
  return s;
}

std::vector<double> log_spaced(double t_min, double t_max, int n)
{
  require_argument(t_min > 0 && t_max > t_min && std::isfinite(t_max) && n >= 2,
                   "log_spaced: need 0 < t_min < t_max and n >= 2");
  std::vector<double> t(static_cast<std::size_t>(n));
  const double r = std::log(t_max / t_min) / (n - 1);
  for (int i = 0; i < n; ++i)
    t[static_cast<std::size_t>(i)] = t_min * std::exp(r * i);
  t.back() = t_max;
  return t;
}

void integrate(std::span<const double> a, double dt, std::vector<double>& v,
               std::vector<double>& d)
{
  const std::size_t n = a.size();
  v.assign(n, 0.0);
  d.assign(n, 0.0);
  for (std::size_t k = 0; k + 1 < n; ++k)
  {
    v[k + 1] = v[k] + 0.5 * dt * (a[k] + a[k + 1]);
    d[k + 1] = d[k] + dt * v[k] + dt * dt * (a[k] / 3.0 + a[k + 1] / 6.0);
  }
}

Measures measures(std::span<const double> a, double dt)
{
  require_argument(dt > 0 && std::isfinite(dt),
                   "time step " + number_text(dt) + " s must be > 0");
  Measures m;
  std::vector<double> v, d;
  integrate(a, dt, v, d);
  for (std::size_t k = 0; k < a.size(); ++k)
  {
    m.pga = std::max(m.pga, std::abs(a[k]));
    m.pgv = std::max(m.pgv, std::abs(v[k]));
    m.pgd = std::max(m.pgd, std::abs(d[k]));
  }
  if (!a.empty())
  {
    m.final_velocity = v.back();
    m.final_displacement = d.back();
  }
  // Arias intensity: int a^2 dt exact for linear a over each step.
  std::vector<double> cumulative(a.size(), 0.0);
  for (std::size_t k = 0; k + 1 < a.size(); ++k)
    cumulative[k + 1] =
        cumulative[k] +
        dt / 3.0 * (a[k] * a[k] + a[k] * a[k + 1] + a[k + 1] * a[k + 1]);
  const double total = a.empty() ? 0.0 : cumulative.back();
  m.arias = std::numbers::pi / (2.0 * standard_gravity) * total;
  if (total > 0)
  {
    // Times where the cumulative intensity reaches 5% and 95% (linear
    // between samples).
    auto time_at = [&](double fraction)
    {
      const double target = fraction * total;
      const auto it =
          std::lower_bound(cumulative.begin(), cumulative.end(), target);
      const auto k = static_cast<std::size_t>(it - cumulative.begin());
      if (k == 0)
        return 0.0;
      const double c0 = cumulative[k - 1], c1 = cumulative[k];
      return dt * (static_cast<double>(k - 1) + (target - c0) / (c1 - c0));
    };
    m.t5 = time_at(0.05);
    m.t95 = time_at(0.95);
    m.significant_duration = m.t95 - m.t5;
  }
  return m;
}
} // namespace damseis::motion
