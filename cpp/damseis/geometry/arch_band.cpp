#include "arch_band.h"
#include "occ_cuts.h"
#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

namespace damseis::geometry
{
namespace
{
/// The x of the band's vertical cuts, ascending: the block's faces, the
/// band's inner faces, the rims and the floor's edges.
std::vector<double> band_x_cuts(const ArchDamGeometry& g, const ModelBox& e,
                                double w)
{
  const double H = g.height();
  return {e.x0,           e.x0 + w,     g.x_left(H), g.x_left(0.0),
          g.x_right(0.0), g.x_right(H), e.x1 - w,    e.x1};
}
} // namespace

gmsh::vectorpair split_band(const ArchDamGeometry& g, const ModelBox& e,
                            const gmsh::vectorpair& rock, double w)
{
  namespace occ = gmsh::model::occ;
  const double H = g.height();
  const double top = e.z1 + 0.5 * H; // above the block
  const int inner =
      occ::addBox(e.x0 + w, e.y0 + w, e.z0 + w, e.x1 - e.x0 - 2 * w,
                  e.y1 - e.y0 - 2 * w, top - e.z0 - w);
  gmsh::vectorpair core, band;
  std::vector<gmsh::vectorpair> map;
  occ::intersect(rock, {{3, inner}}, core, map, -1, false, false);
  occ::cut(rock, {{3, inner}}, band, map, -1, true, true);
  if (core.size() != 1)
    throw std::runtime_error("arch dam: the band left " +
                             std::to_string(core.size()) +
                             " core volumes (expected 1)");
  // Cutting planes: rectangles over the block's extent (1 m margins).
  const double m = 1.0;
  auto plane = [&](int axis, double v)
  {
    std::array<std::array<double, 3>, 4> c;
    const double lo[3] = {e.x0 - m, e.y0 - m, e.z0 - m};
    const double hi[3] = {e.x1 + m, e.y1 + m, top};
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    const double ua[4] = {lo[a], hi[a], hi[a], lo[a]};
    const double ub[4] = {lo[b], lo[b], hi[b], hi[b]};
    std::vector<int> pts, lines;
    for (int k = 0; k < 4; ++k)
    {
      c[k][axis] = v;
      c[k][a] = ua[k];
      c[k][b] = ub[k];
      pts.push_back(occ::addPoint(c[k][0], c[k][1], c[k][2]));
    }
    for (int k = 0; k < 4; ++k)
      lines.push_back(occ::addLine(pts[k], pts[(k + 1) % 4]));
    return std::pair{2, occ::addPlaneSurface({occ::addCurveLoop(lines)})};
  };
  gmsh::vectorpair tools = {plane(1, e.y0 + w), plane(1, e.y1 - w),
                            plane(2, e.z0 + w)};
  const std::vector<double> xs = band_x_cuts(g, e, w);
  for (std::size_t i = 1; i + 1 < xs.size(); ++i)
    tools.push_back(plane(0, xs[i]));
  const gmsh::vectorpair pieces = cut_by_surfaces(band, tools);
  gmsh::vectorpair all = core;
  all.insert(all.end(), pieces.begin(), pieces.end());
  return all;
}

namespace
{
using Corner = std::pair<int, std::array<double, 3>>;

/// The corner points of entity (dim, tag) with their coordinates.
std::vector<Corner> corners_of(int dim, int tag)
{
  gmsh::vectorpair points;
  gmsh::model::getBoundary({{dim, tag}}, points, false, false, true);
  std::vector<Corner> c;
  for (const auto& [d, p] : points)
  {
    std::vector<double> x, none;
    gmsh::model::getValue(0, std::abs(p), none, x);
    c.push_back({std::abs(p), {x[0], x[1], x[2]}});
  }
  return c;
}

/// Four corners as (u-, v-), (u+, v-), (u+, v+), (u-, v+) in the axes u <
/// v: the two with the smaller v first, each pair by u.
std::vector<int> ordered(std::vector<Corner> c, int u, int v)
{
  std::sort(c.begin(), c.end(),
            [&](const Corner& a, const Corner& b)
            { return a.second[v] < b.second[v]; });
  auto by_u = [&](const Corner& a, const Corner& b)
  { return a.second[u] < b.second[u]; };
  std::sort(c.begin(), c.begin() + 2, by_u);
  std::sort(c.begin() + 2, c.end(), by_u);
  return {c[0].first, c[1].first, c[3].first, c[2].first};
}

/// A band face's corners in the global frame: its in-plane axes are the
/// two global axes other than its normal's (z for faces that are not
/// vertical, else the larger of the normal's x and y).
std::vector<int> surface_corners(int f)
{
  const std::vector<Corner> c = corners_of(2, f);
  if (c.size() != 4)
    throw std::runtime_error("arch dam: a face of the transmitting "
                             "boundary's band has " +
                             std::to_string(c.size()) + " corners, not 4");
  std::array<double, 3> a{}, b{}, n{};
  for (int k = 0; k < 3; ++k)
  {
    a[k] = c[1].second[k] - c[0].second[k];
    b[k] = c[2].second[k] - c[0].second[k];
  }
  n = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
       a[0] * b[1] - a[1] * b[0]};
  // The pieces' bottoms and tops (horizontal, or a wall's segment above a
  // column) in the volumes' frame of their bottoms and tops: x, y; their
  // sides (vertical) in their planes: y, z or x, z.
  const double size = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const int normal = std::abs(n[2]) > 1e-9 * size
                         ? 2
                         : (std::abs(n[0]) > std::abs(n[1]) ? 0 : 1);
  const int u = normal == 0 ? 1 : 0, v = normal == 2 ? 1 : 2;
  return ordered(c, u, v);
}

/// A band piece's corners in the global frame: the bottom face's (the
/// four lowest) in the order of ordered(x, y), then the top face's.
std::vector<int> volume_corners(int vol)
{
  std::vector<Corner> c = corners_of(3, vol);
  if (c.size() != 8)
    throw std::runtime_error("arch dam: a piece of the transmitting "
                             "boundary's band has " +
                             std::to_string(c.size()) + " corners, not 8");
  std::sort(c.begin(), c.end(),
            [](const Corner& a, const Corner& b)
            { return a.second[2] < b.second[2]; });
  std::vector<int> out =
      ordered(std::vector<Corner>(c.begin(), c.begin() + 4), 0, 1);
  const std::vector<int> top =
      ordered(std::vector<Corner>(c.begin() + 4, c.end()), 0, 1);
  out.insert(out.end(), top.begin(), top.end());
  return out;
}
} // namespace

