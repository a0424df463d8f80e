// Conversion of a gmsh model (held by rank 0) into a distributed DOLFINx
// mesh with region (cell) and boundary (facet) tags.
#include "gmsh_mesh.h"
#include "root_status.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/CoordinateElement.h>
#include <dolfinx/graph/AdjacencyList.h>
#include <dolfinx/io/cells.h>
#include <dolfinx/io/xdmf_utils.h>
#include <dolfinx/mesh/Topology.h>
#include <dolfinx/mesh/cell_types.h>
#include <dolfinx/mesh/utils.h>
#include <gmsh.h>

namespace damseis::geometry
{
namespace
{
/// Mesh data read from gmsh on rank 0, in DOLFINx node ordering.
struct GmshData
{
  std::vector<double> x;                ///< node coordinates, (nnodes, gdim)
  std::vector<std::int64_t> cells;      ///< cell nodes (0-based indices)
  std::vector<std::int32_t> cell_tags;  ///< one physical tag per cell
  std::vector<std::int64_t> facets;     ///< facet nodes (0-based indices)
  std::vector<std::int32_t> facet_tags; ///< one physical tag per facet
};

/// The DOLFINx cell type of the entities of dimension `dim` (1, 2, 3).
dolfinx::mesh::CellType simplex_type(int dim)
{
  switch (dim)
  {
  case 1:
    return dolfinx::mesh::CellType::interval;
  case 2:
    return dolfinx::mesh::CellType::triangle;
  case 3:
    return dolfinx::mesh::CellType::tetrahedron;
  default:
    throw std::invalid_argument("model_from_gmsh: unsupported dimension " +
                                std::to_string(dim));
  }
}

/// Appends the elements of the physical groups of dimension `dim` to
/// `nodes`/`values` (0-based node indices in DOLFINx ordering). Only
/// linear simplices (dim + 1 nodes) are accepted.
void collect_entities(
    int dim, const std::unordered_map<std::size_t, std::int64_t>& node_index,
    std::vector<std::int64_t>& nodes, std::vector<std::int32_t>& values)
{
  const int nn = dim + 1;
  const std::vector<std::uint8_t> perm =
      dolfinx::io::cells::perm_gmsh(simplex_type(dim), nn);
  std::unordered_set<std::size_t> seen;

  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, dim);
  for (const auto& [gdim, gtag] : groups)
  {
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(gdim, gtag, entities);
    for (int entity : entities)
    {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> etags, ntags;
      gmsh::model::mesh::getElements(types, etags, ntags, gdim, entity);
      for (std::size_t t = 0; t < types.size(); ++t)
      {
        std::string name;
        int edim = 0, order = 0, num_nodes = 0, num_primary = 0;
        std::vector<double> local_coords;
        gmsh::model::mesh::getElementProperties(
            types[t], name, edim, order, num_nodes, local_coords, num_primary);
        if (edim != dim or order != 1 or num_nodes != nn)
        {
          throw std::runtime_error(
              "model_from_gmsh: physical group " + std::to_string(gtag) +
              " of dimension " + std::to_string(dim) +
              " contains elements of type '" + name +
              "'; only linear simplices (triangles/tetrahedra and their "
              "facets) are supported");
        }
        for (std::size_t e = 0; e < etags[t].size(); ++e)
        {
          if (!seen.insert(etags[t][e]).second)
          {
            throw std::runtime_error(
                "model_from_gmsh: gmsh element " + std::to_string(etags[t][e]) +
                " of dimension " + std::to_string(dim) +
                " belongs to more than one physical group");
          }
          const std::size_t* en = ntags[t].data() + e * nn;
          for (int j = 0; j < nn; ++j)
          {
            auto it = node_index.find(en[perm[j]]);
            if (it == node_index.end())
            {
              throw std::runtime_error("model_from_gmsh: element node " +
                                       std::to_string(en[perm[j]]) +
                                       " not found in the gmsh nodes");
            }
            nodes.push_back(it->second);
          }
          values.push_back(gtag);
        }
      }
    }
  }
}

/// Reads nodes, cells and facets of the current gmsh model (rank 0).
GmshData read_gmsh(int tdim)
{
  GmshData d;
  std::vector<std::size_t> node_tags;
  std::vector<double> xyz, par;
  gmsh::model::mesh::getNodes(node_tags, xyz, par, -1, -1, false, false);

  // Map gmsh node tags (possibly non-contiguous) to 0-based indices and
  // keep gdim = tdim coordinates
  std::unordered_map<std::size_t, std::int64_t> node_index;
  node_index.reserve(node_tags.size());
  d.x.reserve(node_tags.size() * tdim);
  double scale = 0, zmax = 0;
  for (std::size_t i = 0; i < node_tags.size(); ++i)
  {
    if (!node_index.emplace(node_tags[i], std::int64_t(i)).second)
      throw std::runtime_error("model_from_gmsh: duplicate gmsh node tag");
    for (int k = 0; k < tdim; ++k)
    {
      d.x.push_back(xyz[3 * i + k]);
      scale = std::max(scale, std::abs(xyz[3 * i + k]));
    }
    if (tdim == 2)
      zmax = std::max(zmax, std::abs(xyz[3 * i + 2]));
  }
  if (zmax > 1e-12 * std::max(scale, 1.0))
  {
    throw std::runtime_error("model_from_gmsh: a 2D mesh must lie in the "
                             "plane z = 0");
  }

  collect_entities(tdim, node_index, d.cells, d.cell_tags);
  collect_entities(tdim - 1, node_index, d.facets, d.facet_tags);
  if (d.cell_tags.empty())
  {
    throw std::runtime_error(
        "model_from_gmsh: no cells in physical groups of dimension " +
        std::to_string(tdim) +
        " (is the model meshed and are physical "
        "groups defined?)");
  }
  return d;
}

/// Builds MeshTags of dimension `dim` from entities given by global
/// input node indices (significant on rank 0 only).
std::shared_ptr<dolfinx::mesh::MeshTags<std::int32_t>>
make_tags(const std::shared_ptr<dolfinx::mesh::Mesh>& mesh, int dim,
          const std::vector<std::int64_t>& entities,
          const std::vector<std::int32_t>& values)
{
  auto [local_entities, local_values] =
      dolfinx::io::xdmf_utils::distribute_entity_data(
          *mesh, dim, std::span<const std::int64_t>(entities),
          std::span<const std::int32_t>(values));
  auto adj = dolfinx::graph::regular_adjacency_list(std::move(local_entities),
                                                    dim + 1);
  return std::make_shared<dolfinx::mesh::MeshTags<std::int32_t>>(
      dolfinx::mesh::create_meshtags<std::int32_t>(
          mesh, dim, adj, std::span<const std::int32_t>(local_values)));
}
} // namespace

