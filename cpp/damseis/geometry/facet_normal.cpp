#include "facet_normal.h"
#include <dolfinx/mesh/utils.h>
#include <span>

namespace damseis::geometry
{
Eigen::Vector3d outward_facet_normal(const dolfinx::mesh::Mesh& mesh,
                                     std::int32_t facet, std::int32_t cell)
{
  const int tdim = mesh.topology().dim();
  const auto& x = mesh.geometry().x();
  auto at = [&](std::int32_t node)
  { return Eigen::Vector3d(x[3 * node], x[3 * node + 1], x[3 * node + 2]); };
  const auto fx = dolfinx::mesh::entities_to_geometry(
      mesh, tdim - 1, std::span<const std::int32_t>(&facet, 1), false);
  const auto cx = dolfinx::mesh::entities_to_geometry(
      mesh, tdim, std::span<const std::int32_t>(&cell, 1), false);
  const Eigen::Vector3d a = at(fx[0]), b = at(fx[1]), d = at(fx[2]);
  Eigen::Vector3d n = 0.5 * (b - a).cross(d - a); // |n| = area
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (std::int32_t node : cx) // the cell's vertices
    centre += at(node) / static_cast<double>(cx.size());
  if (n.dot((a + b + d) / 3.0 - centre) < 0.0)
    n = -n;
  return n;
}
} // namespace damseis::geometry
