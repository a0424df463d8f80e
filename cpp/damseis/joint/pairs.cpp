#include "pairs.h"
#include <algorithm>
#include <cmath>
#include <damseis/fem/facet_dofs.h>
#include <damseis/fem/prolongation.h>
#include <damseis/geometry/coincident_points.h>
#include <damseis/geometry/facet_normal.h>
#include <damseis/geometry/tagged.h>
#include <damseis/linalg/all_gather.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/mesh/Mesh.h>
#include <dolfinx/mesh/cell_types.h>
#include <dolfinx/mesh/utils.h>
#include <map>
#include <numeric>
#include <stdexcept>

namespace damseis::joint
{
namespace
{
using Vec3 = Eigen::Vector3d;

/// Global block index of local block b.
std::int64_t global_block(const dolfinx::common::IndexMap& map, std::int32_t b)
{
  std::int64_t g = 0;
  map.local_to_global(std::span<const std::int32_t>(&b, 1),
                      std::span<std::int64_t>(&g, 1));
  return g;
}

/// A facet tagged `tag` whose (single) cell is owned here, and the facet's
/// local index in that cell: each boundary facet once over the ranks.
struct FacetOfCell
{
  std::int32_t facet, cell;
  int local;
};

std::vector<FacetOfCell>
owned_facets(const dolfinx::mesh::Mesh& mesh,
             const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags, int tag)
{
  const int tdim = mesh.topology().dim();
  mesh.topology_mutable().create_connectivity(tdim - 1, tdim);
  mesh.topology_mutable().create_connectivity(tdim, tdim - 1);
  const auto f_to_c = mesh.topology().connectivity(tdim - 1, tdim);
  const auto c_to_f = mesh.topology().connectivity(tdim, tdim - 1);
  const std::int32_t owned_cells =
      mesh.topology().index_map(tdim)->size_local();
  std::vector<FacetOfCell> out;
  for (std::int32_t f : geometry::tagged_entities(facet_tags, {tag}))
  {
    const std::int32_t c = f_to_c->links(f)[0];
    if (c >= owned_cells)
      continue;
    const auto cf = c_to_f->links(c);
    out.push_back({f, c,
                   static_cast<int>(std::distance(
                       cf.begin(), std::find(cf.begin(), cf.end(), f)))});
  }
  return out;
}

/// Area-weighted normals and areas (global block, n_x, n_y, n_z, area) at
/// the nodes of the facets tagged `tag` whose cell is owned here: each
/// facet's normal points out of its cell (side 1 into side 2).
std::vector<double>
node_normals(const dolfinx::fem::FunctionSpace& V,
             const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags, int tag)
{
  const auto& mesh = *V.mesh();
  const int tdim = mesh.topology().dim();
  const auto& dofmap = *V.dofmap();
  const auto& layout = dofmap.element_dof_layout();
  std::vector<double> out;
  for (const auto [f, c, local] : owned_facets(mesh, facet_tags, tag))
  {
    const Vec3 n = geometry::outward_facet_normal(mesh, f, c);
    const auto cell_dofs = dofmap.cell_dofs(c);
    for (int k : layout.entity_closure_dofs(tdim - 1, local))
    {
      const auto g = global_block(*dofmap.index_map, cell_dofs[k]);
      out.insert(out.end(),
                 {static_cast<double>(g), n[0], n[1], n[2], n.norm()});
    }
  }
  return out;
}

/// (midpoint, end, end) global blocks of the edges of the facets tagged
/// `tag` whose cell is owned here (none for P1).
std::vector<std::int64_t>
edge_midpoints(const dolfinx::fem::FunctionSpace& V,
               const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags, int tag)
{
  const auto& mesh = *V.mesh();
  const int tdim = mesh.topology().dim();
  const auto& dofmap = *V.dofmap();
  const auto& layout = dofmap.element_dof_layout();
  std::vector<std::int64_t> out;
  if (layout.num_entity_dofs(1) == 0)
    return out;
  const auto cell_type = mesh.topology().cell_type();
  const auto facet_vertices =
      dolfinx::mesh::get_entity_vertices(cell_type, tdim - 1);
  const auto edge_vertices = dolfinx::mesh::get_entity_vertices(cell_type, 1);
  for (const auto [f, c, lf] : owned_facets(mesh, facet_tags, tag))
  {
    const auto fv = facet_vertices.links(lf);
    const auto cell_dofs = dofmap.cell_dofs(c);
    for (int e = 0; e < edge_vertices.num_nodes(); ++e)
    {
      const auto ev = edge_vertices.links(e);
      auto in_facet = [&](int v)
      { return std::find(fv.begin(), fv.end(), v) != fv.end(); };
      if (!in_facet(ev[0]) || !in_facet(ev[1]))
        continue;
      auto block = [&](int dim, int entity)
      {
        return global_block(*dofmap.index_map,
                            cell_dofs[layout.entity_dofs(dim, entity)[0]]);
      };
      out.insert(out.end(), {block(1, e), block(0, ev[0]), block(0, ev[1])});
    }
  }
  return out;
}

/// (global block, x, y, z) of the owned nodes on the facets tagged `tag`.
std::vector<double>
owned_nodes(const dolfinx::fem::FunctionSpace& V,
            const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags, int tag,
            const std::vector<double>& x)
{
  const auto& map = *V.dofmap()->index_map;
  std::vector<double> out;
  for (std::int32_t b : fem::owned_blocks_on(V, facet_tags, tag))
  {
    out.insert(out.end(), {static_cast<double>(map.local_range()[0] + b),
                           x[3 * b], x[3 * b + 1], x[3 * b + 2]});
  }
  return out;
}

/// The frame (n, t_a, t_b) of a unit normal: t_a is the steepest descent in
/// the plane (or x where the plane is horizontal).
Eigen::Matrix3d frame_of(Vec3 n)
{
  n.normalize();
  Vec3 t = -Vec3::UnitZ() + n.z() * n; // -e_z projected on the plane
  if (t.norm() < 1e-6)
    t = Vec3::UnitX() - n.x() * n;
  t.normalize();
  Eigen::Matrix3d Q;
  Q.col(0) = n;
  Q.col(1) = t;
  Q.col(2) = n.cross(t);
  return Q;
}
} // namespace

PairSet subset(const PairSet& set, const std::vector<std::size_t>& keep)
{
  PairSet out;
  out.joints = set.joints;
  std::vector<int> renumber(set.size(), -1);
  for (std::size_t k = 0; k < keep.size(); ++k)
    renumber[keep[k]] = static_cast<int>(k);
  for (std::size_t i : keep)
  {
    out.joint.push_back(set.joint[i]);
    out.block1.push_back(set.block1[i]);
    out.block2.push_back(set.block2[i]);
    out.x.push_back(set.x[i]);
    out.frame.push_back(set.frame[i]);
    out.area.push_back(set.area[i]);
    out.midside.push_back(set.midside[i]);
    std::array<int, 2> ends = set.edge_ends[i];
    for (int& e : ends)
      e = e < 0 ? -1 : renumber[e];
    out.edge_ends.push_back(ends);
  }
  return out;
}

Mat midside_prolongation(const dolfinx::fem::FunctionSpace& V,
                         const PairSet& set)
{
  const auto& map = *V.dofmap()->index_map;
  const std::int64_t first = map.local_range()[0];
  const std::int64_t last = first + map.size_local();
  std::vector<fem::BlockConstraint> constraints;
  for (std::size_t i = 0; i < set.size(); ++i)
  {
    if (!set.midside[i] || set.block2[i] < first || set.block2[i] >= last)
      continue;
    // w_mid = (w_end1 + w_end2) / 2: u_2 = u_1 + (u_2 - u_1)_ends / 2.
    fem::BlockConstraint c{static_cast<std::int32_t>(set.block2[i] - first),
                           {{set.block1[i], 1.0}}};
    for (int e : set.edge_ends[i])
    {
      if (e < 0)
        continue; // a bonded end: no relative motion
      c.masters.push_back({set.block2[e], 0.5});
      c.masters.push_back({set.block1[e], -0.5});
    }
    constraints.push_back(std::move(c));
  }
  return fem::constraint_prolongation(V, constraints);
}

contact::PairLaw PairSet::law(std::size_t i) const
{
  contact::PairLaw l;
  const JointSpec& j = joints[joint[i]];
  l.mu = j.mu;
  l.keyed = j.keyed;
  l.tension = j.tensile_strength * area[i];
  l.cohesion = j.cohesion * area[i];
  return l;
}

PairSet joint_pairs(const dolfinx::fem::FunctionSpace& V,
                    const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags,
                    const std::vector<JointSpec>& joints, double tol)
{
  if (V.dofmap()->index_map_bs() != 3 || V.mesh()->geometry().dim() != 3)
    throw std::invalid_argument("joint pairs need a 3D vector space");
  MPI_Comm comm = V.mesh()->comm();
  const std::vector<double> x = V.tabulate_dof_coordinates(false);
  PairSet set;
  set.joints = joints;
  for (std::size_t j = 0; j < joints.size(); ++j)
  {
    const auto side1 = linalg::all_gather(
        comm, owned_nodes(V, facet_tags, joints[j].tag_side1, x));
    const auto side2 = linalg::all_gather(
        comm, owned_nodes(V, facet_tags, joints[j].tag_side2, x));
    const auto normals = linalg::all_gather(
        comm, node_normals(V, facet_tags, joints[j].tag_side1));
    // Side-2 edge midpoints and their ends.
    std::map<std::int64_t, std::array<std::int64_t, 2>> edge_of;
    {
      const auto e = linalg::all_gather(
          comm, edge_midpoints(V, facet_tags, joints[j].tag_side2));
      for (std::size_t k = 0; k < e.size(); k += 3)
        edge_of[e[k]] = {e[k + 1], e[k + 2]};
    }
    std::map<std::int64_t, Vec3> normal;
    std::map<std::int64_t, double> facet_area; // of the facets at a node
    for (std::size_t k = 0; k < normals.size(); k += 5)
    {
      const auto block = static_cast<std::int64_t>(normals[k]);
      auto [it, fresh] = normal.try_emplace(block, Vec3::Zero());
      it->second += Vec3(normals[k + 1], normals[k + 2], normals[k + 3]);
      facet_area[block] += normals[k + 4];
    }
    // Side-1 nodes for the coincidence search.
    const std::size_t n1 = side1.size() / 4;
    const geometry::CoincidentPoints side1_points(
        n1,
        [&](std::size_t m)
        {
          return std::array<double, 3>{side1[4 * m + 1], side1[4 * m + 2],
                                       side1[4 * m + 3]};
        },
        tol);
    std::vector<std::int64_t> on_side1(n1);
    for (std::size_t m = 0; m < n1; ++m)
      on_side1[m] = static_cast<std::int64_t>(side1[4 * m]);
    std::sort(on_side1.begin(), on_side1.end());

    struct Pair
    {
      std::int64_t b1, b2;
      std::array<double, 3> x;
    };
    std::vector<Pair> pairs;
    for (std::size_t k = 0; k < side2.size(); k += 4)
    {
      const auto b2 = static_cast<std::int64_t>(side2[k]);
      if (std::binary_search(on_side1.begin(), on_side1.end(), b2))
        continue; // one node: bonded where the joint meets other material
      const double* p = &side2[k + 1];
      const std::int64_t m = side1_points.find(p);
      const std::int64_t b1 =
          m < 0 ? -1 : static_cast<std::int64_t>(side1[4 * m]);
      if (b1 < 0)
      {
        throw std::runtime_error(
            "joint " + joints[j].label + ": no side-1 node at (" +
            std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " +
            std::to_string(p[2]) + ") for the side-2 node there");
      }
      pairs.push_back({b1, b2, {p[0], p[1], p[2]}});
    }
    if (pairs.empty())
      throw std::runtime_error("joint " + joints[j].label +
                               " has no node pairs");
    // By z, x, y, each rounded to the tolerance (dof coordinates carry
    // round-off that differs between partitions).
    auto key = [tol](const Pair& p)
    {
      std::array<long long, 3> k;
      for (int d = 0; d < 3; ++d)
        k[d] = std::llround(p.x[(d + 2) % 3] / std::max(tol, 1e-12));
      return k;
    };
    std::sort(pairs.begin(), pairs.end(),
              [&](const Pair& a, const Pair& b) { return key(a) < key(b); });
    const std::size_t first_pair = set.size();
    std::map<std::int64_t, int> pair_of_side2; // side-2 block -> pair index
    for (std::size_t k = 0; k < pairs.size(); ++k)
      pair_of_side2[pairs[k].b2] = static_cast<int>(first_pair + k);
    for (const Pair& p : pairs)
    {
      const auto edge = edge_of.find(p.b2);
      set.midside.push_back(edge != edge_of.end());
      std::array<int, 2> ends = {-1, -1};
      if (edge != edge_of.end())
      {
        for (int k = 0; k < 2; ++k)
        {
          const auto q = pair_of_side2.find(edge->second[k]);
          ends[k] = q == pair_of_side2.end() ? -1 : q->second;
        }
      }
      set.edge_ends.push_back(ends);
      const auto it = normal.find(p.b1);
      if (it == normal.end() || it->second.norm() == 0.0)
        throw std::runtime_error("joint " + joints[j].label +
                                 ": a pair without a facet normal");
      set.joint.push_back(static_cast<int>(j));
      set.block1.push_back(p.b1);
      set.block2.push_back(p.b2);
      set.x.push_back(p.x);
      set.frame.push_back(frame_of(it->second));
      set.area.push_back(facet_area[p.b1] / 3.0);
    }
  }
  return set;
}
} // namespace damseis::joint
