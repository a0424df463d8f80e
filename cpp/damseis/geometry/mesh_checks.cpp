#include "mesh_checks.h"
#include "tagged.h"
#include <algorithm>
#include <array>
#include <cmath>
#include <damseis/linalg/all_gather.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/mesh/Geometry.h>
#include <dolfinx/mesh/Topology.h>
#include <dolfinx/mesh/utils.h>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

namespace damseis::geometry
{
namespace
{
/// The owned facets with tag `tag`: for each, its vertices' coordinates
/// (3 per vertex) and global node numbers; gathered from all ranks.
struct SideFacets
{
  int vertices_per_facet = 0;
  std::vector<double> x;         ///< (facets * vertices, 3)
  std::vector<std::int64_t> ids; ///< (facets * vertices)
};

SideFacets side_facets(const Model& model, int tag)
{
  const auto& mesh = *model.mesh;
  const int tdim = mesh.topology().dim();
  const std::int32_t owned = mesh.topology().index_map(tdim - 1)->size_local();
  std::vector<std::int32_t> facets = tagged_entities(*model.facet_tags, {tag});
  std::erase_if(facets, [owned](std::int32_t f) { return f >= owned; });
  const std::vector<std::int32_t> nodes =
      dolfinx::mesh::entities_to_geometry(mesh, tdim - 1, facets, false);
  std::vector<double> x;
  std::vector<std::int64_t> ids(nodes.size());
  const auto& gx = mesh.geometry().x();
  const auto& map = *mesh.geometry().index_map();
  std::vector<std::int32_t> local(nodes.begin(), nodes.end());
  map.local_to_global(local, ids);
  for (std::int32_t n : nodes)
    x.insert(x.end(), {gx[3 * n], gx[3 * n + 1], gx[3 * n + 2]});
  MPI_Comm comm = mesh.comm();
  return {tdim, linalg::all_gather(comm, x), linalg::all_gather(comm, ids)};
}

/// Distinct points (within tol) of a list; returns each input point's
/// index among the distinct ones and fills `unique` (3 per point). Points
/// are binned in a grid of cells 4 tol wide; a point is compared with the
/// distinct points of its cell and the 26 around it.
std::vector<std::int64_t> distinct_points(const std::vector<double>& x,
                                          double tol,
                                          std::vector<double>& unique)
{
  const std::size_t n = x.size() / 3;
  const double cell = 4.0 * tol;
  using Key = std::array<std::int64_t, 3>;
  std::map<Key, std::vector<std::int64_t>> grid;
  auto key_of = [&](const double* p)
  {
    return Key{static_cast<std::int64_t>(std::floor(p[0] / cell)),
               static_cast<std::int64_t>(std::floor(p[1] / cell)),
               static_cast<std::int64_t>(std::floor(p[2] / cell))};
  };
  std::vector<std::int64_t> id(n, -1);
  for (std::size_t i = 0; i < n; ++i)
  {
    const double* p = &x[3 * i];
    const Key k = key_of(p);
    for (int a = -1; a <= 1 && id[i] < 0; ++a)
      for (int b = -1; b <= 1 && id[i] < 0; ++b)
        for (int c = -1; c <= 1 && id[i] < 0; ++c)
        {
          const auto it = grid.find({k[0] + a, k[1] + b, k[2] + c});
          if (it == grid.end())
            continue;
          for (std::int64_t u : it->second)
          {
            const double* q = &unique[3 * u];
            if (std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]) <= tol)
            {
              id[i] = u;
              break;
            }
          }
        }
    if (id[i] < 0)
    {
      id[i] = static_cast<std::int64_t>(unique.size() / 3);
      unique.insert(unique.end(), {p[0], p[1], p[2]});
      grid[k].push_back(id[i]);
    }
  }
  return id;
}

std::string point_text(const double* p, int dim)
{
  std::ostringstream s;
  s.precision(6);
  s << "(" << p[0] << ", " << p[1];
  if (dim == 3)
    s << ", " << p[2];
  s << ")";
  return s.str();
}
} // namespace

std::int64_t degenerate_cells(const Model& model)
{
  const auto& mesh = *model.mesh;
  const int tdim = mesh.topology().dim();
  const std::int32_t owned = mesh.topology().index_map(tdim)->size_local();
  std::vector<std::int32_t> cells(owned);
  std::iota(cells.begin(), cells.end(), 0);
  const std::vector<std::int32_t> nodes =
      dolfinx::mesh::entities_to_geometry(mesh, tdim, cells, false);
  const auto& x = mesh.geometry().x();
  const int nv = tdim + 1;
  std::vector<double> volume(owned);
  for (std::int32_t c = 0; c < owned; ++c)
  {
    const double* p0 = &x[3 * nodes[nv * c]];
    double e[3][3] = {};
    for (int j = 1; j < nv; ++j)
      for (int k = 0; k < 3; ++k)
        e[j - 1][k] = x[3 * nodes[nv * c + j] + k] - p0[k];
    volume[c] =
        tdim == 2
            ? std::abs(e[0][0] * e[1][1] - e[0][1] * e[1][0]) / 2
            : std::abs(e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                       e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                       e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) /
                  6;
  }
  double sums[2] = {std::accumulate(volume.begin(), volume.end(), 0.0),
                    static_cast<double>(owned)};
  MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, mesh.comm());
  const double threshold = 1e-10 * sums[0] / std::max(sums[1], 1.0);
  std::int64_t n = std::count_if(volume.begin(), volume.end(),
                                 [&](double v) { return v <= threshold; });
  MPI_Allreduce(MPI_IN_PLACE, &n, 1, MPI_INT64_T, MPI_SUM, mesh.comm());
  return n;
}