//-----------------------------------------------------------------------------
Model model_from_gmsh(MPI_Comm comm, int tdim)
{
  if (tdim != 2 and tdim != 3)
  {
    throw std::invalid_argument("model_from_gmsh: tdim must be 2 or 3, got " +
                                std::to_string(tdim));
  }

  GmshData d;
  on_root(comm, [&] { d = read_gmsh(tdim); },
          {"", "model_from_gmsh: unknown error while reading gmsh"});

  const int nn = tdim + 1;
  const std::size_t gdim = tdim;
  const std::size_t num_nodes = d.x.size() / gdim;
  const dolfinx::mesh::CellType cell_type = simplex_type(tdim);

  auto mesh = std::make_shared<dolfinx::mesh::Mesh>(dolfinx::mesh::create_mesh(
      comm, dolfinx::graph::regular_adjacency_list(d.cells, nn),
      dolfinx::fem::CoordinateElement(cell_type, 1),
      std::span<const double>(d.x), {num_nodes, gdim},
      dolfinx::mesh::GhostMode::shared_facet));

  dolfinx::mesh::Topology& topology = mesh->topology_mutable();
  topology.create_connectivity(tdim, 0);
  topology.create_connectivity(tdim - 1, 0);
  topology.create_connectivity(tdim - 1, tdim);

  Model model;
  model.mesh = mesh;
  model.cell_tags = make_tags(mesh, tdim, d.cells, d.cell_tags);
  model.cell_tags->name = "cell_tags";
  model.facet_tags = make_tags(mesh, tdim - 1, d.facets, d.facet_tags);
  model.facet_tags->name = "facet_tags";
  return model;
}
} // namespace damseis::geometry
