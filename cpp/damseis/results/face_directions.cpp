#include "face_directions.h"
#include "face_points.h"
#include <Eigen/Dense>
#include <damseis/geometry/facet_normal.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/mesh/Mesh.h>
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
  const std::int32_t num_owned = S.dofmap()->index_map->size_local();

  // The summed (area-weighted, out of the cell) normals of the face's
  // facets at each of its points (face_points()' points).
  std::vector<Eigen::Vector3d> normal(num_owned, Eigen::Vector3d::Zero());
  for_each_face_point(S, facet_tags, tags, true,
                      [&](std::int32_t f, std::int32_t c, std::int32_t p)
                      {
                        if (p >= num_owned)
                          return;
                        normal[p] +=
                            geometry::outward_facet_normal(*mesh, f, c);
                      });
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
