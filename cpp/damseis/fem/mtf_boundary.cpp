#include "mtf_boundary.h"
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <damseis/geometry/root_status.h>
#include <damseis/linalg/all_gather.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/fem/FiniteElement.h>
#include <dolfinx/la/petsc.h>
#include <dolfinx/mesh/Mesh.h>
#include <dolfinx/mesh/utils.h>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace damseis::fem
{
namespace
{
using Point = std::array<double, 3>;

/// The mean of the geometry nodes of entity e of dimension d.
Point centroid(const dolfinx::mesh::Mesh& mesh, int d, std::int32_t e,
               std::vector<Point>* vertices = nullptr)
{
  const std::vector<std::int32_t> e1 = {e};
  const auto nodes = dolfinx::mesh::entities_to_geometry(mesh, d, e1, false);
  std::span<const double> x = mesh.geometry().x();
  Point c = {0, 0, 0};
  const std::size_t n = nodes.size(); // one entity: its nodes
  for (std::size_t i = 0; i < n; ++i)
  {
    Point p;
    for (int j = 0; j < 3; ++j)
      p[j] = x[3 * nodes[i] + j];
    for (int j = 0; j < 3; ++j)
      c[j] += p[j] / n;
    if (vertices)
      vertices->push_back(p);
  }
  return c;
}

/// The unit normal of a boundary facet pointing out of its cell (from the
/// facet's first vertices: straight edges, flat triangles).
Point outward_normal(const dolfinx::mesh::Mesh& mesh, std::int32_t facet,
                     std::int32_t cell)
{
  const int tdim = mesh.topology().dim();
  std::vector<Point> v;
  const Point fc = centroid(mesh, tdim - 1, facet, &v);
  const Point cc = centroid(mesh, tdim, cell);
  Point n;
  const Point t1 = {v[1][0] - v[0][0], v[1][1] - v[0][1], v[1][2] - v[0][2]};
  if (tdim == 2)
    n = {t1[1], -t1[0], 0.0};
  else
  {
    const Point t2 = {v[2][0] - v[0][0], v[2][1] - v[0][1], v[2][2] - v[0][2]};
    n = {t1[1] * t2[2] - t1[2] * t2[1], t1[2] * t2[0] - t1[0] * t2[2],
         t1[0] * t2[1] - t1[1] * t2[0]};
  }
  double dot = 0.0, norm = 0.0;
  for (int j = 0; j < 3; ++j)
  {
    dot += n[j] * (fc[j] - cc[j]);
    norm += n[j] * n[j];
  }
  const double scale = (dot < 0.0 ? -1.0 : 1.0) / std::sqrt(norm);
  for (double& c : n)
    c *= scale;
  return n;
}

std::string format(const Point& x, int dim)
{
  std::ostringstream s;
  s << "(";
  for (int j = 0; j < dim; ++j)
    s << (j ? ", " : "") << x[j];
  s << ")";
  return s.str();
}

/// The message of the lowest rank that has one (empty: none), on every
/// rank (collective).
std::string lowest_rank_message(MPI_Comm comm, const std::string& message)
{
  int rank = 0, first = 0;
  MPI_Comm_rank(comm, &rank);
  const int mine = message.empty() ? 1 << 30 : rank;
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm);
  if (first == 1 << 30)
    return {};
  return geometry::broadcast_from_root(comm, message, first);
}

/// The global block of each local (owned and ghost) block of V.
std::vector<std::int64_t> global_blocks(const dolfinx::fem::FunctionSpace& V)
{
  const auto& map = *V.dofmap()->index_map;
  const std::int32_t n = map.size_local() + map.num_ghosts();
  std::vector<std::int32_t> local(n);
  std::iota(local.begin(), local.end(), 0);
  std::vector<std::int64_t> global(n);
  map.local_to_global(local, global);
  return global;
}

/// Whether boundary node a takes precedence over b at a node on facets of
/// both: the bottom's (corners belong to the bottom), else the smaller
/// normal in lexicographic order (a vertical edge's node marches along
/// one side's normal), an order that does not depend on the partition.
bool precedes(const MtfBoundary::Node& a, const MtfBoundary::Node& b)
{
  if (a.bottom != b.bottom)
    return a.bottom;
  return a.normal < b.normal;
}

/// The owned nodes of V on the facets tagged `tags`, with the outward
/// normal of one of their facets, or straight down where one of them is a
/// bottom facet. A node's facets may all lie on other ranks: every rank
/// sends the nodes of its facets (owned and ghost) to all, and each keeps
/// its own (collective).
std::map<std::int32_t, MtfBoundary::Node>
boundary_nodes(const dolfinx::fem::FunctionSpace& V,
               const dolfinx::mesh::MeshTags<std::int32_t>& facets,
               const std::vector<int>& tags)
{
  const auto& mesh = *V.mesh();
  const auto& dofmap = *V.dofmap();
  const std::int32_t owned = dofmap.index_map->size_local();
  const std::vector<double> x = V.tabulate_dof_coordinates(false);
  const std::vector<std::int64_t> global = global_blocks(V);
  const int tdim = mesh.topology().dim(), fdim = tdim - 1;
  auto& topology = mesh.topology_mutable();
  topology.create_connectivity(fdim, tdim);
  topology.create_connectivity(tdim, fdim);
  auto f_to_c = topology.connectivity(fdim, tdim);
  auto c_to_f = topology.connectivity(tdim, fdim);
  const auto& layout = dofmap.element_dof_layout();
  // This rank's facets' nodes: global block, normal, bottom (0 / 1).
  std::vector<std::int64_t> blocks;
  std::vector<double> data; // normal (3), bottom
  for (std::size_t i = 0; i < facets.indices().size(); ++i)
  {
    if (std::find(tags.begin(), tags.end(), facets.values()[i]) == tags.end())
      continue;
    const std::int32_t f = facets.indices()[i];
    const std::int32_t c = f_to_c->links(f)[0];
    auto cf = c_to_f->links(c);
    const int local = static_cast<int>(
        std::distance(cf.begin(), std::find(cf.begin(), cf.end(), f)));
    Point n = outward_normal(mesh, f, c);
    const bool bottom = n[tdim - 1] < -0.9;
    if (bottom)
    {
      n = {0, 0, 0};
      n[tdim - 1] = -1.0;
    }
    auto cell_dofs = dofmap.cell_dofs(c);
    for (int ld : layout.entity_closure_dofs(fdim, local))
    {
      blocks.push_back(global[cell_dofs[ld]]);
      data.insert(data.end(), {n[0], n[1], n[2], bottom ? 1.0 : 0.0});
    }
  }
  const MPI_Comm comm = mesh.comm();
  blocks = linalg::all_gather(comm, blocks);
  data = linalg::all_gather(comm, data);
  // The owned ones, each with the normal that takes precedence.
  const std::int64_t first = dofmap.index_map->local_range()[0];
  std::map<std::int32_t, MtfBoundary::Node> nodes;
  for (std::size_t i = 0; i < blocks.size(); ++i)
  {
    if (blocks[i] < first || blocks[i] >= first + owned)
      continue;
    const auto b = static_cast<std::int32_t>(blocks[i] - first);
    const MtfBoundary::Node node{
        {x[3 * b], x[3 * b + 1], x[3 * b + 2]},
        {data[4 * i], data[4 * i + 1], data[4 * i + 2]},
        data[4 * i + 3] > 0.5};
    auto [it, inserted] = nodes.try_emplace(b, node);
    if (!inserted && precedes(node, it->second))
      it->second = node;
  }
  return nodes;
}

/// The band's cells of every rank (their vertices and the global blocks of
/// their nodes) in a grid of boxes of the node spacing, and the
/// weights that interpolate the field at a point from its cell's nodes
/// (the element's basis there: at a node, that node alone).
class BandCells
{
public:
  BandCells(const dolfinx::fem::FunctionSpace& V,
            const std::vector<std::int32_t>& cells, double size)
      : _size(size), _tdim(V.mesh()->topology().dim()),
        _element(V.dofmap()->index_map_bs() > 1
                     ? V.element()->extract_sub_element({0})
                     : V.element())
  {
    if (_element->needs_dof_transformations())
      throw std::invalid_argument("the multi-transmitting boundary needs a "
                                  "Lagrange element (no dof transformations)");
    const auto& mesh = *V.mesh();
    const auto& dofmap = *V.dofmap();
    const std::vector<std::int64_t> global = global_blocks(V);
    const std::int32_t owned_cells =
        mesh.topology().index_map(_tdim)->size_local();
    const auto& x_dofmap = mesh.geometry().dofmap();
    std::span<const double> x = mesh.geometry().x();
    _nodes = _element->space_dimension();
    // This rank's owned band cells (a ghost is another rank's owned cell).
    for (std::int32_t c : cells)
    {
      if (c >= owned_cells)
        continue;
      auto g = x_dofmap.links(c);
      for (int v = 0; v <= _tdim; ++v)
        _x.insert(_x.end(), x.begin() + 3 * g[v], x.begin() + 3 * g[v] + 3);
      for (std::int32_t b : dofmap.cell_dofs(c))
        _blocks.push_back(global[b]);
    }
    const MPI_Comm comm = mesh.comm();
    _x = linalg::all_gather(comm, _x);
    _blocks = linalg::all_gather(comm, _blocks);
    const int nv = _tdim + 1;
    const std::size_t n = _x.size() / (3 * nv);
    for (std::size_t c = 0; c < n; ++c)
    {
      Key lo, hi;
      for (int j = 0; j < 3; ++j)
      {
        double a = _x[3 * nv * c + j], b = a;
        for (int v = 1; v < nv; ++v)
        {
          a = std::min(a, _x[3 * (nv * c + v) + j]);
          b = std::max(b, _x[3 * (nv * c + v) + j]);
        }
        lo[j] = key(a - 1e-6 * _size);
        hi[j] = key(b + 1e-6 * _size);
      }
      for (auto i = lo[0]; i <= hi[0]; ++i)
        for (auto j = lo[1]; j <= hi[1]; ++j)
          for (auto k = lo[2]; k <= hi[2]; ++k)
            _grid[{i, j, k}].push_back(static_cast<std::int32_t>(c));
    }
  }

  /// The global blocks and weights that interpolate the field at p, or
  /// none if no band cell contains p.
  std::vector<std::pair<std::int64_t, double>> weights(const Point& p) const
  {
    auto it = _grid.find({key(p[0]), key(p[1]), key(p[2])});
    if (it == _grid.end())
      return {};
    // The cell with p deepest inside (the largest least barycentric).
    std::int32_t best = -1;
    std::array<double, 3> X_best{};
    double depth = -1e-8;
    for (std::int32_t c : it->second)
    {
      const auto [X, least] = reference(c, p);
      if (least > depth)
      {
        depth = least;
        best = c;
        X_best = X;
      }
    }
    if (best < 0)
      return {};
    const auto [phi, shape] =
        _element->tabulate(std::span<const double>(X_best.data(), _tdim),
                           {1, static_cast<std::size_t>(_tdim)}, 0);
    std::vector<std::pair<std::int64_t, double>> w;
    for (int i = 0; i < _nodes; ++i)
      if (std::abs(phi[i]) > 1e-12)
        w.emplace_back(_blocks[best * _nodes + i], phi[i]);
    return w;
  }

private:
  using Key = std::array<std::int64_t, 3>;
  std::int64_t key(double x) const
  {
    return static_cast<std::int64_t>(std::floor(x / _size));
  }
  /// p's reference coordinates in cell c (affine map from its vertices)
  /// and its least barycentric coordinate.
  std::pair<std::array<double, 3>, double> reference(std::int32_t c,
                                                     const Point& p) const
  {
    const int nv = _tdim + 1;
    const double* v = _x.data() + 3 * nv * c;
    Eigen::Matrix3d J = Eigen::Matrix3d::Identity();
    Eigen::Vector3d r = Eigen::Vector3d::Zero();
    for (int i = 0; i < _tdim; ++i)
    {
      for (int j = 1; j <= _tdim; ++j)
        J(i, j - 1) = v[3 * j + i] - v[i];
      r(i) = p[i] - v[i];
    }
    const Eigen::Vector3d X = J.partialPivLu().solve(r);
    double least = 1.0;
    for (int i = 0; i < _tdim; ++i)
      least = std::min(least, X(i));
    least = std::min(least, 1.0 - X.head(_tdim).sum());
    return {{X(0), X(1), X(2)}, least};
  }

  double _size;
  int _tdim, _nodes = 0;
  std::shared_ptr<const dolfinx::fem::FiniteElement> _element;
  std::vector<double> _x;            ///< per cell, its vertices (3 each)
  std::vector<std::int64_t> _blocks; ///< per cell, its nodes' global blocks
  std::map<Key, std::vector<std::int32_t>> _grid;
};
/// The message for stencil point k of `node` at p, which no band cell
/// holds.
std::string missing_point(const Point& p, const MtfBoundary::Node& node, int k,
                          double dx, int tdim)
{
  return "the foundation has no band for the multi-transmitting boundary "
         "at " +
         format(p, tdim) + ", " + std::to_string(k) +
         " node spacings inward of the boundary node at " +
         format(node.x, tdim) + " (the band must reach 2N node spacings of " +
         std::to_string(dx) + " m inward along the normals)";
}

/// The formula's points x_k = x_0 - k dx n (k = 0 .. width - 1) of every
/// node, each as the global blocks and weights that interpolate the field
/// there in the band's cells, in the nodes' order; `missing` names the
/// first point no band cell holds (then the points stop there).
struct Stencils
{
  std::vector<std::vector<std::pair<std::int64_t, double>>> points;
  std::string missing;
};

Stencils find_stencils(const std::map<std::int32_t, MtfBoundary::Node>& nodes,
                       const BandCells& band, int width, double dx, int tdim)
{
  Stencils s;
  for (const auto& [b, node] : nodes)
    for (int k = 0; k < width; ++k)
    {
      Point p = node.x;
      for (int j = 0; j < 3; ++j)
        p[j] -= k * dx * node.normal[j];
      s.points.push_back(band.weights(p));
      if (s.points.back().empty())
      {
        s.missing = missing_point(p, node, k, dx, tdim);
        return s;
      }
    }
  return s;
}
} // namespace

