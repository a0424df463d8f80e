#include "layered_column.h"
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace damseis::boundary
{
LayeredColumn::LayeredColumn(double z_base, const std::vector<Layer>& layers,
                             int dim,
                             const std::array<SampledMotion, 3>& incident,
                             double dt, int steps, double h_max)
    : _dim(dim), _steps(steps), _layers(layers.size())
{
  if (layers.empty() || !(h_max > 0.0) || !(dt > 0.0) || steps < 0 ||
      (dim != 2 && dim != 3))
    throw std::invalid_argument("layered column: needs layers, h_max > 0, "
                                "dt > 0, steps >= 0, dimension 2 or 3");
  // Nodes: each layer cut into equal elements of at most h_max.
  _z.push_back(z_base);
  std::vector<const Rock*> element_rock;
  double c_max = 0.0, h_min = HUGE_VAL;
  for (const Layer& l : layers)
  {
    const double bottom = _z.back();
    if (!(l.top > bottom))
      throw std::invalid_argument("layered column: layer tops must rise");
    const int n = static_cast<int>(std::ceil((l.top - bottom) / h_max));
    const double h = (l.top - bottom) / n;
    for (int i = 1; i <= n; ++i)
    {
      _z.push_back(i == n ? l.top : bottom + i * h);
      element_rock.push_back(&l.rock);
    }
    c_max = std::max(c_max, l.rock.cp());
    h_min = std::min(h_min, h);
    _delay += (l.top - bottom) / l.rock.cs();
  }
  // Sub-steps: a step no longer than a wave's crossing of an element.
  _m = std::max(1, static_cast<int>(std::ceil(dt * c_max / h_min)));
  const double stored = 3.0 * dim * _z.size() * (steps + 1.0);
  if (stored > 2e8 || double(_m) * steps * _z.size() > 1e11)
    throw std::invalid_argument(
        "layered column: " + std::to_string(_z.size()) + " nodes, " +
        std::to_string(_m) +
        " sub-steps per step: too large; the layers' "
        "rock is too soft or too varied for the record's time step");
  const Rock& bottom_rock = layers.front().rock;
  for (int c = 0; c < dim; ++c)
  {
    if (incident[c].empty())
      continue;
    _active[c] = true;
    const bool vertical = c == dim - 1;
    std::vector<double> modulus, density;
    for (const Rock* r : element_rock)
    {
      modulus.push_back(vertical ? r->p_modulus() : r->G());
      density.push_back(r->rho);
    }
    const double rho_c =
        bottom_rock.rho * (vertical ? bottom_rock.cp() : bottom_rock.cs());
    solve(c, modulus, density, incident[c], rho_c, dt);
  }
}

LayeredColumn LayeredColumn::from_outcrop(
    double z_base, const std::vector<Layer>& layers, int dim,
    const std::array<std::vector<double>, 3>& outcrop, double dt, int steps)
{
  if (layers.empty())
    throw std::invalid_argument("layered column: no layers");
  std::array<bool, 3> corrected{};
  double s_time = 0.0, p_time = 0.0, bottom = z_base;
  for (const Layer& l : layers)
  {
    s_time += (l.top - bottom) / l.rock.cs();
    p_time += (l.top - bottom) / l.rock.cp();
    bottom = l.top;
  }
  const std::array<SampledMotion, 3> incident =
      incident_from_outcrop(dim, s_time, p_time, outcrop, dt, corrected);
  double cs_min = HUGE_VAL;
  for (const Layer& l : layers)
    cs_min = std::min(cs_min, l.rock.cs());
  LayeredColumn column(z_base, layers, dim, incident, dt, steps,
                       cs_min / 25.0 / 20.0);
  column._corrected = corrected;
  return column;
}

std::string LayeredColumn::description() const
{
  return "vertically incident waves in " + std::to_string(_layers) +
         " horizontal rock layers (a 1D column of " +
         std::to_string(_z.size()) + " nodes)";
}

void LayeredColumn::solve(int c, const std::vector<double>& modulus,
                          const std::vector<double>& density,
                          const SampledMotion& wave, double rho_c_bottom,
                          double dt)
{
  const int n = static_cast<int>(_z.size());
  // Consistent mass and stiffness of linear elements (per unit area).
  std::vector<Eigen::Triplet<double>> mt, kt;
  for (int e = 0; e + 1 < n; ++e)
  {
    const double h = _z[e + 1] - _z[e];
    const double m = density[e] * h / 6.0, k = modulus[e] / h;
    for (auto [i, j, mv, kv] :
         {std::tuple{e, e, 2 * m, k}, std::tuple{e + 1, e + 1, 2 * m, k},
          std::tuple{e, e + 1, m, -k}, std::tuple{e + 1, e, m, -k}})
    {
      mt.emplace_back(i, j, mv);
      kt.emplace_back(i, j, kv);
    }
  }
  Eigen::SparseMatrix<double> M(n, n), K(n, n), C(n, n);
  M.setFromTriplets(mt.begin(), mt.end());
  K.setFromTriplets(kt.begin(), kt.end());
  C.insert(0, 0) = rho_c_bottom; // the half-space below: a dashpot
  const double h = dt / _m, beta = 0.25, gamma = 0.5;
  Eigen::SparseMatrix<double> A = M + gamma * h * C + beta * h * h * K;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> lu(A);
  if (lu.info() != Eigen::Success)
    throw std::runtime_error("layered column: factorisation failed");
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n), v = u, a = u, f = u;
  auto store = [&](int k)
  {
    for (int i = 0; i < n; ++i)
    {
      _u[c][static_cast<std::size_t>(k) * n + i] = u[i];
      _v[c][static_cast<std::size_t>(k) * n + i] = v[i];
      _a[c][static_cast<std::size_t>(k) * n + i] = a[i];
      // Nodal stress: the mean of the adjacent elements' (0 at the top).
      double s = 0.0;
      if (i + 1 < n)
      {
        const double below =
            modulus[i] * (u[i + 1] - u[i]) / (_z[i + 1] - _z[i]);
        const double above =
            i > 0 ? modulus[i - 1] * (u[i] - u[i - 1]) / (_z[i] - _z[i - 1])
                  : below;
        s = 0.5 * (below + above);
      }
      _s[c][static_cast<std::size_t>(k) * n + i] = s;
    }
  };
  const std::size_t size = static_cast<std::size_t>(_steps + 1) * n;
  _u[c].assign(size, 0.0);
  _v[c].assign(size, 0.0);
  _a[c].assign(size, 0.0);
  _s[c].assign(size, 0.0);
  store(0);
  for (int k = 0; k < _steps; ++k)
    for (int j = 1; j <= _m; ++j)
    {
      const double t = k * dt + j * h;
      f.setZero();
      f[0] = 2.0 * rho_c_bottom * wave.velocity(t);
      const Eigen::VectorXd ut = u + h * v + 0.5 * h * h * (1 - 2 * beta) * a;
      const Eigen::VectorXd vt = v + (1 - gamma) * h * a;
      a = lu.solve(f - C * vt - K * ut);
      u = ut + beta * h * h * a;
      v = vt + gamma * h * a;
      if (j == _m)
        store(k + 1);
    }
}

FreeFieldState LayeredColumn::at(double z, int k) const
{
  FreeFieldState s;
  k = std::clamp(k, 0, _steps);
  const int n = static_cast<int>(_z.size());
  z = std::clamp(z, _z.front(), _z.back());
  const int e = std::clamp(
      static_cast<int>(std::upper_bound(_z.begin(), _z.end(), z) - _z.begin()) -
          1,
      0, n - 2);
  const double w = (z - _z[e]) / (_z[e + 1] - _z[e]);
  const std::size_t base = static_cast<std::size_t>(k) * n;
  for (int c = 0; c < _dim; ++c)
  {
    if (!_active[c])
      continue;
    auto lerp = [&](const std::vector<double>& x)
    { return (1 - w) * x[base + e] + w * x[base + e + 1]; };
    s.u[c] = lerp(_u[c]);
    s.v[c] = lerp(_v[c]);
    s.a[c] = lerp(_a[c]);
    s.s[c] = lerp(_s[c]);
  }
  return s;
}
} // namespace damseis::boundary
