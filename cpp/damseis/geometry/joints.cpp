// Contraction joints with duplicated nodes.
#include "joints.h"
#include "tags.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include <dolfinx/graph/AdjacencyList.h>
#include <dolfinx/mesh/Geometry.h>
#include <dolfinx/mesh/Topology.h>

namespace damseis::geometry
{
namespace
{
double signed_distance(const JointSplitSpec& j, const double* p)
{
  return (p[0] - j.point[0]) * j.normal[0] + (p[1] - j.point[1]) * j.normal[1] +
         (p[2] - j.point[2]) * j.normal[2];
}

/// Centroid of `n` nodes.
std::array<double, 3> centroid(const std::vector<double>& x,
                               const std::int64_t* nodes, int n)
{
  std::array<double, 3> c = {0, 0, 0};
  for (int a = 0; a < n; ++a)
    for (int k = 0; k < 3; ++k)
      c[k] += x[3 * nodes[a] + k] / n;
  return c;
}
} // namespace

//-----------------------------------------------------------------------------
std::vector<JointPairs> split_joints(std::vector<double>& x,
                                     std::vector<std::int64_t>& cells,
                                     std::span<const std::int32_t> cell_values,
                                     std::vector<std::int64_t>& facets,
                                     std::vector<std::int32_t>& facet_values,
                                     std::span<const JointSplitSpec> joints,
                                     int split_region, int bonded_tag)
{
  // Nodes that are never split
  std::unordered_set<std::int64_t> bonded;
  for (std::size_t f = 0; f < facet_values.size(); ++f)
    if (facet_values[f] == bonded_tag)
      for (int a = 0; a < 3; ++a)
        bonded.insert(facets[3 * f + a]);

  // Node -> cells (of the split region)
  const std::size_t ncells = cell_values.size();
  std::unordered_map<std::int64_t, std::vector<std::int32_t>> node_cells;

  std::vector<JointPairs> out;
  const std::size_t nfacets0 = facet_values.size();
  for (const JointSplitSpec& j : joints)
  {
    JointPairs p;
    p.label_index = j.label_index;
    p.label = j.label;
    p.tag_side1 = j.tag_side1;
    p.tag_side2 = j.tag_side2;
    p.plane_point = j.point;
    p.plane_normal = j.normal;

    // Joint facets, the joint nodes, their normals and tributary areas
    std::vector<std::size_t> jf;
    std::map<std::int64_t, std::array<double, 4>> acc; // n*area, area
    for (std::size_t f = 0; f < nfacets0; ++f)
    {
      if (facet_values[f] != j.tag_side1)
        continue;
      jf.push_back(f);
      const std::int64_t* v = &facets[3 * f];
      double e1[3], e2[3];
      for (int k = 0; k < 3; ++k)
      {
        e1[k] = x[3 * v[1] + k] - x[3 * v[0] + k];
        e2[k] = x[3 * v[2] + k] - x[3 * v[0] + k];
      }
      std::array<double, 3> n = {e1[1] * e2[2] - e1[2] * e2[1],
                                 e1[2] * e2[0] - e1[0] * e2[2],
                                 e1[0] * e2[1] - e1[1] * e2[0]};
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      const double area = 0.5 * len;
      const double s =
          n[0] * j.normal[0] + n[1] * j.normal[1] + n[2] * j.normal[2] < 0 ? -1
                                                                           : 1;
      for (int a = 0; a < 3; ++a)
      {
        auto& q = acc[v[a]];
        for (int k = 0; k < 3; ++k)
          q[k] += s * n[k] * 0.5; // area-weighted: |n|/2 = area
        q[3] += area / 3;
      }
    }
    if (jf.empty())
    {
      throw std::runtime_error(std::string("split_joints: joint ") + j.label +
                               " has no facets (tag " +
                               std::to_string(j.tag_side1) + ")");
    }

    // Copies of the joint nodes (sorted by original index: deterministic)
    std::unordered_map<std::int64_t, std::int64_t> copy;
    for (const auto& [node, q] : acc)
    {
      if (bonded.count(node))
        continue;
      const std::int64_t c = std::int64_t(x.size() / 3);
      for (int k = 0; k < 3; ++k)
        x.push_back(x[3 * node + k]);
      copy.emplace(node, c);
      p.node1.push_back(node);
      p.node2.push_back(c);
      const double len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
      for (int k = 0; k < 3; ++k)
      {
        p.x.push_back(x[3 * node + k]);
        p.normal.push_back(q[k] / len);
      }
      p.area.push_back(q[3]);
    }

    // Cells of the region on side 2 that touch a joint node
    if (node_cells.empty())
    {
      for (std::size_t c = 0; c < ncells; ++c)
        if (cell_values[c] == split_region)
          for (int a = 0; a < 4; ++a)
            node_cells[cells[4 * c + a]].push_back(std::int32_t(c));
    }
    std::unordered_set<std::int32_t> side2;
    for (const auto& [node, c] : copy)
    {
      auto it = node_cells.find(node);
      if (it == node_cells.end())
        continue;
      for (std::int32_t cell : it->second)
      {
        const auto m = centroid(x, &cells[4 * cell], 4);
        const double d = signed_distance(j, m.data());
        if (d > 0)
          side2.insert(cell);
      }
    }
    for (std::int32_t cell : side2)
    {
      for (int a = 0; a < 4; ++a)
      {
        auto it = copy.find(cells[4 * cell + a]);
        if (it != copy.end())
          cells[4 * cell + a] = it->second;
      }
    }
    // Update node -> cells for the renumbered nodes (later joints are
    // disjoint from this one, so this only keeps the map consistent)
    for (const auto& [node, c] : copy)
    {
      auto it = node_cells.find(node);
      if (it == node_cells.end())
        continue;
      std::vector<std::int32_t> keep, moved;
      for (std::int32_t cell : it->second)
        (side2.count(cell) ? moved : keep).push_back(cell);
      it->second = keep;
      node_cells[c] = moved;
    }

    // Tagged facets on side 2 (other than the joint facets)
    for (std::size_t f = 0; f < nfacets0; ++f)
    {
      if (facet_values[f] == j.tag_side1)
        continue;
      std::int64_t* v = &facets[3 * f];
      bool touches = false;
      for (int a = 0; a < 3; ++a)
        touches = touches or copy.count(v[a]);
      if (!touches)
        continue;
      const auto m = centroid(x, v, 3);
      if (signed_distance(j, m.data()) > 0)
        for (int a = 0; a < 3; ++a)
        {
          auto it = copy.find(v[a]);
          if (it != copy.end())
            v[a] = it->second;
        }
    }
    // Side-2 copies of the joint facets
    for (std::size_t f : jf)
    {
      for (int a = 0; a < 3; ++a)
      {
        const std::int64_t v = facets[3 * f + a];
        auto it = copy.find(v);
        facets.push_back(it == copy.end() ? v : it->second);
      }
      facet_values.push_back(j.tag_side2);
    }
    out.push_back(std::move(p));
  }
  return out;
}
//-----------------------------------------------------------------------------
void untag_joint_facets(std::vector<std::int64_t>& facets,
                        std::vector<std::int32_t>& facet_values)
{
  std::vector<std::int64_t> kept;
  std::vector<std::int32_t> values;
  for (std::size_t f = 0; f < facet_values.size(); ++f)
  {
    if (tags::is_joint_tag(facet_values[f]))
      continue;
    kept.insert(kept.end(), facets.begin() + 3 * f, facets.begin() + 3 * f + 3);
    values.push_back(facet_values[f]);
  }
  facets = std::move(kept);
  facet_values = std::move(values);
}

std::vector<std::int32_t>
local_geometry_nodes(const dolfinx::mesh::Mesh& mesh,
                     std::span<const std::int64_t> input_indices)
{
  const std::vector<std::int64_t>& in = mesh.geometry().input_global_indices();
  std::unordered_map<std::int64_t, std::int32_t> map;
  map.reserve(in.size());
  for (std::size_t i = 0; i < in.size(); ++i)
    map.emplace(in[i], std::int32_t(i));
  std::vector<std::int32_t> out(input_indices.size(), -1);
  for (std::size_t i = 0; i < input_indices.size(); ++i)
  {
    auto it = map.find(input_indices[i]);
    if (it != map.end())
      out[i] = it->second;
  }
  return out;
}
//-----------------------------------------------------------------------------
std::vector<std::int32_t>
local_vertices(const dolfinx::mesh::Mesh& mesh,
               std::span<const std::int64_t> input_indices)
{
  const std::vector<std::int32_t> g = local_geometry_nodes(mesh, input_indices);
  const int tdim = mesh.topology().dim();
  auto c2v = mesh.topology().connectivity(tdim, 0);
  if (!c2v)
    throw std::runtime_error("local_vertices: cell-vertex connectivity "
                             "missing");
  const auto& dofs = mesh.geometry().dofmap();
  const std::size_t nnodes = mesh.geometry().x().size() / 3;
  std::vector<std::int32_t> node_to_vertex(nnodes, -1);
  for (std::int32_t c = 0; c < dofs.num_nodes(); ++c)
  {
    auto d = dofs.links(c);
    auto v = c2v->links(c);
    for (std::size_t a = 0; a < v.size(); ++a)
      node_to_vertex[d[a]] = v[a];
  }
  std::vector<std::int32_t> out(g.size(), -1);
  for (std::size_t i = 0; i < g.size(); ++i)
    if (g[i] >= 0)
      out[i] = node_to_vertex[g[i]];
  return out;
}
//-----------------------------------------------------------------------------
void broadcast_joint_pairs(MPI_Comm comm, std::vector<JointPairs>& joints)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::int64_t nj = std::int64_t(joints.size());
  MPI_Bcast(&nj, 1, MPI_INT64_T, 0, comm);
  if (rank != 0)
    joints.assign(nj, JointPairs());
  for (JointPairs& p : joints)
  {
    int head[4] = {p.label_index, int(p.label), p.tag_side1, p.tag_side2};
    MPI_Bcast(head, 4, MPI_INT, 0, comm);
    p.label_index = head[0];
    p.label = char(head[1]);
    p.tag_side1 = head[2];
    p.tag_side2 = head[3];
    MPI_Bcast(p.plane_point.data(), 3, MPI_DOUBLE, 0, comm);
    MPI_Bcast(p.plane_normal.data(), 3, MPI_DOUBLE, 0, comm);
    std::int64_t n = std::int64_t(p.node1.size());
    MPI_Bcast(&n, 1, MPI_INT64_T, 0, comm);
    p.node1.resize(n);
    p.node2.resize(n);
    p.x.resize(3 * n);
    p.normal.resize(3 * n);
    p.area.resize(n);
    MPI_Bcast(p.node1.data(), int(n), MPI_INT64_T, 0, comm);
    MPI_Bcast(p.node2.data(), int(n), MPI_INT64_T, 0, comm);
    MPI_Bcast(p.x.data(), int(3 * n), MPI_DOUBLE, 0, comm);
    MPI_Bcast(p.normal.data(), int(3 * n), MPI_DOUBLE, 0, comm);
    MPI_Bcast(p.area.data(), int(n), MPI_DOUBLE, 0, comm);
  }
}
} // namespace damseis::geometry