std::string band_gap(const dolfinx::fem::FunctionSpace& V,
                     const dolfinx::mesh::MeshTags<std::int32_t>& facets,
                     const std::vector<int>& boundary_tags,
                     const std::vector<std::int32_t>& band_cells, int order,
                     double spacing)
{
  const auto& mesh = *V.mesh();
  const Stencils stencils =
      find_stencils(boundary_nodes(V, facets, boundary_tags),
                    BandCells(V, band_cells, spacing), 2 * order + 1, spacing,
                    mesh.topology().dim());
  return lowest_rank_message(mesh.comm(), stencils.missing);
}

MtfBoundary::MtfBoundary(const dolfinx::fem::FunctionSpace& V,
                         const dolfinx::mesh::MeshTags<std::int32_t>& facets,
                         const std::vector<int>& boundary_tags,
                         const std::vector<std::int32_t>& band_cells,
                         MtfSettings s, KnownField known)
    : _normal(s.order,
              std::clamp(s.speed_normal * s.dt / s.spacing, 1e-12, 1.0),
              s.drift),
      _tangential(s.order,
                  std::clamp(s.speed_tangential * s.dt / s.spacing, 1e-12, 1.0),
                  s.drift),
      _s(s), _known(std::move(known))
{
  const auto& mesh = *V.mesh();
  const MPI_Comm comm = mesh.comm();
  if (s.order < 1 || s.order > 2)
    throw std::invalid_argument("the multi-transmitting boundary takes order "
                                "1 or 2");
  if (!(s.speed_tangential > 0.0 && s.courant() <= 1.0))
  {
    std::ostringstream m;
    m << "the multi-transmitting boundary needs s = c_a dt / dx in (0, 1]; "
         "it is "
      << s.courant() << " (c_p " << s.speed_normal << " m/s, dt " << s.dt
      << " s, dx " << s.spacing << " m): a smaller time step";
    throw std::invalid_argument(m.str());
  }
  const auto& map = *V.dofmap()->index_map;
  _dim = V.dofmap()->index_map_bs();
  const std::int64_t first_block = map.local_range()[0];
  const int tdim = mesh.topology().dim();
  const double dx = s.spacing;
  const std::map<std::int32_t, Node> nodes =
      boundary_nodes(V, facets, boundary_tags);
  const BandCells band(V, band_cells, s.spacing);

  // The stencils: per node and k, the gathered blocks and their weights.
  const int width = _normal.stencil();
  const Stencils stencils = find_stencils(nodes, band, width, dx, tdim);
  if (const std::string m = lowest_rank_message(comm, stencils.missing);
      !m.empty())
    throw std::invalid_argument(m);
  std::map<std::int64_t, std::int32_t> position; // global block -> buffer
  std::vector<PetscInt> gathered;
  _offsets.push_back(0);
  auto point = stencils.points.begin();
  for (const auto& [b, node] : nodes)
  {
    for (int k = 0; k < width; ++k, ++point)
    {
      for (const auto& [block, w] : *point)
      {
        auto [it, inserted] = position.try_emplace(
            block, static_cast<std::int32_t>(position.size()));
        if (inserted)
          for (int c = 0; c < _dim; ++c)
            gathered.push_back(block * _dim + c);
        _positions.push_back(it->second);
        _weights.push_back(w);
      }
      _offsets.push_back(static_cast<std::int32_t>(_positions.size()));
    }
    _nodes.push_back(node);
    for (int c = 0; c < _dim; ++c)
      _rows.push_back((first_block + b) * _dim + c);
  }
  std::int64_t counts[2] = {static_cast<std::int64_t>(_nodes.size()),
                            std::count_if(_nodes.begin(), _nodes.end(),
                                          [](const Node& n)
                                          { return n.bottom; })};
  MPI_Allreduce(counts, _counts.data(), 2, MPI_INT64_T, MPI_SUM, comm);

  // The scatter from the unknowns' layout to this rank's stencil values.
  Vec layout_vec = dolfinx::la::petsc::create_vector(map, _dim);
  IS from;
  ISCreateGeneral(PETSC_COMM_SELF, static_cast<PetscInt>(gathered.size()),
                  gathered.data(), PETSC_COPY_VALUES, &from);
  for (Vec& x : _gathered)
    VecCreateSeq(PETSC_COMM_SELF, static_cast<PetscInt>(gathered.size()), &x);
  VecScatterCreate(layout_vec, from, _gathered[0], nullptr, &_scatter);
  ISDestroy(&from);
  VecDestroy(&layout_vec);
}