std::int64_t interior_facets(const Model& model, int tag)
{
  auto& mesh = *model.mesh;
  const int tdim = mesh.topology().dim();
  mesh.topology_mutable().create_connectivity(tdim - 1, tdim);
  const auto f_to_c = mesh.topology().connectivity(tdim - 1, tdim);
  const std::int32_t owned = mesh.topology().index_map(tdim - 1)->size_local();
  std::int64_t n = 0;
  for (std::int32_t f : tagged_entities(*model.facet_tags, {tag}))
    n += f < owned && f_to_c->num_links(f) == 2;
  MPI_Allreduce(MPI_IN_PLACE, &n, 1, MPI_INT64_T, MPI_SUM, mesh.comm());
  return n;
}

JointMatch match_joint_sides(const Model& model, int tag1, int tag2,
                             const std::string& name1, const std::string& name2,
                             double rel_tol)
{
  const int tdim = model.mesh->topology().dim();
  const SideFacets s1 = side_facets(model, tag1), s2 = side_facets(model, tag2);
  JointMatch r;
  if (s1.ids.empty() || s2.ids.empty())
  {
    r.problem = "joint sides \"" + name1 + "\" and \"" + name2 + "\": \"" +
                (s1.ids.empty() ? name1 : name2) + "\" has no facets";
    return r;
  }
  // The tolerance: rel_tol times the extent of the joint.
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL},
         hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (std::size_t i = 0; i < s1.x.size(); ++i)
  {
    lo[i % 3] = std::min(lo[i % 3], s1.x[i]);
    hi[i % 3] = std::max(hi[i % 3], s1.x[i]);
  }
  const double tol =
      rel_tol *
      std::max(1e-300, std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]));
  // Distinct points of both sides together: a side-2 node matches a
  // side-1 node if they are the same point.
  std::vector<double> both(s1.x);
  both.insert(both.end(), s2.x.begin(), s2.x.end());
  std::vector<double> points;
  const std::vector<std::int64_t> id = distinct_points(both, tol, points);
  const std::size_t n1 = s1.ids.size();
  std::vector<std::int8_t> on1(points.size() / 3, 0), on2(on1.size(), 0);
  std::map<std::int64_t, std::int64_t> node1_of_point; // a side-1 node
  for (std::size_t i = 0; i < n1; ++i)
  {
    on1[id[i]] = 1;
    node1_of_point[id[i]] = s1.ids[i];
  }
  for (std::size_t i = 0; i < s2.ids.size(); ++i)
    on2[id[n1 + i]] = 1;
  // Nodes of one side without a coincident node on the other.
  std::size_t unmatched = 0, first = 0;
  for (std::size_t p = on1.size(); p-- > 0;)
  {
    if (on1[p] != on2[p])
    {
      ++unmatched;
      first = p;
    }
  }
  if (unmatched > 0)
  {
    r.problem = "joint sides \"" + name1 + "\" and \"" + name2 +
                "\" do not match: " + std::to_string(unmatched) +
                " nodes have no coincident node on the other side (first "
                "at " +
                point_text(&points[3 * first], tdim) + ")";
    return r;
  }
  // Facet for facet: each side-2 facet's points form a side-1 facet.
  const int nv = s1.vertices_per_facet;
  std::set<std::vector<std::int64_t>> facets1;
  for (std::size_t f = 0; f < n1 / nv; ++f)
  {
    std::vector<std::int64_t> key(id.begin() + nv * f,
                                  id.begin() + nv * (f + 1));
    std::sort(key.begin(), key.end());
    facets1.insert(key);
  }
  for (std::size_t f = 0; f < s2.ids.size() / nv; ++f)
  {
    std::vector<std::int64_t> key(id.begin() + n1 + nv * f,
                                  id.begin() + n1 + nv * (f + 1));
    std::sort(key.begin(), key.end());
    if (!facets1.count(key))
    {
      r.problem = "joint sides \"" + name1 + "\" and \"" + name2 +
                  "\" are not conforming: the facet of \"" + name2 + "\" at " +
                  point_text(&points[3 * key[0]], tdim) +
                  " is not a facet of \"" + name1 +
                  "\" (mesh the joint surface once and duplicate its nodes)";
      return r;
    }
  }
  // Pairs: points whose side-2 node differs from the side-1 node.
  std::set<std::int64_t> shared_points, split_points;
  for (std::size_t i = 0; i < s2.ids.size(); ++i)
  {
    const std::int64_t p = id[n1 + i];
    if (node1_of_point[p] == s2.ids[i])
      shared_points.insert(p);
    else
      split_points.insert(p);
  }
  r.pairs = static_cast<std::int64_t>(split_points.size());
  r.shared = static_cast<std::int64_t>(shared_points.size());
  r.tolerance = tol;
  r.points = std::move(points);
  if (r.pairs == 0)
  {
    r.problem = "joint sides \"" + name1 + "\" and \"" + name2 +
                "\" share all their nodes: the joint is not split (duplicate "
                "its nodes, e.g. two volumes meshed with coincident faces "
                "and not merged)";
  }
  return r;
}
std::int64_t shared_joint_points(const JointMatch& a, const JointMatch& b)
{
  const double tol = std::max(a.tolerance, b.tolerance);
  std::vector<double> both(a.points);
  both.insert(both.end(), b.points.begin(), b.points.end());
  std::vector<double> unique;
  const std::vector<std::int64_t> id = distinct_points(both, tol, unique);
  const std::size_t na = a.points.size() / 3;
  return static_cast<std::int64_t>(na + (id.size() - na)) -
         static_cast<std::int64_t>(unique.size() / 3);
}
} // namespace damseis::geometry
