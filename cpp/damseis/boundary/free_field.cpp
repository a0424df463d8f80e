#include "free_field.h"
#include <algorithm>
#include <cmath>
#include <damseis/motion/baseline.h>
#include <damseis/motion/spectrum.h>
#include <stdexcept>

namespace damseis::boundary
{
namespace
{
/// Whether the final velocity and displacement of a record are within
/// 1e-3 of their peaks.
bool ends_at_rest(const std::vector<double>& a, double dt)
{
  if (a.empty())
    return true;
  std::vector<double> v, d;
  motion::integrate(a, dt, v, d);
  auto peak = [](const std::vector<double>& x)
  {
    double m = 0.0;
    for (double y : x)
      m = std::max(m, std::abs(y));
    return m;
  };
  return std::abs(v.back()) <= 1e-3 * peak(v) &&
         std::abs(d.back()) <= 1e-3 * peak(d);
}
} // namespace

SampledMotion::SampledMotion(std::vector<double> a, double dt, double t_start)
    : _a(std::move(a)), _dt(dt), _t0(t_start)
{
  if (!(dt > 0.0))
    throw std::invalid_argument("sampled motion: dt must be > 0");
  const std::size_t n = _a.size();
  _v.assign(n, 0.0);
  _d.assign(n, 0.0);
  for (std::size_t k = 1; k < n; ++k)
  {
    _v[k] = _v[k - 1] + 0.5 * dt * (_a[k - 1] + _a[k]);
    _d[k] =
        _d[k - 1] + dt * _v[k - 1] + dt * dt * (_a[k - 1] / 3.0 + _a[k] / 6.0);
  }
}

double SampledMotion::samples(double t) const
{
  const double s = (t - _t0) / _dt;
  const double nearest = std::round(s);
  return std::abs(s - nearest) < 1e-9 ? nearest : s;
}

std::size_t SampledMotion::interval(double s, double& tau) const
{
  const std::size_t last = _a.size() - 1;
  std::size_t k = static_cast<std::size_t>(std::floor(s));
  if (k >= last)
  {
    tau = (s - static_cast<double>(last)) * _dt;
    return last;
  }
  tau = (s - static_cast<double>(k)) * _dt;
  return k;
}

double SampledMotion::acceleration(double t) const
{
  const double s = samples(t);
  if (_a.empty() || s <= 0.0)
    return 0.0;
  double tau = 0.0;
  const std::size_t k = interval(s, tau);
  if (k + 1 >= _a.size())
    return tau == 0.0 ? _a[k] : 0.0;
  return _a[k] + (_a[k + 1] - _a[k]) * tau / _dt;
}

double SampledMotion::velocity(double t) const
{
  const double s = samples(t);
  if (_a.empty() || s <= 0.0)
    return 0.0;
  double tau = 0.0;
  const std::size_t k = interval(s, tau);
  if (k + 1 >= _a.size())
    return _v[k];
  const double da = (_a[k + 1] - _a[k]) / _dt;
  return _v[k] + _a[k] * tau + 0.5 * da * tau * tau;
}

double SampledMotion::displacement(double t) const
{
  const double s = samples(t);
  if (_a.empty() || s <= 0.0)
    return 0.0;
  double tau = 0.0;
  const std::size_t k = interval(s, tau);
  if (k + 1 >= _a.size())
    return _d[k] + _v[k] * tau;
  const double da = (_a[k + 1] - _a[k]) / _dt;
  return _d[k] + _v[k] * tau + 0.5 * _a[k] * tau * tau +
         da * tau * tau * tau / 6.0;
}

VerticalFreeField::VerticalFreeField(const Rock& rock, int dim, double z_base,
                                     double z_surface,
                                     std::array<SampledMotion, 3> incident)
    : _rock(rock), _dim(dim), _zb(z_base), _zs(z_surface),
      _incident(std::move(incident))
{
  if (dim != 2 && dim != 3)
    throw std::invalid_argument("free field: dimension 2 or 3");
  if (!(z_surface > z_base))
    throw std::invalid_argument(
        "free field: the free surface must be above the base");
  if (!(rock.rho > 0.0) || !(rock.E > 0.0))
    throw std::invalid_argument("free field: the rock needs E > 0, rho > 0");
}

std::array<SampledMotion, 3>
incident_from_outcrop(const Rock& rock, int dim, double depth,
                      const std::array<std::vector<double>, 3>& outcrop,
                      double dt, std::array<bool, 3>& corrected)
{
  return incident_from_outcrop(dim, depth / rock.cs(), depth / rock.cp(),
                               outcrop, dt, corrected);
}

std::array<SampledMotion, 3>
incident_from_outcrop(int dim, double s_time, double p_time,
                      const std::array<std::vector<double>, 3>& outcrop,
                      double dt, std::array<bool, 3>& corrected)
{
  std::array<SampledMotion, 3> incident;
  corrected = {};
  for (int i = 0; i < dim; ++i)
  {
    if (outcrop[i].empty())
      continue;
    std::vector<double> a = outcrop[i];
    if (!ends_at_rest(a, dt) && a.size() >= 8)
    {
      motion::remove_displacement_trend(a, dt);
      corrected[i] = true;
    }
    for (double& x : a)
      x *= 0.5;
    // Every component reaches the surface one S travel time late.
    const double delay = i == dim - 1 ? s_time - p_time : 0.0;
    incident[i] = SampledMotion(std::move(a), dt, delay);
  }
  return incident;
}

VerticalFreeField VerticalFreeField::from_outcrop(
    const Rock& rock, int dim, double z_base, double z_surface,
    const std::array<std::vector<double>, 3>& outcrop, double dt)
{
  std::array<bool, 3> corrected{};
  std::array<SampledMotion, 3> incident = incident_from_outcrop(
      rock, dim, z_surface - z_base, outcrop, dt, corrected);
  VerticalFreeField f(rock, dim, z_base, z_surface, std::move(incident));
  f._corrected = corrected;
  return f;
}

std::string VerticalFreeField::description() const
{
  return "vertically incident waves in a homogeneous half-space (c_s " +
         std::to_string(_rock.cs()) + " m/s, c_p " +
         std::to_string(_rock.cp()) + " m/s)";
}

FreeFieldState FreeField::incident(const std::array<double, 3>&, double) const
{
  throw std::logic_error("this free field does not give its incident wave "
                         "alone (a transmitting boundary needs it)");
}

FreeFieldState VerticalFreeField::incident(const std::array<double, 3>& x,
                                           double t) const
{
  FreeFieldState s;
  for (int i = 0; i < _dim; ++i)
  {
    const SampledMotion& w = _incident[i];
    if (w.empty())
      continue;
    const double t_up = arrivals(x[_dim - 1], _zs, t, i).up;
    s.u[i] = w.displacement(t_up);
    s.v[i] = w.velocity(t_up);
    s.a[i] = w.acceleration(t_up);
    s.s[i] = -_rock.rho * speed(i) * s.v[i];
  }
  return s;
}

std::string SideBySideFreeField::description() const
{
  return "two rocks side by side at x = " + std::to_string(_x) + ": " +
         _left->description() + " | " + _right->description();
}

VerticalFreeField::Arrivals VerticalFreeField::arrivals(double z, double zs,
                                                        double t, int i) const
{
  zs = std::max(zs, _zb);
  const double zc = std::min(z, zs); // above the surface: the surface's
  const double c = speed(i);
  return {t - (zc - _zb) / c, t - (2.0 * zs - zc - _zb) / c};
}

FreeFieldState VerticalFreeField::at(double z, double zs, double t) const
{
  FreeFieldState s;
  for (int i = 0; i < _dim; ++i)
  {
    const SampledMotion& w = _incident[i];
    if (w.empty())
      continue;
    const auto [t_up, t_dn] = arrivals(z, zs, t, i);
    s.u[i] = w.displacement(t_up) + w.displacement(t_dn);
    const double v_up = w.velocity(t_up), v_dn = w.velocity(t_dn);
    s.v[i] = v_up + v_dn;
    s.a[i] = w.acceleration(t_up) + w.acceleration(t_dn);
    s.s[i] = _rock.rho * speed(i) * (v_dn - v_up);
  }
  return s;
}

std::array<double, 3> VerticalFreeField::velocity(double z, double zs,
                                                  double t) const
{
  std::array<double, 3> v{};
  for (int i = 0; i < _dim; ++i)
  {
    const SampledMotion& w = _incident[i];
    if (w.empty())
      continue;
    const auto [t_up, t_dn] = arrivals(z, zs, t, i);
    v[i] = w.velocity(t_up) + w.velocity(t_dn);
  }
  return v;
}
} // namespace damseis::boundary
