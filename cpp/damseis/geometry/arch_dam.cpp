// Parametric double-curvature arch dam in a canyon: definition,
// evaluation and reference integrals.
#include "arch_dam.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

namespace damseis::geometry
{
namespace
{
constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180.0;
/// Largest tangent angle of a ring (the centre line is a graph over x).
constexpr double theta_max = 89.5 * deg;

std::string str(double v)
{
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

[[noreturn]] void fail(const std::string& field, const std::string& what)
{
  throw std::invalid_argument(field + ": " + what);
}

void require(bool ok, const std::string& field, const std::string& what)
{
  if (!ok)
    fail(field, what);
}

/// Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n).
struct Gauss
{
  std::vector<double> x, w;
  explicit Gauss(int n)
  {
    x.resize(n);
    w.resize(n);
    for (int i = 0; i < n; ++i)
    {
      double t = std::cos(pi * (i + 0.75) / (n + 0.5));
      double dp = 1;
      for (int it = 0; it < 100; ++it)
      {
        double p0 = 1, p1 = t;
        for (int k = 2; k <= n; ++k)
        {
          const double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (t * p1 - p0) / (t * t - 1);
        const double dt = p1 / dp;
        t -= dt;
        if (std::abs(dt) < 1e-15)
          break;
      }
      x[i] = t;
      w[i] = 2 / ((1 - t * t) * dp * dp);
    }
  }
  /// Integral of f over [a, b] split into m equal parts.
  double integrate(const std::function<double(double)>& f, double a, double b,
                   int m = 1) const
  {
    double s = 0;
    const double h = (b - a) / m;
    for (int j = 0; j < m; ++j)
    {
      const double c = a + (j + 0.5) * h;
      for (std::size_t i = 0; i < x.size(); ++i)
        s += 0.5 * h * w[i] * f(c + 0.5 * h * x[i]);
    }
    return s;
  }
};

const Gauss& gauss()
{
  static const Gauss g(16);
  return g;
}

/// Root of a monotone f on [a, b] by bisection (f(a), f(b) of opposite
/// signs; otherwise the end with the smaller |f|).
double bisect(const std::function<double(double)>& f, double a, double b)
{
  double fa = f(a), fb = f(b);
  if (fa * fb > 0)
    return std::abs(fa) < std::abs(fb) ? a : b;
  for (int it = 0; it < 200 and b - a > 1e-15 * (1 + std::abs(a)); ++it)
  {
    const double m = 0.5 * (a + b);
    const double fm = f(m);
    if ((fm <= 0) == (fa <= 0))
    {
      a = m;
      fa = fm;
    }
    else
      b = m;
  }
  return 0.5 * (a + b);
}

/// Integral over [a, b] with break points `cuts` (those inside) and about
/// `nmax` equal sub-intervals in total.
double integrate_pieces(const std::function<double(double)>& f, double a,
                        double b, std::vector<double> cuts, int nmax)
{
  cuts.push_back(a);
  cuts.push_back(b);
  std::sort(cuts.begin(), cuts.end());
  double s = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
  {
    const double lo = std::max(a, cuts[i]), hi = std::min(b, cuts[i + 1]);
    if (hi - lo <= 1e-14 * (1 + std::abs(b - a)))
      continue;
    const int m = std::max(1, int(std::ceil(nmax * (hi - lo) / (b - a))));
    s += gauss().integrate(f, lo, hi, m);
  }
  return s;
}
} // namespace

//-----------------------------------------------------------------------------
LevelTable::LevelTable(std::vector<double> z, std::vector<double> y,
                       LevelInterpolation kind)
    : _z(std::move(z)), _y(std::move(y)),
      _cubic(kind == LevelInterpolation::cubic)
{
  const std::size_t n = _z.size();
  _m.assign(n, 0.0);
  if (!_cubic or n < 3)
    return;
  // Natural cubic spline: tridiagonal system for the second derivatives
  std::vector<double> a(n, 0), b(n, 1), c(n, 0), r(n, 0);
  for (std::size_t i = 1; i + 1 < n; ++i)
  {
    const double h0 = _z[i] - _z[i - 1], h1 = _z[i + 1] - _z[i];
    a[i] = h0 / 6;
    b[i] = (h0 + h1) / 3;
    c[i] = h1 / 6;
    r[i] = (_y[i + 1] - _y[i]) / h1 - (_y[i] - _y[i - 1]) / h0;
  }
  for (std::size_t i = 1; i < n; ++i)
  {
    const double f = a[i] / b[i - 1];
    b[i] -= f * c[i - 1];
    r[i] -= f * r[i - 1];
  }
  _m[n - 1] = r[n - 1] / b[n - 1];
  for (std::size_t i = n - 1; i-- > 0;)
    _m[i] = (r[i] - c[i] * _m[i + 1]) / b[i];
}
//-----------------------------------------------------------------------------
double LevelTable::operator()(double z) const
{
  const std::size_t n = _z.size();
  if (n == 1)
    return _y[0];
  auto slope_at = [&](std::size_t i, bool left_end)
  {
    const double h = _z[i + 1] - _z[i];
    const double d = (_y[i + 1] - _y[i]) / h;
    return left_end ? d - h * (2 * _m[i] + _m[i + 1]) / 6
                    : d + h * (_m[i] + 2 * _m[i + 1]) / 6;
  };
  if (z <= _z[0])
    return _y[0] + slope_at(0, true) * (z - _z[0]);
  if (z >= _z[n - 1])
    return _y[n - 1] + slope_at(n - 2, false) * (z - _z[n - 1]);
  const std::size_t i = std::min<std::size_t>(
      n - 2, std::upper_bound(_z.begin(), _z.end(), z) - _z.begin() - 1);
  const double h = _z[i + 1] - _z[i];
  const double t = (z - _z[i]) / h, u = 1 - t;
  double v = u * _y[i] + t * _y[i + 1];
  if (_cubic)
    v -= h * h / 6 * t * u * ((1 + u) * _m[i] + (1 + t) * _m[i + 1]);
  return v;
}

//-----------------------------------------------------------------------------
ArchDamGeometry::ArchDamGeometry(const ArchDamDefinition& def) : _def(def)
{
  const ArchDamShape& d = _def.dam;
  const CanyonDefinition& c = _def.canyon;
  require(std::isfinite(d.height) and d.height > 0, "dam.height",
          "must be positive, got " + str(d.height));
  const double H = d.height;
  const std::size_t n = d.levels.size();
  require(n >= 2, "dam.levels", "at least two levels are needed");
  require(std::abs(d.levels.front()) <= 1e-9 * H and
              std::abs(d.levels.back() - H) <= 1e-9 * H,
          "dam.levels",
          "must start at 0 and end at dam.height (" + str(H) + ")");
  for (std::size_t i = 0; i + 1 < n; ++i)
    require(d.levels[i + 1] > d.levels[i], "dam.levels",
            "must be strictly increasing");
  auto table = [&](const std::vector<double>& v, const std::string& name)
  {
    require(v.size() == n, name,
            "needs one value per level (" + std::to_string(n) + "), got " +
                std::to_string(v.size()));
    for (double x : v)
      require(std::isfinite(x), name, "values must be finite");
    return LevelTable(d.levels, v, d.interpolation);
  };
  _yu = table(d.crown_upstream_y, "dam.crown_upstream_y");
  _tc = table(d.crown_thickness, "dam.crown_thickness");
  _ta = table(d.abutment_thickness, "dam.abutment_thickness");
  _rc = table(d.radius_central, "dam.radius_central");
  if (d.shape == ArchShape::three_centred)
  {
    _rl = table(d.radius_lateral, "dam.radius_lateral");
    _phi = table(d.central_angle_deg, "dam.central_angle");
  }
  require(std::isfinite(d.thickening_exponent) and d.thickening_exponent > 0,
          "dam.thickening_exponent", "must be positive");

  // Canyon polyline
  if (c.shape == CanyonShape::v or c.shape == CanyonShape::u)
  {
    require(std::isfinite(c.bottom_width) and c.bottom_width > 0,
            "canyon.bottom_width", "must be positive");
    require(std::isfinite(c.crest_width) and c.crest_width > c.bottom_width,
            "canyon.crest_width", "must exceed canyon.bottom_width");
  }
  const double b2 = 0.5 * c.bottom_width, w2 = 0.5 * c.crest_width;
  if (c.shape == CanyonShape::v)
    _canyon = {{0, -b2, b2}, {H, -w2, w2}};
  else if (c.shape == CanyonShape::u)
  {
    const double R = c.u_radius;
    require(std::isfinite(R) and R > 0 and R < H, "canyon.u_radius",
            "must be positive and below dam.height");
    require(w2 > b2 + R, "canyon.u_radius",
            "the fillets do not fit: need crest_width > bottom_width + "
            "2 u_radius");
    require(c.u_segments >= 1, "canyon.u_segments", "must be >= 1");
    // Wall angle beta from the vertical so that X(H) = w2 (bisection)
    auto f = [&](double beta)
    {
      return b2 + R * std::cos(beta) +
             std::tan(beta) * (H - R + R * std::sin(beta)) - w2;
    };
    const double beta = bisect(f, 0, 0.5 * pi - 1e-9);
    _canyon.push_back({0, -b2, b2});
    for (int i = 1; i <= c.u_segments; ++i)
    {
      const double a = (0.5 * pi - beta) * i / c.u_segments;
      const double x = b2 + R * std::sin(a), z = R - R * std::cos(a);
      _canyon.push_back({z, -x, x});
    }
    _canyon.push_back({H, -w2, w2});
  }
  else
  {
    require(c.z.size() >= 2 and c.x_left.size() == c.z.size() and
                c.x_right.size() == c.z.size(),
            "canyon.z",
            "canyon.z, canyon.x_left, canyon.x_right need the "
            "same length (>= 2)");
    require(std::abs(c.z.front()) <= 1e-9 * H, "canyon.z", "must start at 0");
    require(c.z.back() >= H * (1 - 1e-9), "canyon.z", "must reach dam.height");
    for (std::size_t i = 0; i < c.z.size(); ++i)
    {
      require(i == 0 or c.z[i] > c.z[i - 1], "canyon.z",
              "must be strictly increasing");
      require(c.x_left[i] < 0, "canyon.x_left", "values must be < 0");
      require(c.x_right[i] > 0, "canyon.x_right", "values must be > 0");
      _canyon.push_back({c.z[i], c.x_left[i], c.x_right[i]});
    }
  }
  validate();
}
//-----------------------------------------------------------------------------
double ArchDamGeometry::x_left(double z) const
{
  const auto& p = _canyon;
  if (z <= p.front()[0])
    return p.front()[1];
  std::size_t i = 0;
  while (i + 2 < p.size() and z > p[i + 1][0])
    ++i;
  const double t = (z - p[i][0]) / (p[i + 1][0] - p[i][0]);
  return p[i][1] + t * (p[i + 1][1] - p[i][1]);
}
//-----------------------------------------------------------------------------
double ArchDamGeometry::x_right(double z) const
{
  const auto& p = _canyon;
  if (z <= p.front()[0])
    return p.front()[2];
  std::size_t i = 0;
  while (i + 2 < p.size() and z > p[i + 1][0])
    ++i;
  const double t = (z - p[i][0]) / (p[i + 1][0] - p[i][0]);
  return p[i][2] + t * (p[i + 1][2] - p[i][2]);
}
//-----------------------------------------------------------------------------
ArchDamGeometry::Ring ArchDamGeometry::ring(double z) const
{
  Ring r;
  r.t_c = _tc(z);
  r.t_a = _ta(z);
  r.y_c = _yu(z) + 0.5 * r.t_c;
  r.r_c = _rc(z);
  const bool tc = _def.dam.shape == ArchShape::three_centred;
  r.r_l = tc ? _rl(z) : r.r_c;
  r.phi_c = tc ? _phi(z) * deg : pi;
  return r;
}
//-----------------------------------------------------------------------------
std::array<double, 2> ArchDamGeometry::centre(double z, double theta) const
{
  const Ring r = ring(z);
  const double s = theta < 0 ? -1 : 1;
  const double t = std::abs(theta);
  double x, y;
  if (_def.dam.shape == ArchShape::parabolic)
  {
    x = r.r_c * std::tan(t);
    y = 0.5 * x * x / r.r_c;
  }
  else if (t <= r.phi_c)
  {
    x = r.r_c * std::sin(t);
    y = r.r_c * (1 - std::cos(t));
  }
  else
  {
    x = r.r_c * std::sin(r.phi_c) + r.r_l * (std::sin(t) - std::sin(r.phi_c));
    y = r.r_c * (1 - std::cos(r.phi_c)) +
        r.r_l * (std::cos(r.phi_c) - std::cos(t));
  }
  return {s * x, r.y_c + y};
}
//-----------------------------------------------------------------------------
double ArchDamGeometry::curvature_radius(double z, double theta) const
{
  const Ring r = ring(z);
  const double t = std::abs(theta);
  if (_def.dam.shape == ArchShape::parabolic)
    return r.r_c / std::pow(std::cos(t), 3);
  return t <= r.phi_c ? r.r_c : r.r_l;
}
//-----------------------------------------------------------------------------
double ArchDamGeometry::thickness(double z, double theta) const
{
  const Ring r = ring(z);
  const double x = centre(z, theta)[0];
  const double X = x < 0 ? -x_left(z) : x_right(z);
  const double xi = std::abs(x) / X;
  const double p = _def.dam.thickening_exponent;
  // Beyond the wall (inside the rock): C1 linear continuation
  const double f = xi <= 1 ? std::pow(xi, p) : 1 + p * (xi - 1);
  return r.t_c + (r.t_a - r.t_c) * f;
}
//-----------------------------------------------------------------------------
std::array<double, 3> ArchDamGeometry::face_point(double z, double theta,
                                                  int side) const
{
  const auto c = centre(z, theta);
  const double h = side == 0 ? 0.0 : 0.5 * side * thickness(z, theta);
  // Downstream normal (-sin, cos)
  return {c[0] - h * std::sin(theta), c[1] + h * std::cos(theta), z};
}
//-----------------------------------------------------------------------------
double ArchDamGeometry::theta_at_x(double z, double x) const
{
  return bisect([&](double t) { return centre(z, t)[0] - x; }, -theta_max,
                theta_max);
}
//-----------------------------------------------------------------------------
double ArchDamGeometry::face_theta_at_x(double z, double x, int side) const
{
  // Bracket around the centre-line theta at x (the face is offset by at
  // most T/2 from the centre line)
  const double t0 = theta_at_x(z, x);
  const double dt =
      std::min(1.0, 0.75 * thickness(z, t0) / curvature_radius(z, t0) + 0.05);
  return bisect([&](double t) { return face_point(z, t, side)[0] - x; },
                std::max(-theta_max, t0 - dt), std::min(theta_max, t0 + dt));
}
//-----------------------------------------------------------------------------
std::array<double, 2> ArchDamGeometry::offset(double z, double x,
                                              double y) const
{
  // Foot of the normal: (p - c(theta)) . t(theta) = 0, decreasing in theta
  const double t = bisect(
      [&](double th)
      {
        const auto c = centre(z, th);
        return (x - c[0]) * std::cos(th) + (y - c[1]) * std::sin(th);
      },
      -theta_max, theta_max);
  const auto c = centre(z, t);
  return {-(x - c[0]) * std::sin(t) + (y - c[1]) * std::cos(t), t};
}
//-----------------------------------------------------------------------------
std::array<double, 2> ArchDamGeometry::loft_theta_range(double z,
                                                        double margin) const
{
  const double zl = std::max(z, 0.0);
  const double xl = x_left(zl) - margin, xr = x_right(zl) + margin;
  return {std::min(face_theta_at_x(z, xl, -1), face_theta_at_x(z, xl, 1)),
          std::max(face_theta_at_x(z, xr, -1), face_theta_at_x(z, xr, 1))};
}
//-----------------------------------------------------------------------------
double ArchDamGeometry::section_area(double z) const
{
  const double xl = x_left(z), xr = x_right(z);
  const Ring r = ring(z);
  std::vector<double> cuts = {0.0};
  if (_def.dam.shape == ArchShape::three_centred)
    cuts = {-r.phi_c, 0.0, r.phi_c};
  const double h = 1e-7;
  // 1/2 (x dy - y dx) along a face, theta from a to b
  auto face = [&](int side, double a, double b)
  {
    auto f = [&](double t)
    {
      const auto p = face_point(z, t, side);
      const auto p1 = face_point(z, t + h, side);
      const auto p0 = face_point(z, t - h, side);
      const double dx = (p1[0] - p0[0]) / (2 * h),
                   dy = (p1[1] - p0[1]) / (2 * h);
      return 0.5 * (p[0] * dy - p[1] * dx);
    };
    return a < b ? integrate_pieces(f, a, b, cuts, 16)
                 : -integrate_pieces(f, b, a, cuts, 16);
  };
  const double ul = face_theta_at_x(z, xl, -1), ur = face_theta_at_x(z, xr, -1);
  const double dl = face_theta_at_x(z, xl, 1), dr = face_theta_at_x(z, xr, 1);
  const auto pur = face_point(z, ur, -1), pdr = face_point(z, dr, 1);
  const auto pdl = face_point(z, dl, 1), pul = face_point(z, ul, -1);
  auto seg = [](const std::array<double, 3>& p, const std::array<double, 3>& q)
  { return 0.5 * (p[0] * q[1] - q[0] * p[1]); };
  return face(-1, ul, ur) + seg(pur, pdr) + face(1, dr, dl) + seg(pdl, pul);
}
//-----------------------------------------------------------------------------
namespace
{
/// Break points in z: dam levels and canyon polyline points.
std::vector<double> z_cuts(const ArchDamDefinition& d,
                           const std::vector<std::array<double, 3>>& canyon)
{
  std::vector<double> c = d.dam.levels;
  for (const auto& p : canyon)
    c.push_back(p[0]);
  return c;
}
} // namespace
//-----------------------------------------------------------------------------
double ArchDamGeometry::volume() const
{
  return integrate_pieces([&](double z) { return section_area(z); }, 0,
                          height(), z_cuts(_def, _canyon), 24);
}
//-----------------------------------------------------------------------------
double ArchDamGeometry::face_area(int side, double z_top) const
{
  const double h = 1e-7, hz = 1e-6 * height();
  auto row = [&](double z)
  {
    const Ring r = ring(z);
    std::vector<double> cuts = {0.0};
    if (_def.dam.shape == ArchShape::three_centred)
      cuts = {-r.phi_c, 0.0, r.phi_c};
    const double a = face_theta_at_x(z, x_left(z), side);
    const double b = face_theta_at_x(z, x_right(z), side);
    auto f = [&](double t)
    {
      const auto t1 = face_point(z, t + h, side),
                 t0 = face_point(z, t - h, side);
      // z derivative one-sided at the ends of [0, H]
      const double za = std::max(0.0, z - hz), zb = std::min(height(), z + hz);
      const auto z1 = face_point(zb, t, side), z0 = face_point(za, t, side);
      std::array<double, 3> u, v;
      for (int k = 0; k < 3; ++k)
      {
        u[k] = (t1[k] - t0[k]) / (2 * h);
        v[k] = (z1[k] - z0[k]) / (zb - za);
      }
      const double cx = u[1] * v[2] - u[2] * v[1],
                   cy = u[2] * v[0] - u[0] * v[2],
                   cz = u[0] * v[1] - u[1] * v[0];
      return std::sqrt(cx * cx + cy * cy + cz * cz);
    };
    return integrate_pieces(f, a, b, cuts, 16);
  };
  const double top = z_top >= 0 ? std::min(z_top, height()) : height();
  return integrate_pieces(row, 0, top, z_cuts(_def, _canyon), 24);
}
//-----------------------------------------------------------------------------
double ArchDamGeometry::min_face_radius() const
{
  double rmin = 1e300;
  const double H = height();
  for (int i = 0; i <= 50; ++i)
  {
    const double z = H * i / 50.0;
    const double a = theta_at_x(z, x_left(z)), b = theta_at_x(z, x_right(z));
    for (int j = 0; j <= 50; ++j)
    {
      const double t = a + (b - a) * j / 50.0;
      rmin = std::min(rmin, curvature_radius(z, t) - 0.5 * thickness(z, t));
    }
    // Vertical curvature of the crown cantilever (upstream face)
    const double hz = 1e-3 * H;
    const double za = std::clamp(z, hz, H - hz);
    const double d2 = (_yu(za + hz) - 2 * _yu(za) + _yu(za - hz)) / (hz * hz);
    if (std::abs(d2) > 0)
      rmin = std::min(rmin, 1 / std::abs(d2));
  }
  return rmin;
}
//-----------------------------------------------------------------------------
double ArchDamGeometry::crest_length() const
{
  const double H = height();
  const double a = theta_at_x(H, x_left(H)), b = theta_at_x(H, x_right(H));
  const Ring r = ring(H);
  std::vector<double> cuts = {0.0};
  if (_def.dam.shape == ArchShape::three_centred)
    cuts = {-r.phi_c, 0.0, r.phi_c};
  return integrate_pieces([&](double t) { return curvature_radius(H, t); }, a,
                          b, cuts, 16);
}
//-----------------------------------------------------------------------------
std::vector<JointPlane> ArchDamGeometry::joint_planes() const
{
  const JointDefinition& j = _def.joints;
  std::vector<double> f = j.positions;
  if (f.empty())
    for (int k = 0; k < j.count; ++k)
      f.push_back((k + 1.0) / (j.count + 1.0));
  const double H = height();
  const double a = theta_at_x(H, x_left(H));
  const double b = theta_at_x(H, x_right(H));
  const double L = crest_length();
  const Ring r = ring(H);
  std::vector<double> cuts = {0.0};
  if (_def.dam.shape == ArchShape::three_centred)
    cuts = {-r.phi_c, 0.0, r.phi_c};
  std::vector<JointPlane> out;
  for (std::size_t k = 0; k < f.size(); ++k)
  {
    const char label = joint_label(int(k));
    if (!j.active.empty() and j.active.find(label) == std::string::npos)
      continue;
    const double t = bisect(
        [&](double th)
        {
          return integrate_pieces([&](double s)
                                  { return curvature_radius(H, s); },
                                  a, th, cuts, 16) -
                 f[k] * L;
        },
        a, b);
    JointPlane p;
    p.label_index = int(k);
    p.label = label;
    p.fraction = f[k];
    const auto c = centre(H, t);
    p.point = {c[0], c[1], H};
    p.normal = {std::cos(t), std::sin(t), 0.0};
    out.push_back(p);
  }
  return out;
}
//-----------------------------------------------------------------------------
void ArchDamGeometry::validate() const
{
  const ArchDamDefinition& d = _def;
  const double H = height();
  const bool tc = d.dam.shape == ArchShape::three_centred;
  // Canyon: crown inside, walls of a valley widening upwards
  for (const auto& p : _canyon)
    require(p[1] < 0 and p[2] > 0, "canyon",
            "the walls must be on either side of x = 0 (the crown) at z = " +
                str(p[0]));
  // Level tables, sampled
  for (int i = 0; i <= 200; ++i)
  {
    const double z = -0.05 * H + 1.1 * H * i / 200.0;
    const Ring r = ring(z);
    // (Messages are built only on failure: this loop runs 200 levels.)
    auto at = [&] { return " (interpolated at z = " + str(z) + ")"; };
    if (!(r.t_c > 0))
      fail("dam.crown_thickness", "must be positive" + at());
    if (!(r.t_a > 0))
      fail("dam.abutment_thickness", "must be positive" + at());
    if (!(r.r_c > 0))
      fail("dam.radius_central", "must be positive" + at());
    if (tc && !(r.r_l > 0))
      fail("dam.radius_lateral", "must be positive" + at());
    if (tc && !(r.phi_c > 0 and r.phi_c < theta_max))
      fail("dam.central_angle", "must be in (0, 89.5) degrees" + at());
    if (z < 0 or z > H)
      continue;
    // The centre line must reach both walls with a tangent below 89.5 deg
    const double xr = centre(z, theta_max)[0];
    if (!(xr > x_right(z) + 0.5 * r.t_a))
      fail("dam.radius_lateral",
           "the arch at z = " + str(z) +
               " does not reach the canyon walls (centre line bends back "
               "before x = " +
               str(x_right(z)) + "); increase the radii");
    if (!(-xr < x_left(z) - 0.5 * r.t_a))
      fail("dam.radius_lateral",
           "the arch at z = " + str(z) +
               " does not reach the left canyon wall; increase the radii");
    const double a = theta_at_x(z, x_left(z)), b = theta_at_x(z, x_right(z));
    for (int side : {-1, 1})
    {
      double xprev = -1e300;
      for (int j = 0; j <= 80; ++j)
      {
        const double t = a - 0.1 + (b - a + 0.2) * j / 80.0;
        const double xf = face_point(z, t, side)[0];
        if (!(xf > xprev))
          fail("dam.abutment_thickness",
               "the " + std::string(side < 0 ? "upstream" : "downstream") +
                   " face at z = " + str(z) +
                   " folds back near the walls (thickening too fast "
                   "for the radius of curvature)");
        xprev = xf;
      }
    }
    for (int j = 0; j <= 40; ++j)
    {
      const double t = a + (b - a) * j / 40.0;
      if (!(0.5 * thickness(z, t) < 0.9 * curvature_radius(z, t)))
        fail(tc ? "dam.radius_lateral" : "dam.radius_central",
             "the radius of curvature at z = " + str(z) +
                 " is smaller than half the thickness (the downstream "
                 "face folds)");
    }
  }
  const FoundationDefinition& f = d.foundation;
  for (auto [v, n] : {std::pair{f.upstream, "foundation.upstream"},
                      {f.downstream, "foundation.downstream"},
                      {f.below, "foundation.below"},
                      {f.beyond, "foundation.beyond"}})
    require(std::isfinite(v) and v > 0, n, "must be positive");
  const JointDefinition& j = d.joints;
  require(j.count >= 0 and j.count <= 26, "joints.count",
          "must be in 0 ... 26");
  require(j.positions.size() <= 26, "joints.positions",
          "at most 26 positions (labels A ... Z)");
  for (std::size_t k = 0; k < j.positions.size(); ++k)
    require(j.positions[k] > 0 and j.positions[k] < 1 and
                (k == 0 or j.positions[k] > j.positions[k - 1]),
            "joints.positions",
            "fractions of the crest length must be increasing in (0, 1)");
  const std::size_t ncand = j.positions.empty() ? j.count : j.positions.size();
  for (std::size_t i = 0; i < j.active.size(); ++i)
  {
    const char ch = j.active[i];
    require(ch >= 'A' and ch < char('A' + ncand), "joints.active",
            std::string("label '") + ch + "' is not one of the " +
                std::to_string(ncand) + " candidate positions");
    require(j.active.find(ch) == i, "joints.active",
            std::string("label '") + ch + "' repeated");
  }
  const ArchMeshOptions& m = d.mesh;
  require(std::isfinite(m.size) and m.size > 0, "mesh.size",
          "must be positive");
  require(std::isfinite(m.size_far) and m.size_far >= 0, "mesh.size_far",
          "must be >= 0");
  require(std::isfinite(m.grading_distance) and m.grading_distance > 0,
          "mesh.grading_distance", "must be positive");
  require(m.dam_layers >= 0, "mesh.dam_layers", "must be >= 0");
  require(m.sections == 0 or m.sections >= 3, "mesh.sections",
          "must be 0 (automatic) or >= 3");
  require(m.arch_points >= 5, "mesh.arch_points", "must be >= 5");
}
//-----------------------------------------------------------------------------
ModelBox model_box(const ArchDamGeometry& g)
{
  const double H = g.height();
  // Dam extents in y (inside the canyon), sampled on both faces.
  double ymin = 1e300, ymax = -1e300;
  for (int i = 0; i <= 40; ++i)
  {
    const double z = H * i / 40.0;
    for (int side : {-1, 1})
    {
      const double a = g.face_theta_at_x(z, g.x_left(z), side);
      const double b = g.face_theta_at_x(z, g.x_right(z), side);
      for (int k = 0; k <= 40; ++k)
      {
        const auto p = g.face_point(z, a + (b - a) * k / 40.0, side);
        ymin = std::min(ymin, p[1]);
        ymax = std::max(ymax, p[1]);
      }
    }
  }
  const FoundationDefinition& f = g.definition().foundation;
  return {g.x_left(H) - f.beyond * H,
          g.x_right(H) + f.beyond * H,
          ymin - f.upstream * H,
          ymax + f.downstream * H,
          -f.below * H,
          H};
}
//-----------------------------------------------------------------------------
double distance_from_model(const ArchDamGeometry& g,
                           const std::array<double, 3>& p)
{
  // The point clamped into the model box, then: in the rock, 0; in the
  // valley (water or air), the distance to the dam body (along the
  // centre-line normal) or to the nearer wall or the floor. A point outside
  // the box adds its distance to the box (Pythagoras: the two offsets are
  // nearly orthogonal).
  const ModelBox b = model_box(g);
  const double x = std::clamp(p[0], b.x0, b.x1);
  const double y = std::clamp(p[1], b.y0, b.y1);
  const double z = std::clamp(p[2], b.z0, b.z1);
  const double outside = std::hypot(p[0] - x, p[1] - y, p[2] - z);
  double inside = 0.0;
  const double left = x - g.x_left(z), right = g.x_right(z) - x;
  if (z > 0 && left > 0 && right > 0)
  {
    const auto [off, theta] = g.offset(z, x, y);
    const double to_dam = std::abs(off) - 0.5 * g.thickness(z, theta);
    inside = std::max(0.0, std::min({to_dam, left, right, z}));
  }
  return std::hypot(outside, inside);
}
} // namespace damseis::geometry
