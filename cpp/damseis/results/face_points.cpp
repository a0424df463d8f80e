#include "face_points.h"
#include <algorithm>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/mesh/Mesh.h>
#include <dolfinx/mesh/Topology.h>

namespace damseis::results
{
void for_each_face_point(
    const dolfinx::fem::FunctionSpace& S,
    const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags,
    const std::vector<int>& tags, bool vertex_points,
    const std::function<void(std::int32_t, std::int32_t, std::int32_t)>& visit)
{
  auto mesh = S.mesh();
  const int tdim = mesh->topology().dim();
  auto& topology = mesh->topology_mutable();
  topology.create_connectivity(tdim - 1, tdim);
  topology.create_connectivity(tdim - 1, 0);
  topology.create_connectivity(tdim, 0);
  auto f_to_c = topology.connectivity(tdim - 1, tdim);
  auto f_to_v = topology.connectivity(tdim - 1, 0);
  auto c_to_v = topology.connectivity(tdim, 0);
  const auto& dofmap = *S.dofmap();
  for (std::size_t i = 0; i < facet_tags.indices().size(); ++i)
  {
    if (std::find(tags.begin(), tags.end(), facet_tags.values()[i]) ==
        tags.end())
      continue;
    const std::int32_t f = facet_tags.indices()[i];
    auto fv = f_to_v->links(f);
    for (std::int32_t c : f_to_c->links(f))
    {
      auto dofs = dofmap.cell_dofs(c);
      auto cv = c_to_v->links(c);
      // One point per cell vertex, in the cell's vertex order: those of the
      // facet; otherwise (P1: a point per cell, or quadrature points) all
      // the cell's points.
      const bool at_vertices = vertex_points && dofs.size() == cv.size();
      for (std::size_t k = 0; k < dofs.size(); ++k)
      {
        if (!at_vertices || std::find(fv.begin(), fv.end(), cv[k]) != fv.end())
          visit(f, c, dofs[k]);
      }
    }
  }
}

std::vector<std::int32_t>
face_points(const dolfinx::fem::FunctionSpace& S,
            const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags,
            const std::vector<int>& tags, bool vertex_points)
{
  const std::int32_t num_owned = S.dofmap()->index_map->size_local();
  std::vector<std::int32_t> points;
  for_each_face_point(S, facet_tags, tags, vertex_points,
                      [&](std::int32_t, std::int32_t, std::int32_t p)
                      {
                        if (p < num_owned)
                          points.push_back(p);
                      });
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

std::vector<std::int64_t>
face_point_cells(const dolfinx::fem::FunctionSpace& S,
                 const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags,
                 const std::vector<int>& tags,
                 std::span<const std::int32_t> points)
{
  auto mesh = S.mesh();
  auto cell_map = mesh->topology().index_map(mesh->topology().dim());
  std::vector<std::int64_t> cells(points.size(), -1);
  for_each_face_point(
      S, facet_tags, tags, false,
      [&](std::int32_t, std::int32_t c, std::int32_t p)
      {
        auto it = std::lower_bound(points.begin(), points.end(), p);
        if (it != points.end() && *it == p)
        {
          std::int64_t global = 0;
          cell_map->local_to_global(std::span(&c, 1), std::span(&global, 1));
          cells[it - points.begin()] = global;
        }
      });
  return cells;
}
} // namespace damseis::results
