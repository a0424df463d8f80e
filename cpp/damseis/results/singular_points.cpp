#include "singular_points.h"
#include <algorithm>
#include <cmath>
#include <damseis/linalg/all_gather.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/mesh/Mesh.h>
#include <dolfinx/mesh/MeshTags.h>
#include <dolfinx/mesh/utils.h>
#include <limits>
#include <set>

namespace damseis::results
{
std::vector<Point3> reflex_corners(std::span<const Point3> polygon,
                                   std::span<const int> always)
{
  std::vector<Point3> out;
  const int n = static_cast<int>(polygon.size());
  for (int i = 0; i < n; ++i)
  {
    const Point3& a = polygon[(i + n - 1) % n];
    const Point3& b = polygon[i];
    const Point3& c = polygon[(i + 1) % n];
    // Counterclockwise polygon: a clockwise turn at b is a reflex corner.
    const double cross =
        (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]);
    const bool listed =
        std::find(always.begin(), always.end(), i) != always.end();
    if (listed || cross < 0.0)
      out.push_back(b);
  }
  return out;
}

std::vector<Point3> meeting_points(const geometry::Model& model,
                                   std::span<const int> face_tags,
                                   int interface_tag)
{
  const auto& mesh = *model.mesh;
  const int fdim = mesh.topology().dim() - 1;
  const auto& tags = *model.facet_tags;
  std::vector<std::int32_t> face_facets, interface_facets;
  for (std::size_t i = 0; i < tags.indices().size(); ++i)
  {
    const int v = tags.values()[i];
    if (std::find(face_tags.begin(), face_tags.end(), v) != face_tags.end())
      face_facets.push_back(tags.indices()[i]);
    else if (v == interface_tag)
      interface_facets.push_back(tags.indices()[i]);
  }
  auto nodes_of = [&](const std::vector<std::int32_t>& facets)
  {
    const auto g =
        dolfinx::mesh::entities_to_geometry(mesh, fdim, facets, false);
    return std::set<std::int32_t>(g.begin(), g.end());
  };
  const auto a = nodes_of(face_facets), b = nodes_of(interface_facets);
  std::vector<double> local;
  const auto x = mesh.geometry().x();
  for (std::int32_t n : a)
  {
    if (b.count(n))
      local.insert(local.end(), {x[3 * n], x[3 * n + 1], x[3 * n + 2]});
  }
  // Gather on every rank.
  const std::vector<double> all = linalg::all_gather(mesh.comm(), local);
  std::vector<Point3> points;
  for (std::size_t i = 0; i + 2 < all.size(); i += 3)
    points.push_back({all[i], all[i + 1], all[i + 2]});
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

double distance_to(const Point3& x, std::span<const Point3> points)
{
  double d2 = std::numeric_limits<double>::infinity();
  for (const Point3& p : points)
  {
    const double dx = x[0] - p[0], dy = x[1] - p[1], dz = x[2] - p[2];
    d2 = std::min(d2, dx * dx + dy * dy + dz * dz);
  }
  return std::sqrt(d2);
}

std::vector<std::int32_t>
points_away_from(const StressEnvelope& env,
                 std::span<const std::int32_t> candidates,
                 std::span<const Point3> singular, double radius)
{
  std::vector<std::int32_t> out;
  for (std::int32_t i : candidates)
  {
    if (distance_to(env.point(i), singular) >= radius)
      out.push_back(i);
  }
  return out;
}
} // namespace damseis::results
