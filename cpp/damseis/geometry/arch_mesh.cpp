// 3D arch dam + canyon + foundation: gmsh/OCC construction, meshing, joint
// splitting and distribution.
#include "arch_mesh.h"
#include "arch_band.h"
#include "model_arrays.h"
#include "occ_cuts.h"
#include "tags.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <set>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "gmsh_session.h"
#include "root_status.h"
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/CoordinateElement.h>
#include <dolfinx/graph/AdjacencyList.h>
#include <dolfinx/io/XDMFFile.h>
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
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Mesh arrays read from gmsh on rank 0 (0-based node indices, DOLFINx
/// node order).
struct MeshArrays
{
  std::vector<double> x;
  std::vector<std::int64_t> cells;
  std::vector<std::int32_t> cell_values;
  std::vector<std::int64_t> facets;
  std::vector<std::int32_t> facet_values;
  std::vector<JointPairs> joints;
  double geometry_seconds = 0, mesh_seconds = 0;
};

/// Adds an OCC wire through the arch ring at elevation z; returns its tag.
int add_ring_wire(const ArchDamGeometry& g, double z, double margin, int np,
                  std::vector<int>& face_curves)
{
  namespace occ = gmsh::model::occ;
  const auto [a, b] = g.loft_theta_range(z, margin);
  std::vector<int> up, down;
  for (int i = 0; i < np; ++i)
  {
    const double t = a + (b - a) * i / (np - 1);
    const auto u = g.face_point(z, t, -1);
    const auto d = g.face_point(z, t, 1);
    up.push_back(occ::addPoint(u[0], u[1], z));
    down.push_back(occ::addPoint(d[0], d[1], z));
  }
  std::reverse(down.begin(), down.end());
  const int su = occ::addSpline(up);
  const int er = occ::addLine(up.back(), down.front());
  const int sd = occ::addSpline(down);
  const int el = occ::addLine(down.back(), up.front());
  face_curves.push_back(su);
  face_curves.push_back(sd);
  return occ::addWire({su, er, sd, el}, -1, true);
}

/// Valley prism: the canyon cross-section (extended above the top)
/// extruded along y over [y0, y1].
int add_valley(const ArchDamGeometry& g, double y0, double y1, double ztop)
{
  namespace occ = gmsh::model::occ;
  const auto& prof = g.canyon_profile();
  // (x, z): top-left, left wall down to the floor, right wall up, top-right
  std::vector<std::array<double, 2>> pts;
  pts.push_back({g.x_left(ztop), ztop});
  for (std::size_t i = prof.size(); i-- > 0;)
    if (prof[i][0] < ztop)
      pts.push_back({prof[i][1], prof[i][0]});
  for (std::size_t i = 0; i < prof.size(); ++i)
    if (prof[i][0] < ztop)
      pts.push_back({prof[i][2], prof[i][0]});
  pts.push_back({g.x_right(ztop), ztop});
  std::vector<int> p, l;
  for (const auto& q : pts)
    p.push_back(occ::addPoint(q[0], y0, q[1]));
  for (std::size_t i = 0; i < p.size(); ++i)
    l.push_back(occ::addLine(p[i], p[(i + 1) % p.size()]));
  const int s = occ::addPlaneSurface({occ::addCurveLoop(l)});
  gmsh::vectorpair out;
  occ::extrude({{2, s}}, 0, y1 - y0, 0, out);
  for (const auto& [d, t] : out)
    if (d == 3)
      return t;
  throw std::runtime_error("arch dam: valley extrusion failed");
}

/// Rectangle in the joint plane covering the dam's cut.
int add_joint_surface(const ArchDamGeometry& g, const JointPlane& j, double zlo,
                      double zhi)
{
  namespace occ = gmsh::model::occ;
  const std::array<double, 3> t = j.normal;         // plane normal (tangent)
  const std::array<double, 3> n = {-t[1], t[0], 0}; // in-plane horizontal
  double dmin = 1e300, dmax = -1e300, tmax = 0;
  for (int i = 0; i <= 40; ++i)
  {
    const double z = zlo + (zhi - zlo) * i / 40.0;
    // Centre-line point of ring z on the plane
    const double th = [&]
    {
      // (c(s) - P).t increases with s for |s - theta_k| < pi/2
      const double tk = std::atan2(t[1], t[0]);
      double a = std::max(-1.55, tk - 1.4), b = std::min(1.55, tk + 1.4);
      auto f = [&](double s)
      {
        const auto c = g.centre(z, s);
        return (c[0] - j.point[0]) * t[0] + (c[1] - j.point[1]) * t[1];
      };
      for (int it = 0; it < 200; ++it)
      {
        const double m = 0.5 * (a + b);
        ((f(m) > 0) == (f(b) > 0) ? b : a) = m;
      }
      return 0.5 * (a + b);
    }();
    const auto c = g.centre(z, th);
    const double d = (c[0] - j.point[0]) * n[0] + (c[1] - j.point[1]) * n[1];
    dmin = std::min(dmin, d);
    dmax = std::max(dmax, d);
    tmax = std::max(tmax, g.thickness(z, th));
  }
  const double pad = tmax + 0.02 * g.height() + 1;
  dmin -= pad;
  dmax += pad;
  std::vector<int> p;
  for (auto [d, z] :
       {std::pair{dmin, zlo}, {dmax, zlo}, {dmax, zhi}, {dmin, zhi}})
    p.push_back(occ::addPoint(j.point[0] + d * n[0], j.point[1] + d * n[1], z));
  std::vector<int> l;
  for (int i = 0; i < 4; ++i)
    l.push_back(occ::addLine(p[i], p[(i + 1) % 4]));
  return occ::addPlaneSurface({occ::addCurveLoop(l)});
}

/// Builds, tags and meshes the model (rank 0); reads the mesh arrays.
MeshArrays build_on_root(const ArchDamGeometry& g, bool verbose)
{
  namespace occ = gmsh::model::occ;
  const ArchDamDefinition& def = g.definition();
  const double H = g.height();
  const auto t0 = Clock::now();
  GmshSession session(verbose);
  // Stage lines (rank 0 runs this): meshing a 3D dam takes a minute or
  // more, which the user must see progressing.
  auto stage = [&](const char* name)
  {
    std::printf("mesh: %s at %.1f s\n", name, seconds_since(t0));
    std::fflush(stdout);
  };
  stage("gmsh started");
  gmsh::model::add("arch_dam");

  const ModelBox e = model_box(g);

  // Over-long dam: loft of the rings from below the floor to the crest
  const ArchMeshOptions& mo = def.mesh;
  const int nsec = mo.sections > 0 ? mo.sections : 12;
  const double zb = -0.05 * H;
  const double margin = 0.05 * H + 2;
  std::vector<int> wires, face_curves;
  for (int i = 0; i < nsec; ++i)
    wires.push_back(add_ring_wire(g, zb + (H - zb) * i / (nsec - 1), margin,
                                  mo.arch_points, face_curves));
  // The face splines of the sections stay in the model as free curves
  // (they are meshed in 1D, but their nodes are not in any tetrahedron and
  // are dropped): the distance field of the mesh size uses them (sampling
  // curves is cheap; sampling the lofted faces needs an OCC triangulation)
  gmsh::vectorpair loft;
  occ::addThruSections(wires, loft, -1, true, false, 3);
  stage("dam lofted");
  gmsh::vectorpair loft_vol;
  for (const auto& dt : loft)
    if (dt.first == 3)
      loft_vol.push_back(dt);
  if (loft_vol.size() != 1)
    throw std::runtime_error("arch dam: the loft did not give one solid");

  // Valley, foundation (box minus valley), dam (loft inside the valley)
  const int valley = add_valley(g, e.y0 - 1, e.y1 + 1, H + 0.5 * H);
  const int box =
      occ::addBox(e.x0, e.y0, e.z0, e.x1 - e.x0, e.y1 - e.y0, e.z1 - e.z0);
  gmsh::vectorpair rock, dam;
  std::vector<gmsh::vectorpair> map;
  occ::cut({{3, box}}, {{3, valley}}, rock, map, -1, true, false);
  occ::intersect(loft_vol, {{3, valley}}, dam, map, -1, true, true);
  if (rock.size() != 1 or dam.size() != 1)
    throw std::runtime_error("arch dam: the boolean operations gave " +
                             std::to_string(rock.size()) + " rock and " +
                             std::to_string(dam.size()) +
                             " dam volumes (expected 1 and 1)");
  const double band_w = mo.band_layers * mo.band_size;
  if (mo.band_layers > 0)
    rock = split_band(g, e, rock, band_w);

  stage("valley, foundation and dam booleans done");
  // Cuts the dam blocks with tool surfaces; drops the tool parts outside.
  auto cut_dam = [&](const gmsh::vectorpair& tools)
  { dam = cut_by_surfaces(dam, tools); };
  // Joints: cut the dam with the joint planes
  const std::vector<JointPlane> planes = g.joint_planes();
  if (!planes.empty())
  {
    gmsh::vectorpair tools;
    for (const JointPlane& j : planes)
      tools.push_back({2, add_joint_surface(g, j, -0.1 * H, 1.1 * H)});
    cut_dam(tools);
    if (dam.size() != planes.size() + 1)
      throw std::runtime_error(
          "arch dam: " + std::to_string(planes.size()) +
          " joint planes cut the dam into " + std::to_string(dam.size()) +
          " blocks (expected " + std::to_string(planes.size() + 1) +
          "); joints too close to each other or to the abutments?");
  }
  // Water line: cut the dam blocks at the reservoir level, so that the
  // mesh follows it and the wetted part of the upstream face has its tag.
  const double wl = mo.water_level;
  const bool water_line = wl > 1e-3 * H and wl < (1 - 1e-3) * H;
  if (water_line)
  {
    cut_dam({{2, occ::addRectangle(e.x0 - 1, e.y0 - 1, wl, e.x1 - e.x0 + 2,
                                   e.y1 - e.y0 + 2)}});
  }
  stage("joint planes cut");
  gmsh::vectorpair out;
  occ::fragment(rock, dam, out, map);
  occ::synchronize();
  stage("dam-foundation fragment (OCC) done");
  // The rock: the core first, then the band's pieces (split_band).
  std::vector<int> rock_vols, band_vols, dam_vols;
  const std::size_t n_rock = rock.size();
  for (std::size_t i = 0; i < n_rock; ++i)
    for (const auto& dt : map[i])
      (i == 0 ? rock_vols : band_vols).push_back(dt.second);
  for (std::size_t i = n_rock; i < map.size(); ++i)
    for (const auto& dt : map[i])
      dam_vols.push_back(dt.second);
  const std::set<int> dam_set(dam_vols.begin(), dam_vols.end());

  // Classify the surfaces
  const double tol = 1e-6 * H;
  std::map<int, std::vector<int>> groups;
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  for (const auto& [d, s] : surfaces)
  {
    std::vector<int> up, down;
    gmsh::model::getAdjacencies(2, s, up, down);
    int ndam = 0;
    for (int v : up)
      ndam += dam_set.count(v);
    double bx0, by0, bz0, bx1, by1, bz1;
    gmsh::model::getBoundingBox(2, s, bx0, by0, bz0, bx1, by1, bz1);
    double cx, cy, cz;
    occ::getCenterOfMass(2, s, cx, cy, cz);
    int tag = -1;
    if (water_line and up.size() == 2 and ndam == 2 and bz1 - bz0 < 1e-4 * H and
        std::abs(cz - wl) < 1e-4 * H)
      continue; // the water-line cut inside the dam: interior, untagged
    if (up.size() == 2 and ndam == 2)
    {
      // Joint: the plane through the centre of mass
      double best = 1e300;
      for (const JointPlane& j : planes)
      {
        const double dist = std::abs((cx - j.point[0]) * j.normal[0] +
                                     (cy - j.point[1]) * j.normal[1]);
        if (dist < best)
        {
          best = dist;
          tag = tags::joint_side1(j.label_index);
        }
      }
      if (best > 1e-3 * H)
        throw std::runtime_error("arch dam: an internal dam surface is on "
                                 "no joint plane");
    }
    else if (up.size() == 2 && ndam == 1)
      tag = tags::dam_base;
    else if (up.size() == 2)
      continue; // between the band's pieces and the core: interior
    else if (ndam == 1)
    {
      if (bz0 > H - tol)
        tag = tags::crest;
      else
      {
        std::vector<double> p, par;
        gmsh::model::getClosestPoint(2, s, {cx, cy, cz}, p, par);
        const double z = std::clamp(p[2], 0.0, H);
        tag = g.offset(z, p[0], p[1])[0] < 0 ? tags::upstream_face
                                             : tags::downstream_face;
        if (tag == tags::upstream_face and water_line and cz < wl)
          tag = tags::upstream_wetted;
      }
    }
    else
    {
      if (bz1 < e.z0 + tol)
        tag = tags::foundation_bottom;
      else if (bx1 < e.x0 + tol or bx0 > e.x1 - tol)
        tag = tags::foundation_sides;
      else if (by1 < e.y0 + tol)
        tag = tags::foundation_upstream;
      else if (by0 > e.y1 - tol)
        tag = tags::foundation_downstream;
      else if (bz0 > H - tol)
        tag = tags::foundation_top;
      else
      {
        const double z = std::clamp(cz, 0.0, H);
        tag = g.offset(z, cx, cy)[0] < 0 ? tags::reservoir_floor
                                         : tags::foundation_top_downstream;
      }
    }
    groups[tag].push_back(s);
  }
  gmsh::model::addPhysicalGroup(3, dam_vols, tags::dam);
  gmsh::model::setPhysicalName(3, tags::dam, tags::region_name(tags::dam));
  gmsh::model::addPhysicalGroup(3, rock_vols, tags::foundation);
  gmsh::model::setPhysicalName(3, tags::foundation,
                               tags::region_name(tags::foundation));
  if (!band_vols.empty())
  {
    gmsh::model::addPhysicalGroup(3, band_vols, tags::foundation_band);
    gmsh::model::setPhysicalName(3, tags::foundation_band,
                                 tags::region_name(tags::foundation_band));
    structure_band(g, e, band_w, mo.band_size, band_vols);
  }
  for (const auto& [tag, s] : groups)
  {
    gmsh::model::addPhysicalGroup(2, s, tag);
    gmsh::model::setPhysicalName(2, tag, tags::boundary_name(tag));
  }

  // Mesh size: h at the dam, grading to size_far over grading_distance
  const double h = mo.size;
  const double hfar = mo.size_far > 0 ? mo.size_far : 4 * h;
  namespace field = gmsh::model::mesh::field;
  const int fd = field::add("Distance");
  std::vector<double> curves;
  {
    gmsh::vectorpair existing;
    gmsh::model::getEntities(existing, 1);
    std::set<int> have;
    for (const auto& dt : existing)
      have.insert(dt.second);
    for (int c : face_curves)
      if (have.count(c))
        curves.push_back(c);
    if (curves.empty())
      throw std::runtime_error("arch dam: the section curves were lost");
  }
  field::setNumbers(fd, "EdgesList", curves);
  field::setNumber(fd, "NumPointsPerCurve", 200);
  const int ft = field::add("Threshold");
  field::setNumber(ft, "IField", fd);
  field::setNumber(ft, "LcMin", h);
  field::setNumber(ft, "LcMax", std::max(h, hfar));
  field::setNumber(ft, "DistMin", 0.0);
  field::setNumber(ft, "DistMax", mo.grading_distance * H);
  field::setAsBackgroundMesh(ft);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", std::max(h, hfar));
  if (mo.dam_layers > 0)
  {
    // Dam entities (volumes, their faces, curves, points): thickness rule
    std::set<std::pair<int, int>> dam_entities;
    for (int v : dam_vols)
    {
      dam_entities.insert({3, v});
      gmsh::vectorpair b;
      gmsh::model::getBoundary({{3, v}}, b, false, false, true);
      for (const auto& dt : b)
        dam_entities.insert({dt.first, std::abs(dt.second)});
    }
    const int layers = mo.dam_layers;
    gmsh::model::mesh::setSizeCallback(
        [&g, dam_entities, layers, h, hfar](int dim, int tag, double, double,
                                            double z)
        {
          if (!dam_entities.count({dim, tag}))
            return std::max(h, hfar);
          const double zc = std::clamp(z, 0.0, g.height());
          return std::min(h, g.ring(zc).t_c / layers);
        });
  }
  gmsh::option::setNumber("Mesh.Algorithm", 6);
  gmsh::option::setNumber("Mesh.Algorithm3D", 1);
  gmsh::option::setNumber("Mesh.Optimize", mo.optimize ? 1 : 0);
  gmsh::option::setNumber("Mesh.OptimizeNetgen", 0);

  MeshArrays m;
  m.geometry_seconds = seconds_since(t0);
  const auto t1 = Clock::now();
  gmsh::model::mesh::generate(3);
  m.mesh_seconds = seconds_since(t1);
  if (!band_vols.empty())
  {
    const auto bad = band_mismatches(band_vols);
    if (!bad.empty())
      throw std::runtime_error(
          "arch dam: the transmitting boundary's band is not conforming: " +
          std::to_string(bad.size()) +
          " faces of its pieces are not faces of their tetrahedra");
  }

  // Read nodes, tetrahedra and triangles of the physical groups
  std::vector<std::size_t> node_tags;
  std::vector<double> xyz, par;
  gmsh::model::mesh::getNodes(node_tags, xyz, par, -1, -1, false, false);
  std::unordered_map<std::size_t, std::int64_t> index;
  index.reserve(node_tags.size());
  for (std::size_t i = 0; i < node_tags.size(); ++i)
    index.emplace(node_tags[i], std::int64_t(i));
  m.x = xyz;
  stage("tetrahedra generated");
  auto collect = [&](int dim, std::vector<std::int64_t>& nodes,
                     std::vector<std::int32_t>& values)
  {
    const int nn = dim + 1;
    const auto perm = dolfinx::io::cells::perm_gmsh(
        dim == 3 ? dolfinx::mesh::CellType::tetrahedron
                 : dolfinx::mesh::CellType::triangle,
        nn);
    const int type = dim == 3 ? 4 : 2; // gmsh: 4-node tet, 3-node triangle
    gmsh::vectorpair groups_dim;
    gmsh::model::getPhysicalGroups(groups_dim, dim);
    for (const auto& [gd, gt] : groups_dim)
    {
      std::vector<int> ents;
      gmsh::model::getEntitiesForPhysicalGroup(gd, gt, ents);
      for (int ent : ents)
      {
        std::vector<std::size_t> et, nt;
        gmsh::model::mesh::getElementsByType(type, et, nt, ent);
        for (std::size_t k = 0; k < et.size(); ++k)
        {
          for (int a = 0; a < nn; ++a)
            nodes.push_back(index.at(nt[nn * k + perm[a]]));
          values.push_back(gt);
        }
      }
    }
  };
  collect(3, m.cells, m.cell_values);
  collect(2, m.facets, m.facet_values);

  // Keep only the nodes of the tetrahedra (the construction leaves free
  // points and curves whose nodes DOLFINx must not see)
  {
    std::vector<std::int64_t> renum(m.x.size() / 3, -1);
    std::vector<double> x;
    for (std::int64_t& v : m.cells)
    {
      if (renum[v] < 0)
      {
        renum[v] = std::int64_t(x.size() / 3);
        x.insert(x.end(), m.x.begin() + 3 * v, m.x.begin() + 3 * v + 3);
      }
      v = renum[v];
    }
    for (std::int64_t& v : m.facets)
    {
      if (renum[v] < 0)
        throw std::runtime_error("arch dam: a tagged facet has a node that "
                                 "belongs to no tetrahedron");
      v = renum[v];
    }
    m.x = std::move(x);
  }

  if (!def.mesh.split_joints)
  {
    // Jointless model of the same mesh.
    untag_joint_facets(m.facets, m.facet_values);
    return m;
  }

  // Split the joints
  std::vector<JointSplitSpec> specs;
  for (const JointPlane& j : planes)
  {
    JointSplitSpec s;
    s.label_index = j.label_index;
    s.label = j.label;
    s.point = j.point;
    s.normal = j.normal;
    s.tag_side1 = tags::joint_side1(j.label_index);
    s.tag_side2 = tags::joint_side2(j.label_index);
    specs.push_back(s);
  }
  m.joints = split_joints(m.x, m.cells, m.cell_values, m.facets, m.facet_values,
                          specs, tags::dam, tags::dam_base);
  return m;
}

} // namespace

