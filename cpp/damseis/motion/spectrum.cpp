#include "spectrum.h"
#include "message.h"
#include "record.h"
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
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

SdofBank::SdofBank(std::span<const double> periods, double damping, double dt,
                   int substeps)
    : _substeps(substeps)
{
  require_argument(substeps >= 1, "substeps must be >= 1");
  for (double period : periods)
  {
    const Sdof s(period, damping, dt / substeps);
    _a11.push_back(s.a11);
    _a12.push_back(s.a12);
    _a21.push_back(s.a21);
    _a22.push_back(s.a22);
    _b11.push_back(s.b11);
    _b12.push_back(s.b12);
    _b21.push_back(s.b21);
    _b22.push_back(s.b22);
  }
}

SdofBank::Peaks SdofBank::peaks(std::span<const double> a) const
{
  const std::size_t m = size();
  Peaks p;
  p.peak.assign(m, 0.0);
  p.u_at_peak.assign(m, 0.0);
  p.u_end.assign(m, 0.0);
  p.v_end.assign(m, 0.0);
  p.at.assign(m, 0);
  double* u = p.u_end.data();
  double* v = p.v_end.data();
  long index = 0;
  for (std::size_t k = 0; k + 1 < a.size(); ++k)
  {
    const double slope = (a[k + 1] - a[k]) / _substeps;
    double a0 = a[k];
    for (int j = 1; j <= _substeps; ++j)
    {
      const double a1 = j == _substeps ? a[k + 1] : a[k] + slope * j;
      ++index;
      for (std::size_t i = 0; i < m; ++i)
      {
        const double un =
            _a11[i] * u[i] + _a12[i] * v[i] + _b11[i] * a0 + _b12[i] * a1;
        v[i] = _a21[i] * u[i] + _a22[i] * v[i] + _b21[i] * a0 + _b22[i] * a1;
        u[i] = un;
        if (std::abs(un) > p.peak[i])
        {
          p.peak[i] = std::abs(un);
          p.u_at_peak[i] = un;
          p.at[i] = index;
        }
      }
      a0 = a1;
    }
  }
  return p;
}

void SdofBank::run_to(const double* x, long k0, long k_last,
                      std::span<const std::size_t> which,
                      std::span<const long> stop, std::span<double> u,
                      std::span<double> v, std::span<long> reached) const
{
  // The selected oscillators in order of their stops, with their
  // coefficients side by side: those still running are the tail
  // [first, n) of these arrays.
  const std::size_t n = which.size();
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return stop[i] < stop[j]; });
  std::vector<double> c(8 * n), us(n, 0.0), vs(n, 0.0);
  std::vector<long> stops(n);
  for (std::size_t r = 0; r < n; ++r)
  {
    const std::size_t o = which[order[r]];
    const double values[8] = {_a11[o], _a12[o], _a21[o], _a22[o],
                              _b11[o], _b12[o], _b21[o], _b22[o]};
    for (int q = 0; q < 8; ++q)
      c[static_cast<std::size_t>(q) * n + r] = values[q];
    stops[r] = stop[order[r]];
  }
  const double *c11 = c.data(), *c12 = c11 + n, *c21 = c12 + n, *c22 = c21 + n,
               *d11 = c22 + n, *d12 = d11 + n, *d21 = d12 + n, *d22 = d21 + n;
  double* u_ = us.data();
  double* v_ = vs.data();
  long index = k0 * _substeps;
  std::vector<long> reached_sorted(n, index);
  std::size_t first = 0;
  auto retire = [&]
  {
    while (first < n && stops[first] <= index)
      reached_sorted[first++] = index;
  };
  retire();
  for (long k = k0; k < k_last && first < n; ++k)
  {
    const double slope = (x[k + 1] - x[k]) / _substeps;
    double a0 = x[k];
    for (int j = 1; j <= _substeps && first < n; ++j)
    {
      const double a1 = j == _substeps ? x[k + 1] : x[k] + slope * j;
      for (std::size_t i = first; i < n; ++i)
      {
        const double un =
            c11[i] * u_[i] + c12[i] * v_[i] + d11[i] * a0 + d12[i] * a1;
        v_[i] = c21[i] * u_[i] + c22[i] * v_[i] + d21[i] * a0 + d22[i] * a1;
        u_[i] = un;
      }
      a0 = a1;
      ++index;
      retire();
    }
  }
  for (std::size_t r = first; r < n; ++r)
    reached_sorted[r] = index;
  for (std::size_t r = 0; r < n; ++r)
  {
    u[order[r]] = us[r];
    v[order[r]] = vs[r];
    reached[order[r]] = reached_sorted[r];
  }
}

