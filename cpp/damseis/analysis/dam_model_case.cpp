#include "dam_model_case.h"
#include "joint_contact_keys.h"
#include "transmitting_keys.h"
#include <algorithm>
#include <cmath>
#include <damseis/geometry/mesh_checks.h>
#include <damseis/geometry/tagged.h>
#include <damseis/geometry/tags.h>
#include <damseis/motion/record.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/mesh/Geometry.h>
#include <dolfinx/mesh/Topology.h>
#include <dolfinx/mesh/utils.h>
#include <numbers>
#include <set>
#include <sstream>

namespace damseis::analysis
{
namespace
{
/// The internal facet tag of a facet group: the reservoir's wetted faces
/// and floor take the tags the compiled forms integrate over; any other
/// group keeps its number, shifted clear of those.
constexpr int facet_tag_offset = 1000;

/// "a, b, c" (at most 12 names).
std::string name_list(const std::map<std::string, geometry::PhysicalGroup>& g,
                      int dim)
{
  std::string text;
  int n = 0;
  for (const auto& [name, group] : g)
  {
    if (group.dim != dim)
      continue;
    if (n++ == 12)
      return text + ", ...";
    text += (text.empty() ? "\"" : ", \"") + name + "\"";
  }
  return text.empty() ? "none" : text;
}

/// Refuses a name listed twice in `key`.
void check_unique(const input::Case& c, const std::string& key,
                  const std::vector<std::string>& names)
{
  std::set<std::string> seen;
  for (const auto& n : names)
    if (!seen.insert(n).second)
      c.fail(key, "lists \"" + n + "\" twice", "each name once");
}

/// Refuses a name that cannot be part of a file or column name.
void check_plain(const input::Case& c, const std::string& key,
                 const std::vector<std::string>& names, bool colon = false)
{
  for (const auto& n : names)
  {
    const bool plain =
        !n.empty() &&
        std::all_of(n.begin(), n.end(),
                    [&](char ch)
                    {
                      return std::isalnum(static_cast<unsigned char>(ch)) ||
                             ch == '_' || ch == '-' || (colon && ch == ':');
                    });
    if (!plain)
      c.fail(key, "has the name \"" + n + "\"",
             "names of letters, digits, '_' and '-' (they name output files "
             "and columns)");
  }
}

/// The tag of group `name` named by key `key`, which must have dimension
/// `dim` (cells: the mesh's dimension; facets: one less).
int group_tag(const input::Case& c, const geometry::MeshFile& mesh,
              const std::string& key, const std::string& name, int dim)
{
  const std::string what = dim == mesh.tdim ? "cells" : "facets";
  const auto it = mesh.groups.find(name);
  if (it == mesh.groups.end())
  {
    c.fail(key,
           "names \"" + name + "\", which is not a physical group of " +
               c.path("mesh.file").string(),
           "a group of " + what + " (dimension " + std::to_string(dim) +
               "); the file has " + name_list(mesh.groups, dim));
  }
  if (it->second.dim != dim)
  {
    c.fail(key,
           "names \"" + name + "\", a group of dimension " +
               std::to_string(it->second.dim),
           "a group of " + what + " (dimension " + std::to_string(dim) +
               "): " + name_list(mesh.groups, dim));
  }
  return it->second.tag;
}

/// Per group: the vector of `values_key` (dim components per group).
std::vector<GroupVector> group_vectors(const input::Case& c,
                                       const geometry::MeshFile& mesh,
                                       const std::string& groups_key,
                                       const std::string& values_key, int dim)
{
  const auto groups = c.strings(groups_key);
  const auto values = c.reals(values_key);
  const int d = mesh.tdim;
  if (values.size() != groups.size() * d)
  {
    c.fail(values_key,
           "has " + std::to_string(values.size()) + " values for " +
               std::to_string(groups.size()) + " groups of " + groups_key,
           std::to_string(d) + " components per group (" +
               std::to_string(groups.size() * d) + " values)");
  }
  std::vector<GroupVector> out;
  for (std::size_t i = 0; i < groups.size(); ++i)
  {
    group_tag(c, mesh, groups_key, groups[i], dim);
    GroupVector g{groups[i], {0, 0, 0}};
    for (int k = 0; k < d; ++k)
      g.value[k] = values[d * i + k];
    out.push_back(g);
  }
  return out;
}

/// The lowest elevation of the facets with these tags (HUGE_VAL if none).
double lowest_facet_point(const geometry::Model& model,
                          const std::set<int>& tags)
{
  const auto& mesh = *model.mesh;
  const int tdim = mesh.topology().dim();
  const auto facets = geometry::tagged_entities(
      *model.facet_tags, std::vector<int>(tags.begin(), tags.end()));
  const auto nodes =
      dolfinx::mesh::entities_to_geometry(mesh, tdim - 1, facets, false);
  double z = HUGE_VAL;
  for (std::int32_t n : nodes)
    z = std::min(z, mesh.geometry().x()[3 * n + tdim - 1]);
  MPI_Allreduce(MPI_IN_PLACE, &z, 1, MPI_DOUBLE, MPI_MIN, mesh.comm());
  return z;
}

/// Distance from x to the nearest mesh node, and the mean cell size
/// (volume^(1/dim) of the mean cell), the same on every rank.
std::pair<double, double> nearest_node(const geometry::Model& model,
                                       const std::array<double, 3>& p)
{
  const auto& mesh = *model.mesh;
  const auto& x = mesh.geometry().x();
  double d = HUGE_VAL;
  for (std::size_t i = 0; i < x.size() / 3; ++i)
    d = std::min(d, std::hypot(x[3 * i] - p[0], x[3 * i + 1] - p[1],
                               x[3 * i + 2] - p[2]));
  MPI_Allreduce(MPI_IN_PLACE, &d, 1, MPI_DOUBLE, MPI_MIN, mesh.comm());
  const int tdim = mesh.topology().dim();
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k)
  {
    lo[k] = HUGE_VAL;
    hi[k] = -HUGE_VAL;
  }
  for (std::size_t i = 0; i < x.size(); ++i)
  {
    lo[i % 3] = std::min(lo[i % 3], x[i]);
    hi[i % 3] = std::max(hi[i % 3], x[i]);
  }
  MPI_Allreduce(MPI_IN_PLACE, lo, 3, MPI_DOUBLE, MPI_MIN, mesh.comm());
  MPI_Allreduce(MPI_IN_PLACE, hi, 3, MPI_DOUBLE, MPI_MAX, mesh.comm());
  double box = 1.0;
  for (int k = 0; k < tdim; ++k)
    box *= std::max(hi[k] - lo[k], 1e-300);
  const double cells =
      static_cast<double>(mesh.topology().index_map(tdim)->size_global());
  return {d, std::pow(box / cells, 1.0 / tdim)};
}

/// Refuses a point farther than two mean cell sizes from every node.
void check_point(const input::Case& c, const geometry::Model& model,
                 const std::string& key, const std::array<double, 3>& p,
                 int dim)
{
  const auto [d, h] = nearest_node(model, p);
  if (d > 2.0 * h)
  {
    std::ostringstream problem;
    problem.precision(4);
    problem << "puts a point " << d << " m from the nearest node of the mesh";
    c.fail(key, problem.str(),
           "points in the model (within two cell sizes, " +
               std::to_string(2.0 * h) + " m, of a node; " +
               std::to_string(dim) + " coordinates)");
  }
}

/// The facet tags renumbered: `special` groups get their tag, the others
/// their number + facet_tag_offset.
void retag_facets(geometry::Model& model, const std::map<int, int>& special)
{
  const auto& t = *model.facet_tags;
  std::vector<std::int32_t> indices(t.indices().begin(), t.indices().end());
  std::vector<std::int32_t> values(t.values().size());
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    const auto it = special.find(t.values()[i]);
    values[i] =
        it != special.end() ? it->second : t.values()[i] + facet_tag_offset;
  }
  model.facet_tags = std::make_shared<dolfinx::mesh::MeshTags<std::int32_t>>(
      model.mesh, t.dim(), std::move(indices), std::move(values));
}

