#include "face_directions.h"
#include <Eigen/Dense>
#include <algorithm>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/mesh/Mesh.h>
#include <dolfinx/mesh/Topology.h>
#include <dolfinx/mesh/utils.h>
#include <span>
#include <stdexcept>

namespace damseis::results
{
std::vector<std::array<double, 6>> arch_cantilever_directions(
    const dolfinx::fem::FunctionSpace& S,
    const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags,
    const std::vector<int>& tags, const std::vector<std::int32_t>& points)
{
  auto mesh = S.mesh();
  const int tdim = mesh->topology().dim();
  if (tdim != 3)
    throw std::invalid_argument("arch and cantilever directions: 3D only");
  auto& topology = mesh->topology_mutable();
  topology.create_connectivity(tdim - 1, tdim);
  topology.create_connectivity(tdim - 1, 0);
  topology.create_connectivity(tdim, 0);
  auto f_to_c = topology.connectivity(tdim - 1, tdim);
  auto f_to_v = topology.connectivity(tdim - 1, 0);
  auto c_to_v = topology.connectivity(tdim, 0);
  const auto& x = mesh->geometry().x();
  const auto& dofmap = *S.dofmap();
  const std::int32_t num_owned = dofmap.index_map->size_local();

  // The summed (area-weighted, outward) normals of the facets at each point.
  std::vector<Eigen::Vector3d> normal(num_owned, Eigen::Vector3d::Zero());
  for (std::size_t i = 0; i < facet_tags.indices().size(); ++i)
  {
    if (std::find(tags.begin(), tags.end(), facet_tags.values()[i]) ==
        tags.end())
      continue;
    const std::int32_t f = facet_tags.indices()[i];
    auto fv = f_to_v->links(f);
    auto at = [&](std::int32_t node)
    { return Eigen::Vector3d(x[3 * node], x[3 * node + 1], x[3 * node + 2]); };
    const auto fx = dolfinx::mesh::entities_to_geometry(
        *mesh, tdim - 1, std::span<const std::int32_t>(&f, 1), false);
    const Eigen::Vector3d a = at(fx[0]), b = at(fx[1]), d = at(fx[2]);
    for (std::int32_t c : f_to_c->links(f))
    {
      auto cv = c_to_v->links(c);
      const auto cx = dolfinx::mesh::entities_to_geometry(
          *mesh, tdim, std::span<const std::int32_t>(&c, 1), false);
      Eigen::Vector3d centre = Eigen::Vector3d::Zero();
      for (std::int32_t node : cx)
        centre += at(node) / static_cast<double>(cx.size());
      // Area-weighted, out of the cell.
      Eigen::Vector3d n = 0.5 * (b - a).cross(d - a);
      if (n.dot((a + b + d) / 3.0 - centre) < 0.0)
        n = -n;
      // The facet's points: its vertices (P2 stress points at vertices) or
      // the cell's points (P1: one per cell).
      auto dofs = dofmap.cell_dofs(c);
      for (std::size_t k = 0; k < dofs.size(); ++k)
      {
        const bool on_facet =
            dofs.size() != cv.size() ||
            std::find(fv.begin(), fv.end(), cv[k]) != fv.end();
        if (on_facet && dofs[k] < num_owned)
          normal[dofs[k]] += n;
      }
    }
  }
  std::vector<std::array<double, 6>> out;
  out.reserve(points.size());
  const Eigen::Vector3d ez(0.0, 0.0, 1.0);
  for (std::int32_t p : points)
  {
    const Eigen::Vector3d n = normal[p].normalized();
    Eigen::Vector3d t = ez.cross(n);
    t = t.norm() > 1e-6 ? Eigen::Vector3d(t.normalized())
                        : Eigen::Vector3d(1.0, 0.0, 0.0);
    const Eigen::Vector3d c = n.cross(t).normalized();
    out.push_back({t[0], t[1], t[2], c[0], c[1], c[2]});
  }
  return out;
}
} // namespace damseis::results
