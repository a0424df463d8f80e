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
  gmsh::vectorpair tools = {plane(0, e.x0 + w),      plane(0, e.x1 - w),
                            plane(0, g.x_left(0.0)), plane(0, g.x_right(0.0)),
                            plane(1, e.y0 + w),      plane(1, e.y1 - w),
                            plane(2, e.z0 + w),      plane(2, 0.0)};
  const gmsh::vectorpair pieces = cut_by_surfaces(band, tools);
  gmsh::vectorpair all = core;
  all.insert(all.end(), pieces.begin(), pieces.end());
  return all;
}

/// The band's volumes meshed as structured (transfinite) tetrahedra: each
/// curve gets the node count of its interval, so that opposite edges of
/// every piece match: along y and z by its extent (the band's layers of
/// `h`), along x by the interval between the band's and the floor's
/// planes in which it lies. Beside the walls the pieces are trapezoids
/// (their edges at the floor level longer than at the crest, where the
/// walls reach the rims): their count is the crest edge's, so that no
/// cell is narrower than h there (the explicit band's stable step).
void structure_band(const ArchDamGeometry& g, const ModelBox& e, double w,
                    double h, const std::vector<int>& band_volumes)
{
  const double H = g.height(), tol = 1e-6 * H;
  const std::vector<double> xb = {e.x0,           e.x0 + w, g.x_left(0.0),
                                  g.x_right(0.0), e.x1 - w, e.x1};
  auto segments = [&](double length)
  { return std::max(1, static_cast<int>(std::lround(length / h))); };
  // Per x interval, the length its count is made for (beside the walls:
  // the crest edge, from the band to the rim).
  const std::vector<double> x_length = {w, g.x_left(H) - (e.x0 + w),
                                        g.x_right(0.0) - g.x_left(0.0),
                                        (e.x1 - w) - g.x_right(H), w};
  std::set<int> curves, surfaces;
  for (int v : band_volumes)
  {
    gmsh::vectorpair faces;
    gmsh::model::getBoundary({{3, v}}, faces, false, false, false);
    if (faces.size() != 6)
      throw std::runtime_error(
          "arch dam: a piece of the transmitting boundary's band has " +
          std::to_string(faces.size()) +
          " faces (a hexahedron has 6); is the canyon V-shaped?");
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
    if (z1 - z0 > tol) // vertical, or along a wall
      n = segments(z1 - z0);
    else if (y1 - y0 > tol)
      n = segments(y1 - y0);
    else
    {
      const double xm = 0.5 * (x0 + x1);
      for (std::size_t i = 0; i + 1 < xb.size(); ++i)
        if (xm >= xb[i] - tol && xm <= xb[i + 1] + tol)
        {
          n = segments(x_length[i]);
          break;
        }
    }
    gmsh::model::mesh::setTransfiniteCurve(c, n + 1);
  }
  for (int f : surfaces)
    gmsh::model::mesh::setTransfiniteSurface(f);
  for (int v : band_volumes)
    gmsh::model::mesh::setTransfiniteVolume(v);
}

} // namespace damseis::geometry