/// The load history per step: "step" (0 at t = 0, 1 after), "pulse" (half
/// sine of the duration), or a file of (t, value) rows.
std::vector<double> load_history(const input::Case& c, int steps, double dt)
{
  const std::string kind = c.string("loads.traction_history");
  std::vector<double> h(steps + 1, 0.0);
  if (kind == "step")
  {
    std::fill(h.begin() + 1, h.end(), 1.0);
    return h;
  }
  if (kind == "pulse")
  {
    const double T = c.real("loads.pulse_duration");
    for (int k = 0; k <= steps; ++k)
    {
      const double t = k * dt;
      h[k] = t < T ? std::sin(std::numbers::pi * t / T) : 0.0;
    }
    return h;
  }
  const std::filesystem::path file = c.path("loads.traction_history");
  try
  {
    const motion::Record r = motion::read_record(file, motion::Units::m_per_s2,
                                                 motion::Format::columns, 0.0);
    h = motion::resample(r, dt, steps * dt);
    h.resize(steps + 1, 0.0);
  }
  catch (const std::exception& e)
  {
    // The record reader's message names the file and the fix.
    throw input::InputError(c.file().string() +
                            ": loads.traction_history: " + e.what());
  }
  if (std::abs(h[0]) > 0.0)
  {
    c.fail("loads.traction_history",
           "starts at " + std::to_string(h[0]) + " at t = 0",
           "a history starting at 0 (the model starts at rest; a load "
           "present before t = 0 is a static load)");
  }
  return h;
}
} // namespace