SdofBanks::SdofBanks(std::span<const double> periods, double damping, double dt,
                     int samples_per_period)
{
  std::map<int, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < periods.size(); ++i)
    groups[substeps_for(periods[i], dt, samples_per_period)].push_back(i);
  for (const auto& [substeps, group] : groups)
  {
    std::vector<double> t;
    for (std::size_t i : group)
      t.push_back(periods[i]);
    banks.emplace_back(t, damping, dt, substeps);
    members.push_back(group);
  }
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

double free_vibration_displacement(double u0, double v0, double period,
                                   double damping, double t)
{
  // u(t) = e^{-z w t} (u0 cos wd t + B sin wd t), B = (v0 + z w u0) / wd.
  const double w = 2.0 * std::numbers::pi / period, z = damping;
  const double wd = w * std::sqrt(1.0 - z * z);
  return std::exp(-z * w * t) *
         (u0 * std::cos(wd * t) + (v0 + z * w * u0) / wd * std::sin(wd * t));
}

double free_vibration_peak(double u0, double v0, double period, double damping)
{
  const double w = 2.0 * std::numbers::pi / period, z = damping;
  const double s = std::sqrt(1.0 - z * z), wd = w * s;
  // v(t) = e^{-z w t} (v0 cos wd t - (w u0 + z v0) / s sin wd t); its first
  // zero t > 0: tan(wd t) = v0 / c, in (0, pi / wd].
  const double c = (w * u0 + z * v0) / s;
  double phase = std::atan2(v0, c);
  if (phase <= 0)
    phase += std::numbers::pi;
  const double ut =
      free_vibration_displacement(u0, v0, period, damping, phase / wd);
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
  const std::size_t n = periods.size();
  s.period.assign(periods.begin(), periods.end());
  s.sd.assign(n, 0.0);
  std::vector<double> positive;
  std::vector<std::size_t> index;
  for (std::size_t i = 0; i < n; ++i)
  {
    require_argument(periods[i] >= 0 && std::isfinite(periods[i]),
                     "period " + number_text(periods[i]) + " s must be >= 0");
    if (periods[i] > 0)
    {
      positive.push_back(periods[i]);
      index.push_back(i);
    }
  }
  const SdofBanks banks(positive, damping, dt, samples_per_period);
  for (std::size_t b = 0; b < banks.banks.size(); ++b)
  {
    const SdofBank::Peaks p = banks.banks[b].peaks(a);
    // After the record the input is zero: free vibration from the last
    // state (records end at rest; a nonzero last sample is taken to drop
    // to zero, as a step).
    for (std::size_t r = 0; r < banks.members[b].size(); ++r)
    {
      const std::size_t i = banks.members[b][r];
      s.sd[index[i]] =
          std::max(p.peak[r], free_vibration_peak(p.u_end[r], p.v_end[r],
                                                  positive[i], damping));
    }
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    const double w = periods[i] > 0 ? 2.0 * std::numbers::pi / periods[i] : 0;
    s.psv.push_back(w * s.sd[i]);
    s.psa.push_back(periods[i] > 0 ? w * w * s.sd[i] : pga);
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