//-----------------------------------------------------------------------------
ArchModel build_arch_dam(MPI_Comm comm, const ArchDamDefinition& def,
                         bool verbose)
{
  const auto t0 = Clock::now();
  const ArchDamGeometry g(def); // validates (same on every rank)
  int rank = 0;
  MPI_Comm_rank(comm, &rank);

  MeshArrays d;
  on_root(comm, [&] { d = build_on_root(g, verbose); },
          {"build_arch_dam: ", "build_arch_dam: unknown error in gmsh", true});

  const std::size_t num_nodes = d.x.size() / 3;
  ArchModel out;
  out.model = model_from_arrays(comm, d.x, d.cells, d.cell_values, d.facets,
                                d.facet_values);
  if (rank == 0)
  {
    int size = 1;
    MPI_Comm_size(comm, &size);
    std::printf("mesh: %zu cells distributed over %d rank(s) at %.1f s\n",
                d.cell_values.size(), size, seconds_since(t0));
    std::fflush(stdout);
  }
  broadcast_joint_pairs(comm, d.joints);
  out.joints = std::move(d.joints);

  std::int64_t counts[3] = {0, 0, 0};
  double times[2] = {d.geometry_seconds, d.mesh_seconds};
  if (rank == 0)
  {
    counts[0] = std::int64_t(d.cell_values.size());
    counts[1] = std::count(d.cell_values.begin(), d.cell_values.end(),
                           std::int32_t(tags::dam));
    counts[2] = std::int64_t(num_nodes);
  }
  MPI_Bcast(counts, 3, MPI_INT64_T, 0, comm);
  MPI_Bcast(times, 2, MPI_DOUBLE, 0, comm);
  out.num_cells = counts[0];
  out.num_dam_cells = counts[1];
  out.num_nodes = counts[2];
  out.geometry_seconds = times[0];
  out.mesh_seconds = times[1];
  double total = seconds_since(t0);
  MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPI_DOUBLE, MPI_MAX, comm);
  out.total_seconds = total;
  return out;
}
//-----------------------------------------------------------------------------
void write_model(const Model& model, const std::filesystem::path& path)
{
  std::filesystem::path p = path;
  p.replace_extension(".xdmf");
  dolfinx::io::XDMFFile file(model.mesh->comm(), p, "w");
  file.write_mesh(*model.mesh);
  const std::string geo = "/Xdmf/Domain/Grid[@Name='mesh']/Geometry";
  if (model.cell_tags)
    file.write_meshtags(*model.cell_tags, geo);
  if (model.facet_tags)
    file.write_meshtags(*model.facet_tags, geo);
}
} // namespace damseis::geometry
