// A distributed DOLFINx model from mesh arrays held by rank 0.
#include "model_arrays.h"

#include <memory>
#include <utility>
#include <vector>

#include <dolfinx/fem/CoordinateElement.h>
#include <dolfinx/graph/AdjacencyList.h>
#include <dolfinx/io/xdmf_utils.h>
#include <dolfinx/mesh/MeshTags.h>
#include <dolfinx/mesh/Topology.h>
#include <dolfinx/mesh/cell_types.h>
#include <dolfinx/mesh/utils.h>

namespace damseis::geometry
{
namespace
{
/// MeshTags of dimension `dim` from entities given by input node indices
/// (significant on rank 0 only).
std::shared_ptr<dolfinx::mesh::MeshTags<std::int32_t>>
tags_from_arrays(const std::shared_ptr<dolfinx::mesh::Mesh>& mesh, int dim,
                 std::span<const std::int64_t> entities,
                 std::span<const std::int32_t> values)
{
  auto [local_entities, local_values] =
      dolfinx::io::xdmf_utils::distribute_entity_data(*mesh, dim, entities,
                                                      values);
  auto adj = dolfinx::graph::regular_adjacency_list(std::move(local_entities),
                                                    dim + 1);
  return std::make_shared<dolfinx::mesh::MeshTags<std::int32_t>>(
      dolfinx::mesh::create_meshtags<std::int32_t>(
          mesh, dim, adj, std::span<const std::int32_t>(local_values)));
}
} // namespace

Model model_from_arrays(MPI_Comm comm, std::span<const double> x,
                        std::span<const std::int64_t> cells,
                        std::span<const std::int32_t> cell_values,
                        std::span<const std::int64_t> facets,
                        std::span<const std::int32_t> facet_values)
{
  const std::size_t num_nodes = x.size() / 3;
  std::vector<std::int64_t> c(cells.begin(), cells.end());
  auto mesh = std::make_shared<dolfinx::mesh::Mesh>(dolfinx::mesh::create_mesh(
      comm, dolfinx::graph::regular_adjacency_list(std::move(c), 4),
      dolfinx::fem::CoordinateElement(dolfinx::mesh::CellType::tetrahedron, 1),
      x, {num_nodes, 3}, dolfinx::mesh::GhostMode::shared_facet));
  dolfinx::mesh::Topology& topology = mesh->topology_mutable();
  topology.create_connectivity(3, 0);
  topology.create_connectivity(2, 0);
  topology.create_connectivity(2, 3);

  Model model;
  model.mesh = mesh;
  model.cell_tags = tags_from_arrays(mesh, 3, cells, cell_values);
  model.cell_tags->name = "cell_tags";
  model.facet_tags = tags_from_arrays(mesh, 2, facets, facet_values);
  model.facet_tags->name = "facet_tags";
  return model;
}
} // namespace damseis::geometry