/// The band's volumes meshed as structured (transfinite) tetrahedra: each
/// curve gets the node count of its interval, so that opposite edges of
/// every piece match: along x (the pieces' bottoms and tops, a wall's
/// edge) by the interval between the cuts in which it lies, along y by its
/// length (the band's layers of `h`), along z by its length in the bottom
/// band and above it by the tallest piece's height (every vertical edge
/// there runs from the bottom band to the rock's surface). A piece beside
/// a wall of several segments (a U canyon) is not a hexahedron: gmsh
/// meshes it unstructured against its neighbours' structured faces, and
/// the formula's stencil points in it are interpolated (fem/MtfBoundary).
void structure_band(const ArchDamGeometry& g, const ModelBox& e, double w,
                    double h, const std::vector<int>& band_volumes)
{
  const double H = g.height(), tol = 1e-6 * H;
  const std::vector<double> xb = band_x_cuts(g, e, w);
  auto segments = [&](double length)
  { return std::max(1, static_cast<int>(std::lround(length / h))); };
  const int columns = segments(H - (e.z0 + w));
  std::set<int> curves, surfaces;
  std::vector<int> hexahedra;
  for (int v : band_volumes)
  {
    gmsh::vectorpair faces;
    gmsh::model::getBoundary({{3, v}}, faces, false, false, false);
    if (faces.size() != 6 || corners_of(3, v).size() != 8)
      continue; // beside a wall of several segments: unstructured
    hexahedra.push_back(v);
    for (const auto& [d, f] : faces)
    {
      surfaces.insert(std::abs(f));
      gmsh::vectorpair edges;
      gmsh::model::getBoundary({{2, std::abs(f)}}, edges, false, false, false);
      for (const auto& [d1, c] : edges)
        curves.insert(std::abs(c));
    }
  }
  for (int c : curves)
  {
    double x0, y0, z0, x1, y1, z1;
    gmsh::model::getBoundingBox(1, c, x0, y0, z0, x1, y1, z1);
    int n = 1;
    if (x1 - x0 > tol) // along x, or along a wall
    {
      const double xm = 0.5 * (x0 + x1);
      for (std::size_t i = 0; i + 1 < xb.size(); ++i)
        if (xm >= xb[i] - tol && xm <= xb[i + 1] + tol)
        {
          n = segments(xb[i + 1] - xb[i]);
          break;
        }
    }
    else if (y1 - y0 > tol)
      n = segments(y1 - y0);
    else // vertical
      n = z1 <= e.z0 + w + tol ? segments(z1 - z0) : columns;
    gmsh::model::mesh::setTransfiniteCurve(c, n + 1);
  }
  // The corners in one global frame, so that gmsh's split of every piece
  // into tetrahedra matches the triangles of its faces, which its
  // neighbours (pieces or the core) share: with gmsh's default corners a
  // third of the faces did not (a non-conforming mesh).
  for (int f : surfaces)
    gmsh::model::mesh::setTransfiniteSurface(f, "Left", surface_corners(f));
  for (int v : hexahedra)
    gmsh::model::mesh::setTransfiniteVolume(v, volume_corners(v));
}

namespace
{
using Face = std::array<std::size_t, 3>;

/// The sorted node triples of the mesh of entity (dim, tag):
/// the faces of its tetrahedra (type 4) or its triangles (type 2).
std::set<Face> faces_of(int dim, int tag)
{
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> elements, nodes;
  gmsh::model::mesh::getElements(types, elements, nodes, dim, tag);
  std::set<Face> faces;
  for (std::size_t t = 0; t < types.size(); ++t)
  {
    const int per = dim == 3 ? 4 : 3;
    for (std::size_t e = 0; e < nodes[t].size() / per; ++e)
      for (int skip = 0; skip < (dim == 3 ? 4 : 1); ++skip)
      {
        Face f;
        int m = 0;
        for (int j = 0; j < per; ++j)
          if (dim == 2 || j != skip)
            f[m++] = nodes[t][per * e + j];
        std::sort(f.begin(), f.end());
        faces.insert(f);
      }
  }
  return faces;
}
} // namespace

std::vector<std::pair<int, int>>
band_mismatches(const std::vector<int>& band_volumes)
{
  std::vector<std::pair<int, int>> out;
  for (int v : band_volumes)
  {
    const std::set<Face> tets = faces_of(3, v);
    gmsh::vectorpair bounding;
    gmsh::model::getBoundary({{3, v}}, bounding, false, false, false);
    for (const auto& [d, f] : bounding)
    {
      const std::set<Face> triangles = faces_of(2, std::abs(f));
      const bool all =
          std::all_of(triangles.begin(), triangles.end(),
                      [&](const Face& t) { return tets.count(t) > 0; });
      if (!all)
        out.push_back({v, std::abs(f)});
    }
  }
  return out;
}

} // namespace damseis::geometry