MtfBoundary::~MtfBoundary()
{
  VecScatterDestroy(&_scatter);
  for (Vec& x : _gathered)
    VecDestroy(&x);
}

void MtfBoundary::values(int n_next, const dynamics::Kinematics& now,
                         const dynamics::Kinematics& prev,
                         dynamics::PrescribedValues& out)
{
  // The stencils' u, v, a at steps n (0-2) and n - 1 (3-5).
  const std::array<Vec, 6> fields = {now.u,  now.v,  now.a,
                                     prev.u, prev.v, prev.a};
  std::array<const double*, 6> gathered{};
  for (int f = 0; f < 6; ++f)
  {
    VecScatterBegin(_scatter, fields[f], _gathered[f], INSERT_VALUES,
                    SCATTER_FORWARD);
    VecScatterEnd(_scatter, fields[f], _gathered[f], INSERT_VALUES,
                  SCATTER_FORWARD);
    VecGetArrayRead(_gathered[f], &gathered[f]);
  }
  const int width = _normal.stencil(), order = _normal.order();
  const double dt = _s.dt, dx = _s.spacing;
  const double t = n_next * dt;
  std::array<std::vector<double>*, 3> results = {&out.u, &out.v, &out.a};
  for (std::size_t i = 0; i < _nodes.size(); ++i)
  {
    const Node& node = _nodes[i];
    // Per derivative q (u, v, a): x_0 = x_in(x_0, t_(n+1)) + sum_j sum_k
    // w_jk (x - x_in)(x_k, t_(n+1-j)) for the normal and the tangential
    // formula's weights.
    std::array<std::array<double, 3>, 3> normal{}, tangential{};
    for (int j = 1; j <= order; ++j)
      for (int k = 0; k <= 2 * j; ++k)
      {
        Point p = node.x;
        for (int d = 0; d < 3; ++d)
          p[d] -= k * dx * node.normal[d];
        const boundary::FreeFieldState in = _known(p, node.bottom, t - j * dt);
        const std::array<const std::array<double, 3>*, 3> known = {&in.u, &in.v,
                                                                   &in.a};
        const std::size_t at = i * width + k;
        const double wn = _normal.weight(j, k), wt = _tangential.weight(j, k);
        for (int q = 0; q < 3; ++q)
        {
          const double* history = gathered[q + (j == 1 ? 0 : 3)];
          std::array<double, 3> x{};
          for (std::int32_t e = _offsets[at]; e < _offsets[at + 1]; ++e)
            for (int c = 0; c < _dim; ++c)
              x[c] += _weights[e] * history[_positions[e] * _dim + c];
          for (int c = 0; c < _dim; ++c)
          {
            const double scattered = x[c] - (*known[q])[c];
            normal[q][c] += wn * scattered;
            tangential[q][c] += wt * scattered;
          }
        }
      }
    // x = x_in + n (n . normal-formula) + (I - n n^T) tangential-formula.
    const boundary::FreeFieldState in = _known(node.x, node.bottom, t);
    const std::array<const std::array<double, 3>*, 3> known = {&in.u, &in.v,
                                                               &in.a};
    for (int q = 0; q < 3; ++q)
    {
      double along = 0.0, t_along = 0.0;
      for (int c = 0; c < _dim; ++c)
      {
        along += node.normal[c] * normal[q][c];
        t_along += node.normal[c] * tangential[q][c];
      }
      for (int c = 0; c < _dim; ++c)
        (*results[q])[i * _dim + c] = (*known[q])[c] + tangential[q][c] +
                                      node.normal[c] * (along - t_along);
    }
  }
  for (int f = 0; f < 6; ++f)
    VecRestoreArrayRead(_gathered[f], &gathered[f]);
}
} // namespace damseis::fem