const std::vector<Direction>& dam_model_directions()
{
  static const std::vector<Direction> d = {
      {"x", 0, "", 0.0}, {"y", 1, "", 0.0}, {"z", 2, "", 0.0}};
  return d;
}

input::Schema dam_model_schema()
{
  input::Schema s;
  s.string("mesh.file", "", "-",
           "mesh file: gmsh .msh with physical groups (cells: triangles in "
           "z = 0, or tetrahedra; boundary facets), or XDMF with cell and "
           "facet tags (groups \"<dim>:<tag>\")");
  s.string("mesh.xdmf_mesh", "mesh", "-", "XDMF: the mesh grid's name");
  s.string("mesh.xdmf_cell_tags", "cell_tags", "-",
           "XDMF: the cell tags grid's name");
  s.string("mesh.xdmf_facet_tags", "facet_tags", "-",
           "XDMF: the facet tags grid's name");
  s.integer("mesh.order", "2", "-", "displacement polynomial degree")
      .between(1, 2);
  s.string("mesh.plane", "plane_strain", "-", "2D idealisation",
           {"plane_strain", "plane_stress"});
  s.string_array("regions.groups", "[]", "-",
                 "the cell groups, each with its material below (every cell "
                 "group of the mesh)");
  s.real_array("regions.E", "[]", "Pa", "Young's modulus per region")
      .between(1e6, 2e11);
  s.real_array("regions.nu", "[]", "-", "Poisson's ratio per region")
      .between_exclusive(-1, 0.5);
  s.real_array("regions.rho", "[]", "kg/m3",
               "mass density per region (0: massless foundation)")
      .between(0, 20000);
  s.string_array("regions.dam", "[]", "-",
                 "the groups that form the dam: stress envelopes, crest and "
                 "base points ([]: the first region)");
  s.string_array("supports.fixed", "[]", "-",
                 "facet groups with every displacement fixed; the ground "
                 "motion enters there (relative formulation)");
  s.string_array("supports.viscous_spring", "[]", "-",
                 "instead of supports.fixed: the far boundary of rock with "
                 "mass (every region but the dam, one homogeneous rock), "
                 "springs and dashpots on it, the ground motion as the "
                 "outcrop motion of vertically incident waves");
  s.string_array(
      "supports.transmitting", "[]", "-",
      "instead of supports.fixed: the far boundary of rock with mass (as "
      "supports.viscous_spring), Liao's multi-transmitting formula on its "
      "nodes (foundation.mtf_*), its band foundation.band");
  s.string_array(
      "foundation.band", "[]", "-",
      "supports.transmitting: the cell groups of the band along the "
      "boundary, reaching 2N node spacings inward (the formula's stencil; "
      "structured or not: the points between nodes are interpolated); the "
      "explicit group of foundation.band_integration = \"explicit\"");
  s.real("foundation.mtf_spacing", "-1", "m",
         "supports.transmitting: the formula's node spacing dx along the "
         "normals (bounds c_p dt / dx <= 1); -1: the mean edge length of "
         "the boundary's facets / mesh.order")
      .between(-1, 1000);
  add_formula_keys(s);
  s.real("foundation.spring_normal", "-1", "-",
         "viscous-spring boundary: normal spring alpha_n G / R (> 0; -1: "
         "1 in 2D, 4/3 in 3D)")
      .between(-1, 10);
  s.real("foundation.spring_tangential", "-1", "-",
         "viscous-spring boundary: tangential spring alpha_t G / R (> 0; "
         "-1: 1/2 in 2D, 2/3 in 3D)")
      .between(-1, 10);
  s.real_array("foundation.centre", "[]", "m",
               "viscous-spring boundary: the point R is measured from ([]: "
               "the dam's lowest point)");
  s.string_array("reservoir.wetted", "[]", "-",
                 "facet groups the reservoir wets (hydrostatic pressure, "
                 "Westergaard added mass)");
  s.string_array("reservoir.floor", "[]", "-",
                 "facet groups of the reservoir floor (with "
                 "reservoir.load_floor)");
  s.string_array("joints.side1", "[]", "-",
                 "joints: facet groups of one face, with duplicated nodes");
  s.string_array("joints.side2", "[]", "-",
                 "joints: the facet groups of the other faces, in the order "
                 "of side1");
  s.string("joints.model", "bonded", "-",
           "contraction joints: bonded (tied pairs) or "
           "contact (Coulomb friction, no tension; 3D)",
           {"bonded", "contact"});
  s.real_array("joints.friction", "[]", "-",
               "contact: friction coefficient per joint ([]: 1.0 each, the "
               "paper's)")
      .between(0, 100);
  s.string_array("joints.keyed", "[]", "-",
                 "contact: the joints (side1 groups) with shear keys: no "
                 "sliding, opening free");
  add_joint_contact_keys(s, "joints_active");
  s.string_array("loads.traction_groups", "[]", "-",
                 "facet groups loaded by a traction");
  s.real_array("loads.traction", "[]", "Pa",
               "traction per group (2 or 3 components each), times "
               "loads.traction_history");
  s.string("loads.traction_history", "step", "-",
           "\"step\" (1 from the first step on), \"pulse\" (half sine of "
           "loads.pulse_duration), \"static\" (a static load: applied in the "
           "static stage with the dead weight, kept through the time "
           "history) or a file of (time, factor) rows starting at 0");
  s.real("loads.pulse_duration", "0.1", "s", "duration of the pulse").above(0);
  s.string_array("loads.body_force_groups", "[]", "-",
                 "cell groups with a static body force besides dead weight");
  s.real_array("loads.body_force", "[]", "N/m3", "body force per group");
  s.string_array("initial.velocity_groups", "[]", "-",
                 "cell groups with an initial velocity");
  s.real_array("initial.velocity", "[]", "m/s", "initial velocity per group");
  s.string_array("output.faces", "[]", "-",
                 "facet groups whose stress envelopes are tabulated "
                 "(face_<group>.csv)");
  s.string_array("output.history_names", "[]", "-",
                 "names of points whose displacement, velocity and "
                 "acceleration are recorded (histories.csv)");
  s.real_array("output.history_points", "[]", "m",
               "their coordinates (2 or 3 per point)");
  s.string_array("output.history_groups", "[]", "-",
                 "groups of cells or facets whose mean displacement, "
                 "velocity and acceleration are recorded "
                 "(group_histories.csv)");
  add_seismic_keys(s, dam_model_directions(), "[]", "[]");
  add_concrete_keys(s);
  s.set_default("reservoir.level", "0");
  return s;
}

