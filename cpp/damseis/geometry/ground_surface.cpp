#include "ground_surface.h"
#include <algorithm>
#include <cmath>
#include <damseis/linalg/all_gather.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/mesh/Mesh.h>
#include <dolfinx/mesh/MeshTags.h>
#include <dolfinx/mesh/utils.h>
#include <limits>
#include <stdexcept>

namespace damseis::geometry
{
namespace
{
/// The facets of the rock's upper surface on this rank (local indices).
std::vector<std::int32_t> surface_facets(const Model& model,
                                         const std::vector<int>& dam_regions,
                                         const std::vector<int>& excluded)
{
  auto& topology = model.mesh->topology_mutable();
  const int tdim = topology.dim();
  topology.create_entities(tdim - 1);
  topology.create_connectivity(tdim - 1, tdim);
  auto f_to_c = topology.connectivity(tdim - 1, tdim);
  const auto& cmap = *topology.index_map(tdim);
  std::vector<std::int8_t> dam(cmap.size_local() + cmap.num_ghosts(), 0);
  const auto& ct = *model.cell_tags;
  for (std::size_t i = 0; i < ct.indices().size(); ++i)
    if (std::find(dam_regions.begin(), dam_regions.end(), ct.values()[i]) !=
        dam_regions.end())
      dam[ct.indices()[i]] = 1;
  std::vector<std::int8_t> skip(f_to_c->num_nodes(), 0);
  const auto& ft = *model.facet_tags;
  for (std::size_t i = 0; i < ft.indices().size(); ++i)
    if (std::find(excluded.begin(), excluded.end(), ft.values()[i]) !=
        excluded.end())
      skip[ft.indices()[i]] = 1;
  const std::vector<std::int32_t> exterior =
      dolfinx::mesh::exterior_facet_indices(topology);
  std::vector<std::int8_t> is_exterior(f_to_c->num_nodes(), 0);
  for (std::int32_t f : exterior)
    is_exterior[f] = 1;
  // Owned facets only, so that the gathered surface does not depend on
  // the partition.
  const std::int32_t owned = topology.index_map(tdim - 1)->size_local();
  std::vector<std::int32_t> facets;
  for (std::int32_t f = 0; f < owned; ++f)
  {
    auto cells = f_to_c->links(f);
    int rock = 0, dams = 0;
    for (std::int32_t c : cells)
      (dam[c] ? dams : rock) += 1;
    if (rock == 1 && ((is_exterior[f] && !skip[f]) || dams == 1))
      facets.push_back(f);
  }
  return facets;
}
} // namespace

GroundSurface::GroundSurface(const Model& model,
                             const std::vector<int>& dam_regions,
                             const std::vector<int>& excluded)
{
  const auto& mesh = *model.mesh;
  _dim = mesh.geometry().dim();
  const std::vector<std::int32_t> facets =
      surface_facets(model, dam_regions, excluded);
  const auto g =
      dolfinx::mesh::entities_to_geometry(mesh, _dim - 1, facets, false);
  std::span<const double> x = mesh.geometry().x();
  std::vector<double> mine;
  mine.reserve(g.size() * 3);
  for (std::int32_t node : g)
    for (int k = 0; k < 3; ++k)
      mine.push_back(x[3 * node + k]);
  _x = linalg::all_gather(mesh.comm(), mine);
  _facets = _x.size() / (3 * _dim);
  if (_facets == 0)
    throw std::invalid_argument("the model has no rock surface: no "
                                "foundation facet is exterior or under the "
                                "dam");

  // The bucket grid: about one facet per bucket along each direction.
  const int nh = _dim - 1; // horizontal coordinates
  std::array<double, 2> hi{};
  for (int k = 0; k < nh; ++k)
  {
    _lo[k] = std::numeric_limits<double>::max();
    hi[k] = std::numeric_limits<double>::lowest();
  }
  for (std::size_t i = 0; i < _x.size() / 3; ++i)
    for (int k = 0; k < nh; ++k)
    {
      _lo[k] = std::min(_lo[k], _x[3 * i + k]);
      hi[k] = std::max(hi[k], _x[3 * i + k]);
    }
  const double per_side =
      nh == 1 ? double(_facets) : std::sqrt(double(_facets));
  for (int k = 0; k < nh; ++k)
  {
    _n[k] = std::clamp(static_cast<int>(per_side), 1, 4096);
    _h[k] = std::max(hi[k] - _lo[k], 1e-12) / _n[k];
  }
  _buckets.resize(static_cast<std::size_t>(_n[0]) * _n[1]);
  for (std::size_t f = 0; f < _facets; ++f)
  {
    std::array<int, 2> a{_n[0], _n[1]}, b{0, 0};
    for (int v = 0; v < _dim; ++v)
    {
      const std::array<int, 2> q = bucket_of(&_x[3 * (_dim * f + v)]);
      for (int k = 0; k < 2; ++k)
      {
        a[k] = std::min(a[k], q[k]);
        b[k] = std::max(b[k], q[k]);
      }
    }
    for (int i = a[0]; i <= b[0]; ++i)
      for (int j = a[1]; j <= b[1]; ++j)
        _buckets[static_cast<std::size_t>(i) * _n[1] + j].push_back(
            static_cast<std::int32_t>(f));
  }
}

std::array<int, 2> GroundSurface::bucket_of(const double* p) const
{
  std::array<int, 2> q{0, 0};
  for (int k = 0; k < _dim - 1; ++k)
    q[k] = std::clamp(static_cast<int>(std::floor((p[k] - _lo[k]) / _h[k])), 0,
                      _n[k] - 1);
  return q;
}

double GroundSurface::height(const std::array<double, 3>& p) const
{
  const std::array<int, 2> q = bucket_of(p.data());
  const auto& candidates =
      _buckets[static_cast<std::size_t>(q[0]) * _n[1] + q[1]];
  double best = std::numeric_limits<double>::lowest();
  bool found = false;
  const int z = _dim - 1;
  for (std::int32_t f : candidates)
  {
    const double* v = &_x[3 * _dim * f];
    if (_dim == 2)
    {
      const double x0 = v[0], x1 = v[3];
      const double len = x1 - x0;
      if (std::abs(len) < 1e-12)
        continue; // a vertical segment: its neighbours cover it
      const double s = (p[0] - x0) / len;
      if (s < -1e-9 || s > 1 + 1e-9)
        continue;
      best = std::max(best, (1 - s) * v[z] + s * v[3 + z]);
      found = true;
    }
    else
    {
      // Barycentric coordinates of (p0, p1) in the projected triangle.
      const double ax = v[0], ay = v[1], bx = v[3], by = v[4], cx = v[6],
                   cy = v[7];
      const double det = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
      const double scale = std::max(std::abs(bx - ax) + std::abs(cx - ax),
                                    std::abs(by - ay) + std::abs(cy - ay));
      if (std::abs(det) < 1e-12 * scale * scale)
        continue; // a vertical facet
      const double l1 =
          ((p[0] - ax) * (cy - ay) - (cx - ax) * (p[1] - ay)) / det;
      const double l2 =
          ((bx - ax) * (p[1] - ay) - (p[0] - ax) * (by - ay)) / det;
      const double l0 = 1 - l1 - l2;
      if (l0 < -1e-9 || l1 < -1e-9 || l2 < -1e-9)
        continue;
      best = std::max(best, l0 * v[2] + l1 * v[5] + l2 * v[8]);
      found = true;
    }
  }
  if (found)
    return best;
  // Off the surface's projection (round-off at the edge): the nearest
  // vertex's height.
  double d_min = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < _x.size() / 3; ++i)
  {
    double d = 0.0;
    for (int k = 0; k < _dim - 1; ++k)
      d += (_x[3 * i + k] - p[k]) * (_x[3 * i + k] - p[k]);
    if (d < d_min || (d == d_min && _x[3 * i + z] > best))
    {
      d_min = d;
      best = _x[3 * i + z];
    }
  }
  return best;
}
} // namespace damseis::geometry
