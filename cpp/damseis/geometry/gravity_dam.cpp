// 2D gravity-dam section (with an optional foundation block), built and
// meshed with gmsh and distributed as a DOLFINx mesh.
#include "gravity_dam.h"
#include "tags.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "gmsh_session.h"
#include "root_status.h"
#include <gmsh.h>

namespace damseis::geometry
{
namespace
{
/// Throws std::invalid_argument("GravityDamSection: " + what) unless `ok`.
void require(bool ok, const std::string& what)
{
  if (!ok)
    throw std::invalid_argument("GravityDamSection: " + what);
}

/// Formats a number for error messages.
std::string str(double v)
{
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

/// Checks that the dam polygon heel-toe-neck-crest corners is a simple,
/// counter-clockwise polygon (y-monotone: vertical upstream face on the
/// left, downstream polyline strictly to its right).
void validate_polygon(const GravityDamSection& s)
{
  for (double v : {s.heel_x, s.toe_x, s.base_y, s.neck_x, s.neck_y,
                   s.crest_down_x, s.crest_y, s.water_level})
    require(std::isfinite(v), "all coordinates must be finite");
  require(s.toe_x > s.heel_x, "toe_x (" + str(s.toe_x) +
                                  ") must be greater than heel_x (" +
                                  str(s.heel_x) + ")");
  require(s.neck_y > s.base_y, "neck_y (" + str(s.neck_y) +
                                   ") must be above base_y (" + str(s.base_y) +
                                   ")");
  require(s.crest_y > s.neck_y,
          "crest_y (" + str(s.crest_y) +
              ") must be above the neck (neck_y = " + str(s.neck_y) + ")");
  require(s.neck_x > s.heel_x, "neck_x (" + str(s.neck_x) +
                                   ") must be downstream of heel_x (" +
                                   str(s.heel_x) + ")");
  require(s.crest_down_x > s.heel_x, "crest_down_x (" + str(s.crest_down_x) +
                                         ") must be downstream of heel_x (" +
                                         str(s.heel_x) +
                                         "): the crest width must be positive");
}

/// Checks the whole section: polygon, mesh sizes and foundation.
void validate(const GravityDamSection& s)
{
  validate_polygon(s);
  require(std::isfinite(s.mesh_size) and s.mesh_size > 0,
          "mesh_size must be positive, got " + str(s.mesh_size));
  if (s.foundation)
  {
    const double base = s.toe_x - s.heel_x;
    require(std::isfinite(s.foundation_width) and s.foundation_width > base,
            "foundation_width (" + str(s.foundation_width) +
                ") must exceed the dam base width (" + str(base) + ")");
    require(std::isfinite(s.foundation_depth) and s.foundation_depth > 0,
            "foundation_depth must be positive, got " +
                str(s.foundation_depth));
    require(std::isfinite(s.foundation_mesh_size) and
                s.foundation_mesh_size >= 0,
            "foundation_mesh_size must be >= 0 (0 -> 2.5 x mesh_size), got " +
                str(s.foundation_mesh_size));
    if (s.band_layers > 0)
    {
      const double w = s.band_layers * s.band_size;
      require(std::isfinite(s.band_size) and s.band_size > 0,
              "band_size must be positive, got " + str(s.band_size));
      require(s.foundation_split == GravityDamSection::Split::none,
              "a structured band needs an unsplit foundation block");
      require(w < s.foundation_depth and w < 0.5 * (s.foundation_width - base),
              "the structured band (" + str(w) +
                  " m) must be thinner than the block's depth and than "
                  "its width beside the dam");
    }
    if (s.foundation_split == GravityDamSection::Split::layers)
      require(std::isfinite(s.split_depth) and s.split_depth > 0 and
                  s.split_depth < s.foundation_depth,
              "split_depth must be between 0 and foundation_depth, got " +
                  str(s.split_depth));
  }
}

/// The foundation block's curves and surfaces (built-in kernel).
struct FoundationBlock
{
  std::vector<int> foundation, foundation_2, band, bottom, left, right;
  std::vector<int> floor, top_down;
};

/// A straight line meshed with `segments` equal segments.
int structured_line(int a, int b, int segments)
{
  const int l = gmsh::model::geo::addLine(a, b);
  gmsh::model::geo::mesh::setTransfiniteCurve(l, segments + 1);
  return l;
}

/// The block with a structured band of `s.band_layers` layers of cells of
/// size `s.band_size` along its sides and bottom: five transfinite
/// surfaces (two corners, the bottom strip, the two side strips) around
/// the unstructured inner block.
FoundationBlock build_banded_block(const GravityDamSection& s,
                                   const std::vector<int>& base, int heel,
                                   int toe, double lc_far)
{
  namespace geo = gmsh::model::geo;
  FoundationBlock b;
  const double h = s.band_size, w = s.band_layers * h;
  const double xc = 0.5 * (s.heel_x + s.toe_x);
  const double xl = xc - 0.5 * s.foundation_width;
  const double xr = xc + 0.5 * s.foundation_width;
  const double yb = s.base_y - s.foundation_depth, yt = s.base_y;
  auto point = [&](double x, double y) { return geo::addPoint(x, y, 0, h); };
  // Outer corners, the band's inner corners, and where the inner lines
  // meet the outer boundary.
  const int bl = point(xl, yb), br = point(xr, yb), tr = point(xr, yt),
            tl = point(xl, yt);
  const int ibl = point(xl + w, yb + w), ibr = point(xr - w, yb + w);
  const int itl = point(xl + w, yt), itr = point(xr - w, yt);
  const int lb = point(xl, yb + w), rb = point(xr, yb + w);
  const int bb_l = point(xl + w, yb), bb_r = point(xr - w, yb);
  const int n_w = s.band_layers;
  const int n_x = std::max(
      1, static_cast<int>(std::lround((s.foundation_width - 2 * w) / h)));
  const int n_y =
      std::max(1, static_cast<int>(std::lround((s.foundation_depth - w) / h)));
  // Outer boundary.
  const int bot_l = structured_line(bl, bb_l, n_w);
  const int bot_m = structured_line(bb_l, bb_r, n_x);
  const int bot_r = structured_line(bb_r, br, n_w);
  const int side_rb = structured_line(br, rb, n_w);
  const int side_r = structured_line(rb, tr, n_y);
  const int side_l = structured_line(tl, lb, n_y);
  const int side_lb = structured_line(lb, bl, n_w);
  // Inner lines of the band.
  const int in_bl = structured_line(bb_l, ibl, n_w);
  const int in_br = structured_line(bb_r, ibr, n_w);
  const int in_lb = structured_line(lb, ibl, n_w);
  const int in_rb = structured_line(rb, ibr, n_w);
  const int in_b = structured_line(ibl, ibr, n_x);
  const int in_r = structured_line(ibr, itr, n_y);
  const int in_l = structured_line(itl, ibl, n_y);
  const int top_l = structured_line(itl, tl, n_w);
  const int top_r = structured_line(tr, itr, n_w);
  auto surface = [](const std::vector<int>& loop, bool transfinite)
  {
    const int sf = geo::addPlaneSurface({geo::addCurveLoop(loop, -1, false)});
    if (transfinite)
      geo::mesh::setTransfiniteSurface(sf, "Left");
    return sf;
  };
  b.band = {surface({bot_l, in_bl, -in_lb, side_lb}, true),
            surface({bot_m, in_br, -in_b, -in_bl}, true),
            surface({bot_r, side_rb, in_rb, -in_br}, true),
            surface({-in_rb, side_r, top_r, -in_r}, true),
            surface({side_l, in_lb, -in_l, top_l}, true)};
  b.top_down = {top_r, geo::addLine(itr, toe)};
  b.floor = {geo::addLine(heel, itl), top_l};
  b.foundation = {
      surface({in_b, in_r, b.top_down[1], -base[0], b.floor[0], in_l}, false)};
  b.bottom = {bot_l, bot_m, bot_r};
  b.left = {side_l, side_lb};
  b.right = {side_rb, side_r};
  (void)lc_far;
  return b;
}

/// The block below the dam, sharing the base curves (`base`: heel to toe,
/// in two at `base_mid` when split side by side); in two regions if split.
FoundationBlock build_foundation_block(const GravityDamSection& s,
                                       const std::vector<int>& base, int heel,
                                       int toe, int base_mid, double lc_far)
{
  namespace geo = gmsh::model::geo;
  using Split = GravityDamSection::Split;
  FoundationBlock b;
  const double xc = 0.5 * (s.heel_x + s.toe_x);
  const double xl = xc - 0.5 * s.foundation_width;
  const double xr = xc + 0.5 * s.foundation_width;
  const double yb = s.base_y - s.foundation_depth;
  const int bl = geo::addPoint(xl, yb, 0, lc_far);
  const int br = geo::addPoint(xr, yb, 0, lc_far);
  const int tr = geo::addPoint(xr, s.base_y, 0, lc_far);
  const int tl = geo::addPoint(xl, s.base_y, 0, lc_far);
  b.top_down = {geo::addLine(tr, toe)};
  b.floor = {geo::addLine(heel, tl)};
  auto surface = [](const std::vector<int>& loop)
  { return geo::addPlaneSurface({geo::addCurveLoop(loop, -1, false)}); };
  if (s.foundation_split == Split::side_by_side)
  {
    const int mb = geo::addPoint(xc, yb, 0, lc_far);
    b.bottom = {geo::addLine(bl, mb), geo::addLine(mb, br)};
    const int split = geo::addLine(mb, base_mid);
    b.right = {geo::addLine(br, tr)};
    b.left = {geo::addLine(tl, bl)};
    b.foundation = {
        surface({b.bottom[0], split, -base[0], b.floor[0], b.left[0]})};
    b.foundation_2 = {
        surface({b.bottom[1], b.right[0], b.top_down[0], -base[1], -split})};
  }
  else if (s.foundation_split == Split::layers)
  {
    const double ys = s.base_y - s.split_depth;
    const int ml = geo::addPoint(xl, ys, 0, lc_far);
    const int mr = geo::addPoint(xr, ys, 0, lc_far);
    b.bottom = {geo::addLine(bl, br)};
    const int interface = geo::addLine(ml, mr);
    b.right = {geo::addLine(br, mr), geo::addLine(mr, tr)};
    b.left = {geo::addLine(tl, ml), geo::addLine(ml, bl)};
    b.foundation = {surface({interface, b.right[1], b.top_down[0], -base[0],
                             b.floor[0], b.left[0]})};
    b.foundation_2 = {
        surface({b.bottom[0], b.right[0], -interface, b.left[1]})};
  }
  else
  {
    b.bottom = {geo::addLine(bl, br)};
    b.right = {geo::addLine(br, tr)};
    b.left = {geo::addLine(tl, bl)};
    b.foundation = {surface({b.bottom[0], b.right[0], b.top_down[0], -base[0],
                             b.floor[0], b.left[0]})};
  }
  return b;
}

/// Builds the geometry (built-in kernel, shared curves), the physical
/// groups and the size fields, and meshes with linear triangles.
void build_and_mesh(const GravityDamSection& s)
{
  namespace geo = gmsh::model::geo;
  gmsh::model::add("gravity_dam");
  const double lc = s.mesh_size;

  // Dam polygon, counter-clockwise
  const int heel = geo::addPoint(s.heel_x, s.base_y, 0, lc);
  const int toe = geo::addPoint(s.toe_x, s.base_y, 0, lc);
  const int neck = geo::addPoint(s.neck_x, s.neck_y, 0, lc);
  const int crest_down = geo::addPoint(s.crest_down_x, s.crest_y, 0, lc);
  const int crest_up = geo::addPoint(s.heel_x, s.crest_y, 0, lc);

  // The base, in two at its middle when the block is split side by side.
  using Split = GravityDamSection::Split;
  const bool side_by_side =
      s.foundation && s.foundation_split == Split::side_by_side;
  const double xc = 0.5 * (s.heel_x + s.toe_x);
  std::vector<int> base;
  int base_mid = -1;
  if (side_by_side)
  {
    base_mid = geo::addPoint(xc, s.base_y, 0, lc);
    base = {geo::addLine(heel, base_mid), geo::addLine(base_mid, toe)};
  }
  else
    base = {geo::addLine(heel, toe)};
  const int down1 = geo::addLine(toe, neck);
  const int down2 = geo::addLine(neck, crest_down);
  const int crest = geo::addLine(crest_down, crest_up);
  std::vector<int> upstream;
  if (s.water_level > s.base_y and s.water_level < s.crest_y)
  {
    const int water = geo::addPoint(s.heel_x, s.water_level, 0, lc);
    upstream = {geo::addLine(crest_up, water), geo::addLine(water, heel)};
  }
  else
    upstream = {geo::addLine(crest_up, heel)};

  std::vector<int> dam_loop = base;
  dam_loop.insert(dam_loop.end(), {down1, down2, crest});
  dam_loop.insert(dam_loop.end(), upstream.begin(), upstream.end());
  const int dam =
      geo::addPlaneSurface({geo::addCurveLoop(dam_loop, -1, false)});

  // Foundation block below the dam, sharing the base curve.
  FoundationBlock block;
  double lc_far = lc;
  if (s.foundation)
  {
    lc_far = s.foundation_mesh_size > 0 ? s.foundation_mesh_size : 2.5 * lc;
    block = s.band_layers > 0
                ? build_banded_block(s, base, heel, toe, lc_far)
                : build_foundation_block(s, base, heel, toe, base_mid, lc_far);
  }
  geo::synchronize();

  // Physical groups (tags.h), named as tags.h names them
  auto group = [](int dim, const std::vector<int>& entities, int tag)
  {
    gmsh::model::addPhysicalGroup(dim, entities, tag);
    gmsh::model::setPhysicalName(
        dim, tag, dim == 2 ? tags::region_name(tag) : tags::boundary_name(tag));
  };
  group(2, {dam}, tags::dam);
  group(1, upstream, tags::upstream_face);
  group(1, {down1, down2}, tags::downstream_face);
  group(1, {crest}, tags::crest);
  group(1, base, tags::dam_base);
  if (s.foundation)
  {
    group(2, block.foundation, tags::foundation);
    if (!block.foundation_2.empty())
      group(2, block.foundation_2, tags::foundation_2);
    group(1, block.bottom, tags::foundation_bottom);
    std::vector<int> sides = block.left;
    sides.insert(sides.end(), block.right.begin(), block.right.end());
    group(1, sides, tags::foundation_sides);
    if (!block.band.empty())
      group(2, block.band, tags::foundation_band);
    group(1, block.floor, tags::reservoir_floor);
    group(1, block.top_down, tags::foundation_top_downstream);
  }

  gmsh::option::setNumber("Mesh.Algorithm", 6);
  gmsh::option::setNumber("Mesh.ElementOrder", 1);
  gmsh::option::setNumber("Mesh.RecombineAll", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  if (!s.foundation)
  {
    // Uniform size from the points
    gmsh::option::setNumber("Mesh.MeshSizeMax", lc);
  }
  else
  {
    // Size field: min(lc in the dam (surface and its curves),
    // threshold on the distance to the base: lc -> lc_far)
    namespace field = gmsh::model::mesh::field;
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    gmsh::option::setNumber("Mesh.MeshSizeMax", std::max(lc, lc_far));

    const double base_len = s.toe_x - s.heel_x;
    const int distance = field::add("Distance");
    field::setNumbers(distance, "CurvesList",
                      std::vector<double>(base.begin(), base.end()));
    field::setNumber(distance, "NumPointsPerCurve",
                     std::max(20.0, std::ceil(4 * base_len / lc)));

    // Grade with a size increase of 0.2 m per metre of distance
    const int threshold = field::add("Threshold");
    field::setNumber(threshold, "InField", distance);
    field::setNumber(threshold, "SizeMin", lc);
    field::setNumber(threshold, "SizeMax", lc_far);
    field::setNumber(threshold, "DistMin", lc);
    field::setNumber(threshold, "DistMax",
                     lc + std::max(5 * std::abs(lc_far - lc), lc));

    std::ostringstream expr;
    expr.precision(17);
    expr << lc;
    const int constant = field::add("MathEval");
    field::setString(constant, "F", expr.str());
    const int in_dam = field::add("Restrict");
    field::setNumber(in_dam, "InField", constant);
    field::setNumbers(in_dam, "FacesList", {double(dam)});
    std::vector<double> dam_edges(dam_loop.begin(), dam_loop.end());
    field::setNumbers(in_dam, "EdgesList", dam_edges);

    const int min = field::add("Min");
    field::setNumbers(min, "FieldsList", {double(threshold), double(in_dam)});
    field::setAsBackgroundMesh(min);
  }

  gmsh::model::mesh::generate(2);
}
} // namespace

//-----------------------------------------------------------------------------
std::array<std::array<double, 3>, 5> section_outline(const GravityDamSection& s)
{
  return {{{s.heel_x, s.base_y, 0.0},
           {s.toe_x, s.base_y, 0.0},
           {s.neck_x, s.neck_y, 0.0},
           {s.crest_down_x, s.crest_y, 0.0},
           {s.heel_x, s.crest_y, 0.0}}};
}
//-----------------------------------------------------------------------------
double distance_from_model(const GravityDamSection& s, double x, double y)
{
  // Inside the polygon (not convex: the neck is a reflex corner) by the
  // crossing number; outside, the distance is the nearest edge's.
  const auto p = section_outline(s);
  bool inside = false;
  double d = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 5; ++i)
  {
    const auto& a = p[i];
    const auto& b = p[(i + 1) % 5];
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    const double px = x - a[0], py = y - a[1];
    if ((a[1] > y) != (b[1] > y) && px < ex * py / ey)
      inside = !inside;
    const double t =
        std::clamp((px * ex + py * ey) / (ex * ex + ey * ey), 0.0, 1.0);
    d = std::min(d, std::hypot(px - t * ex, py - t * ey));
  }
  if (inside)
    return 0.0;
  if (s.foundation)
  {
    // The block: centred on the base midpoint, below the base.
    const double mid = 0.5 * (s.heel_x + s.toe_x);
    const double dx =
        std::max(std::abs(x - mid) - 0.5 * s.foundation_width, 0.0);
    const double dy =
        std::max({y - s.base_y, s.base_y - s.foundation_depth - y, 0.0});
    d = std::min(d, std::hypot(dx, dy));
  }
  return d;
}
//-----------------------------------------------------------------------------
double section_area(const GravityDamSection& s)
{
  validate_polygon(s);
  const auto p = section_outline(s);
  double twice = 0;
  for (int i = 0; i < 5; ++i)
  {
    const int j = (i + 1) % 5;
    twice += p[i][0] * p[j][1] - p[j][0] * p[i][1];
  }
  return 0.5 * twice;
}
//-----------------------------------------------------------------------------
Model build_gravity_dam(MPI_Comm comm, const GravityDamSection& s, bool verbose,
                        const std::filesystem::path& mesh_file)
{
  // Deterministic, so every rank throws the same error
  validate(s);

  std::optional<GmshSession> session;
  on_root(comm,
          [&]
          {
            session.emplace(verbose);
            build_and_mesh(s);
            if (!mesh_file.empty())
              gmsh::write(mesh_file.string());
          },
          {"build_gravity_dam: gmsh failed: ",
           "build_gravity_dam: gmsh failed: unknown gmsh error"});
  // gmsh stays open on rank 0 until the conversion is done
  return model_from_gmsh(comm, 2);
}
} // namespace damseis::geometry