namespace
{
/// Every region's material; every cell group of the mesh must be a region.
std::vector<Region> read_regions(const input::Case& c,
                                 const geometry::MeshFile& mesh)
{
  const auto groups = c.strings("regions.groups");
  const auto E = c.reals("regions.E"), nu = c.reals("regions.nu"),
             rho = c.reals("regions.rho");
  check_unique(c, "regions.groups", groups);
  if (groups.empty())
    c.fail("regions.groups", "is empty",
           "the cell groups of the mesh: " + name_list(mesh.groups, mesh.tdim));
  for (const auto& [key, values] :
       {std::pair{"regions.E", &E}, std::pair{"regions.nu", &nu},
        std::pair{"regions.rho", &rho}})
  {
    if (values->size() != groups.size())
      c.fail(key,
             "has " + std::to_string(values->size()) + " values for " +
                 std::to_string(groups.size()) + " regions",
             "one value per group of regions.groups");
  }
  std::vector<Region> regions;
  for (std::size_t i = 0; i < groups.size(); ++i)
  {
    group_tag(c, mesh, "regions.groups", groups[i], mesh.tdim);
    regions.push_back({groups[i], {E[i], nu[i], rho[i]}, false});
  }
  for (const auto& [name, g] : mesh.groups)
  {
    if (g.dim == mesh.tdim &&
        std::none_of(groups.begin(), groups.end(),
                     [&](const std::string& r) { return r == name; }))
      c.fail("regions.groups", "does not list the cell group \"" + name + "\"",
             "every cell group of the mesh with its material");
  }
  auto dam = c.strings("regions.dam");
  if (dam.empty())
    dam = {groups.front()};
  for (const std::string& d : dam)
  {
    auto it = std::find_if(regions.begin(), regions.end(),
                           [&](const Region& r) { return r.group == d; });
    if (it == regions.end())
      c.fail("regions.dam", "names \"" + d + "\", which is not a region",
             "groups of regions.groups");
    if (it->material.rho <= 0.0)
      c.fail("regions.dam", "names the massless region \"" + d + "\"",
             "regions with mass (the dam)");
    it->dam = true;
  }
  return regions;
}

/// The facet groups of a key, each checked.
std::vector<std::string> facet_groups(const input::Case& c,
                                      const geometry::MeshFile& mesh,
                                      const std::string& key)
{
  const auto groups = c.strings(key);
  for (const auto& g : groups)
    group_tag(c, mesh, key, g, mesh.tdim - 1);
  return groups;
}

/// Checks each joint's sides and returns the pairs of groups.
std::vector<std::pair<std::string, std::string>>
read_joints(const input::Case& c, const geometry::MeshFile& mesh,
            double& tolerance)
{
  const auto side1 = facet_groups(c, mesh, "joints.side1");
  const auto side2 = facet_groups(c, mesh, "joints.side2");
  if (side1.size() != side2.size())
    c.fail("joints.side2",
           "has " + std::to_string(side2.size()) + " groups for " +
               std::to_string(side1.size()) + " in joints.side1",
           "one side-2 group per side-1 group");
  std::vector<std::pair<std::string, std::string>> joints;
  std::vector<geometry::JointMatch> matches;
  for (std::size_t j = 0; j < side1.size(); ++j)
  {
    auto match = geometry::match_joint_sides(
        mesh.model, mesh.groups.at(side1[j]).tag, mesh.groups.at(side2[j]).tag,
        side1[j], side2[j]);
    if (!match.problem.empty())
      c.fail("joints.side2", match.problem,
             "the two faces of one joint surface, meshed alike, with "
             "duplicated nodes");
    for (std::size_t k = 0; k < matches.size(); ++k)
    {
      if (const auto n = geometry::shared_joint_points(matches[k], match))
        c.fail("joints.side1",
               "joints \"" + side1[k] + "\" and \"" + side1[j] + "\" meet at " +
                   std::to_string(n) +
                   " nodes (where joints cross or end on each other, the "
                   "copies of a node cannot be tied in pairs)",
               "joints that do not touch (leave the nodes where joints meet "
               "unsplit)");
    }
    tolerance = std::max(tolerance, match.tolerance);
    matches.push_back(std::move(match));
    joints.emplace_back(side1[j], side2[j]);
  }
  return joints;
}

/// Named points: names and flattened coordinates.
std::vector<std::pair<std::string, std::array<double, 3>>>
read_history_points(const input::Case& c, int dim)
{
  const auto names = c.strings("output.history_names");
  const auto x = c.reals("output.history_points");
  if (x.size() != names.size() * dim)
    c.fail("output.history_points",
           "has " + std::to_string(x.size()) + " values for " +
               std::to_string(names.size()) + " names",
           std::to_string(dim) + " coordinates per name of "
                                 "output.history_names");
  check_plain(c, "output.history_names", names);
  check_unique(c, "output.history_names", names);
  std::vector<std::pair<std::string, std::array<double, 3>>> points;
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    std::array<double, 3> p = {0, 0, 0};
    for (int k = 0; k < dim; ++k)
      p[k] = x[dim * i + k];
    points.emplace_back(names[i], p);
  }
  return points;
}
} // namespace

/// material.model and the concrete of the dam regions: with HTC concrete
/// the dam regions share E and nu (those of the concrete).
void read_dam_concrete(const input::Case& c, DamModelConfig& cfg)
{
  const Region* first = nullptr;
  for (const Region& r : cfg.regions)
  {
    if (!r.dam)
      continue;
    if (first && (r.material.E != first->material.E ||
                  r.material.nu != first->material.nu))
    {
      if (c.string("material.model") != "linear")
        c.fail("regions.E",
               "differs between the dam regions \"" + first->group +
                   "\" and \"" + r.group + "\"",
               "one concrete (E, nu) in the dam regions with material.model "
               "= \"" +
                   c.string("material.model") + "\"");
    }
    if (!first)
      first = &r;
  }
  cfg.concrete =
      read_concrete_settings(c, first->material.E, first->material.nu);
}

namespace
{
/// The mesh file, read and distributed (collective).
void read_mesh(const input::Case& c, DamModelConfig& cfg)
{
  cfg.mesh_file = c.path("mesh.file");
  if (cfg.mesh_file.empty())
    c.fail("mesh.file", "is empty", "a gmsh .msh file with physical groups");
  try
  {
    cfg.mesh = std::make_shared<geometry::MeshFile>(geometry::read_mesh_file(
        MPI_COMM_WORLD, cfg.mesh_file,
        {c.string("mesh.xdmf_mesh"), c.string("mesh.xdmf_cell_tags"),
         c.string("mesh.xdmf_facet_tags")}));
  }
  catch (const std::runtime_error& e)
  {
    c.fail("mesh.file", e.what(),
           "a gmsh .msh file (format 2 or 4) of linear triangles or "
           "tetrahedra in physical groups, or an XDMF mesh with cell and "
           "facet tags (mesh.xdmf_*)");
  }
  cfg.dim = cfg.mesh->tdim;
  cfg.order = static_cast<int>(c.integer("mesh.order"));
  cfg.plane = c.string("mesh.plane") == "plane_stress"
                  ? fem::PlaneMode::plane_stress
                  : fem::PlaneMode::plane_strain;
  const std::int64_t flat = geometry::degenerate_cells(cfg.mesh->model);
  if (flat > 0)
    c.fail("mesh.file",
           "has " + std::to_string(flat) +
               " degenerate cells (zero area or volume)",
           "a mesh without flat or collapsed cells (check it in gmsh: "
           "Tools > Statistics, quality)");
}

/// joints.model = "contact": the joints' laws and the static stage.
void read_joint_contact(const input::Case& c, DamModelConfig& cfg)
{
  JointContactConfig& jc = cfg.contact;
  jc.enabled = c.string("joints.model") == "contact";
  const auto friction = c.reals("joints.friction");
  const auto keyed = c.strings("joints.keyed");
  refuse_contact_keys_when_bonded(c, {"joints.friction", "joints.keyed"});
  if (!jc.enabled)
    return;
  if (cfg.dim != 3)
    c.fail("joints.model", "is \"contact\" for a 2D mesh",
           "a 3D (tetrahedral) mesh for contact joints, or joints.model = "
           "\"bonded\"");
  if (cfg.joints.empty())
    c.fail("joints.model", "is \"contact\" but joints.side1 is empty",
           "the joints' facet groups in joints.side1 and joints.side2");
  if (!friction.empty() && friction.size() != cfg.joints.size())
    c.fail("joints.friction",
           "has " + std::to_string(friction.size()) + " values for " +
               std::to_string(cfg.joints.size()) + " joints",
           "one coefficient per joint of joints.side1, or [] for 1.0");
  jc.friction =
      friction.empty() ? std::vector<double>(cfg.joints.size(), 1.0) : friction;
  jc.keyed.assign(cfg.joints.size(), false);
  check_unique(c, "joints.keyed", keyed);
  for (const auto& k : keyed)
  {
    auto it = std::find_if(cfg.joints.begin(), cfg.joints.end(),
                           [&](const auto& j) { return j.first == k; });
    if (it == cfg.joints.end())
      c.fail("joints.keyed", "names \"" + k + "\", which is not a joint",
             "side1 groups of joints.side1");
    jc.keyed[static_cast<std::size_t>(it - cfg.joints.begin())] = true;
  }
  jc.joint = read_joint_conditions(c, cfg.joints.size(), "joints.side1 order");
  jc.restitution = read_restitution(c);
  jc.statics = read_joint_statics(c);
  jc.history_points = read_joint_history_points(c);
  jc.ncp = read_ncp_settings(c);
}

/// Exactly one kind of support: fixed, viscous-spring or transmitting.
void read_supports(const input::Case& c, const DamModelConfig& cfg)
{
  const std::pair<const char*, const std::vector<std::string>*> kinds[] = {
      {"supports.fixed", &cfg.fixed},
      {"supports.viscous_spring", &cfg.viscous_spring},
      {"supports.transmitting", &cfg.transmitting}};
  std::vector<const char*> given;
  for (const auto& [key, groups] : kinds)
    if (!groups->empty())
      given.push_back(key);
  const std::string expected =
      "one of them: the facet groups where the model is fixed (the "
      "foundation's far boundary, or the dam base), or those of a "
      "viscous-spring or a multi-transmitting boundary: " +
      name_list(cfg.mesh->groups, cfg.mesh->tdim - 1);
  if (given.empty())
    c.fail("supports.fixed", "is empty", expected);
  if (given.size() > 1)
    c.fail(given[1], std::string("is given with ") + given[0], expected);
}

/// The roles of the groups: regions, supports, reservoir, joints, loads,
/// output faces and points; each facet group in one role, loads on the
/// boundary.
void read_roles(const input::Case& c, DamModelConfig& cfg)
{
  const geometry::MeshFile& mesh = *cfg.mesh;
  cfg.regions = read_regions(c, mesh);
  cfg.fixed = facet_groups(c, mesh, "supports.fixed");
  cfg.viscous_spring = facet_groups(c, mesh, "supports.viscous_spring");
  cfg.transmitting = facet_groups(c, mesh, "supports.transmitting");
  read_supports(c, cfg);
  cfg.wetted = facet_groups(c, mesh, "reservoir.wetted");
  cfg.floor = facet_groups(c, mesh, "reservoir.floor");
  cfg.joint_tolerance = 0.0;
  cfg.joints = read_joints(c, mesh, cfg.joint_tolerance);
  read_joint_contact(c, cfg);
  cfg.faces = facet_groups(c, mesh, "output.faces");
  check_plain(c, "output.faces", cfg.faces, true); // XDMF groups "d:v"
  check_unique(c, "output.faces", cfg.faces);
  cfg.tractions = group_vectors(c, mesh, "loads.traction_groups",
                                "loads.traction", mesh.tdim - 1);
  cfg.body_forces = group_vectors(c, mesh, "loads.body_force_groups",
                                  "loads.body_force", mesh.tdim);
  cfg.initial_velocity = group_vectors(c, mesh, "initial.velocity_groups",
                                       "initial.velocity", mesh.tdim);
  cfg.history_points = read_history_points(c, mesh.tdim);
  // Pressures and tractions act on the model's boundary only.
  for (const auto& [key, groups] :
       {std::pair{"reservoir.wetted", cfg.wetted},
        std::pair{"reservoir.floor", cfg.floor},
        std::pair{"supports.viscous_spring", cfg.viscous_spring},
        std::pair{"supports.transmitting", cfg.transmitting},
        std::pair{"loads.traction_groups", c.strings("loads.traction_groups")}})
  {
    for (const auto& g : groups)
    {
      if (const auto n =
              geometry::interior_facets(mesh.model, mesh.groups.at(g).tag))
        c.fail(key,
               "names \"" + g + "\", which has " + std::to_string(n) +
                   " facets inside the model (between two cells)",
               "groups of boundary facets (a load on an interface needs a "
               "joint there)");
    }
  }
  // A facet group has one role.
  std::map<std::string, std::string> role;
  for (const auto& [key, groups] :
       {std::pair{"supports.fixed", &cfg.fixed},
        std::pair{"supports.viscous_spring", &cfg.viscous_spring},
        std::pair{"supports.transmitting", &cfg.transmitting},
        std::pair{"reservoir.wetted", &cfg.wetted},
        std::pair{"reservoir.floor", &cfg.floor}})
  {
    for (const auto& g : *groups)
    {
      if (role.count(g))
        c.fail(key, "names \"" + g + "\", which " + role[g] + " names too",
               "each facet group in one of supports.fixed, "
               "supports.viscous_spring, supports.transmitting, "
               "reservoir.wetted, reservoir.floor");
      role[g] = key;
    }
  }
}

/// The model's facet tags: the wetted faces and the floor as the forms
/// expect them (the groups' own tags kept in cfg.group_facets).
void tag_for_the_forms(DamModelConfig& cfg)
{
  std::map<int, int> special;
  for (const auto& g : cfg.wetted)
    special[cfg.mesh->groups.at(g).tag] = geometry::tags::upstream_face;
  for (const auto& g : cfg.floor)
    special[cfg.mesh->groups.at(g).tag] = geometry::tags::reservoir_floor;
  cfg.group_facets = cfg.mesh->model.facet_tags;
  retag_facets(cfg.mesh->model, special);
}

/// The shared seismic keys with the dam's crest and base as default points,
/// the concrete, and the reservoir (its bottom: the lowest wetted point;
/// a level given must be above it).
void read_dam_seismic(const input::Case& c, DamModelConfig& cfg)
{
  const geometry::MeshFile& mesh = *cfg.mesh;
  std::set<int> dam_tags;
  for (const Region& r : cfg.regions)
  {
    if (r.dam)
      dam_tags.insert(mesh.groups.at(r.group).tag);
  }
  const auto [crest, base] = extreme_vertices(mesh.model, dam_tags);
  // No ground motion is needed: tractions, an initial velocity, or only the
  // static and modal stages (time.duration then sets the steps).
  cfg.seismic = read_seismic_settings(c, dam_model_directions(), cfg.dim,
                                      crest[cfg.dim - 1], crest, base, true);
  if (cfg.dim == 2 && !c.string("motion.z.record").empty())
    c.fail("motion.z.record", "is given for a 2D mesh",
           "motion.x (horizontal) and motion.y (vertical) in 2D");
  if (cfg.dim == 2 && cfg.seismic.motion[2].active)
    c.fail("motion.z.source", "gives a z motion for a 2D mesh",
           "motion.x (horizontal) and motion.y (vertical) in 2D");
  cfg.seismic.dam_regions.assign(dam_tags.begin(), dam_tags.end());
  cfg.seismic.singular_where = "none (a user mesh: raw extremes)";
  read_dam_concrete(c, cfg);
  auto& reservoir = cfg.seismic.reservoir;
  if (reservoir.level > 0.0 && cfg.wetted.empty())
    c.fail("reservoir.wetted", "is empty while reservoir.level > 0",
           "the facet groups the water wets");
  if (!cfg.wetted.empty())
  {
    reservoir.bottom =
        lowest_facet_point(mesh.model, {geometry::tags::upstream_face});
    if (reservoir.level > 0.0 && reservoir.level <= reservoir.bottom)
    {
      std::ostringstream problem;
      problem << "= " << reservoir.level
              << " m is not above the lowest wetted point (" << reservoir.bottom
              << " m)";
      c.fail("reservoir.level", problem.str(),
             "the elevation of the water surface in the mesh's coordinates "
             "(0: no reservoir)");
    }
  }
  cfg.traction_history_kind = c.string("loads.traction_history");
  if (!cfg.tractions.empty() && cfg.traction_history_kind != "static")
    cfg.traction_history =
        load_history(c, cfg.seismic.steps, cfg.seismic.scheme.dt);
}

/// What is recorded: face tables, the crest and base points, named points
/// and groups (points within the model).
void read_recording(const input::Case& c, DamModelConfig& cfg)
{
  const geometry::MeshFile& mesh = *cfg.mesh;
  for (const auto& g : cfg.faces)
    cfg.seismic.faces.push_back({g, {mesh.groups.at(g).tag}});
  cfg.seismic.face_tags = cfg.group_facets;
  check_point(c, mesh.model, "output.crest_point", cfg.seismic.crest_point,
              cfg.dim);
  check_point(c, mesh.model, "output.base_point", cfg.seismic.base_point,
              cfg.dim);
  for (const auto& [name, x] : cfg.history_points)
    check_point(c, mesh.model, "output.history_points", x, cfg.dim);
  cfg.seismic.history_points = cfg.history_points;
  const auto groups = c.strings("output.history_groups");
  check_plain(c, "output.history_groups", groups, true);
  check_unique(c, "output.history_groups", groups);
  for (const auto& g : groups)
  {
    const auto it = mesh.groups.find(g);
    if (it == mesh.groups.end() || it->second.dim < cfg.dim - 1)
      c.fail("output.history_groups",
             "names \"" + g + "\", which is not a group of cells or facets",
             "groups of cells (" + name_list(mesh.groups, cfg.dim) +
                 ") or facets (" + name_list(mesh.groups, cfg.dim - 1) + ")");
    cfg.seismic.history_groups.push_back(
        {g,
         it->second.dim == cfg.dim
             ? std::shared_ptr<const dolfinx::mesh::MeshTags<std::int32_t>>(
                   mesh.model.cell_tags)
             : cfg.group_facets,
         it->second.tag});
  }
}
} // namespace

std::array<std::array<double, 3>, 2>
extreme_vertices(const geometry::Model& model, const std::set<int>& regions)
{
  const auto& mesh = *model.mesh;
  const int tdim = mesh.topology().dim();
  const auto cells = geometry::tagged_entities(
      *model.cell_tags, std::vector<int>(regions.begin(), regions.end()));
  const auto nodes =
      dolfinx::mesh::entities_to_geometry(mesh, tdim, cells, false);
  const auto& x = mesh.geometry().x();
  struct
  {
    double v;
    int rank;
  } hi{-HUGE_VAL, 0}, lo{-HUGE_VAL, 0};
  MPI_Comm_rank(mesh.comm(), &hi.rank);
  lo.rank = hi.rank;
  std::array<std::array<double, 3>, 2> p{};
  for (std::int32_t n : nodes)
  {
    const double z = x[3 * n + tdim - 1];
    if (z > hi.v)
    {
      hi.v = z;
      p[0] = {x[3 * n], x[3 * n + 1], x[3 * n + 2]};
    }
    if (-z > lo.v)
    {
      lo.v = -z;
      p[1] = {x[3 * n], x[3 * n + 1], x[3 * n + 2]};
    }
  }
  for (auto [local, i] : {std::pair{hi, 0}, std::pair{lo, 1}})
  {
    decltype(hi) global;
    MPI_Allreduce(&local, &global, 1, MPI_DOUBLE_INT, MPI_MAXLOC, mesh.comm());
    MPI_Bcast(p[i].data(), 3, MPI_DOUBLE, global.rank, mesh.comm());
  }
  return p;
}

DamModelConfig read_dam_model_config(const input::Case& c)
{
  DamModelConfig cfg;
  read_mesh(c, cfg);
  read_roles(c, cfg);
  tag_for_the_forms(cfg);
  read_dam_seismic(c, cfg);
  read_recording(c, cfg);
  read_wave_foundation(c, cfg);
  return cfg;
}

/// The internal tag of a facet group of the config (after retagging).
int facet_tag(const DamModelConfig& cfg, const std::string& group)
{
  const int tag = cfg.mesh->groups.at(group).tag;
  for (const auto& w : cfg.wetted)
    if (w == group)
      return geometry::tags::upstream_face;
  for (const auto& f : cfg.floor)
    if (f == group)
      return geometry::tags::reservoir_floor;
  return tag + facet_tag_offset;
}
} // namespace damseis::analysis
