#include "arch_dam_case.h"
#include "joint_contact_keys.h"
#include "transmitting_keys.h"
#include <algorithm>
#include <damseis/geometry/arch_case.h>
#include <damseis/geometry/tags.h>
#include <sstream>

namespace damseis::analysis
{
const std::vector<Direction>& arch_dam_directions()
{
  static const std::vector<Direction> d = {
      {"cross_stream", 0, "", 0.0},
      {"stream", 1, DAMSEIS_SOURCE_DIR "/data/records/elcentro_1940_ns.at2",
       0.2},
      {"vertical", 2, "", 0.0}};
  return d;
}

input::Schema arch_dam_schema()
{
  input::Schema s;
  geometry::arch_dam_schema(s);
  s.integer("mesh.order", "2", "-",
            "displacement polynomial degree (2: no shell locking)")
      .between(1, 2);
  s.real("material.E", "28.6e9", "Pa", "Young's modulus of the dam concrete")
      .between(1e8, 2e11);
  s.real("material.nu", "0.2", "-", "Poisson's ratio of the dam concrete")
      .between_exclusive(-1, 0.5);
  s.real("material.rho", "2400", "kg/m3", "mass density of the dam concrete")
      .between(100, 20000);
  add_concrete_keys(s);
  s.real("rock.E", "28.6e9", "Pa", "Young's modulus of the foundation rock")
      .between(1e7, 2e11);
  s.real("rock.nu", "0.25", "-", "Poisson's ratio of the foundation rock")
      .between_exclusive(-1, 0.5);
  s.real("rock.rho", "2640", "kg/m3",
         "mass density of the rock (with foundation.boundary = "
         "viscous_spring; the fixed foundation is massless)")
      .between(100, 20000);
  s.string("foundation.boundary", "fixed", "-",
           "fixed: massless rock fixed at its far faces, the ground motion "
           "as base acceleration; viscous_spring: rock with mass "
           "(rock.rho) and a viscous-spring boundary on its far faces and "
           "bottom, the ground motion as the outcrop motion of vertically "
           "incident waves; mtf: the same with Liao's multi-transmitting "
           "boundary on a structured band of elements "
           "(foundation.band_*, foundation.mtf_*)",
           {"fixed", "viscous_spring", "mtf"});
  add_transmitting_keys(s, "bottom, sides, upstream and downstream faces",
                        "40.0");
  s.real("foundation.spring_normal", "1.3333333333333333", "-",
         "viscous-spring boundary: normal spring alpha_n G / R (R from the "
         "crown's base; 4/3: Liu et al. 2006)")
      .between(0, 10);
  s.real("foundation.spring_tangential", "0.6666666666666666", "-",
         "viscous-spring boundary: tangential spring alpha_t G / R (2/3)")
      .above(0)
      .at_most(10);
  s.string("joints.model", "bonded", "-",
           "contraction joints: bonded (tied pairs) or "
           "contact (Coulomb friction, no tension)",
           {"bonded", "contact"});
  s.real_array("joints.friction", "[]", "-",
               "contact: friction coefficient per joint, in label order ([]: "
               "1.0 each, the paper's)")
      .between(0, 100);
  s.string("joints.keyed", "", "-",
           "contact: labels of the joints with shear keys (no sliding, "
           "opening free), e.g. \"DG\"");
  add_joint_contact_keys(s, "cantilever");
  s.boolean("study.foundation", "false", "-",
            "the foundation models side by side: for each ratio of "
            "study.foundation_ratios, the massless rock and the rock with "
            "mass and a viscous-spring boundary (with foundation.boundary = "
            "\"mtf\" the multi-transmitting boundary too; the massless "
            "run's Rayleigh damping), into subfolders; "
            "foundation_study.csv/.md");
  s.real_array("study.foundation_ratios", "[0.5, 1.0, 1.5]", "-",
               "E_f / E_d of study.foundation (the paper's for the 102 m "
               "dam)")
      .between(0.01, 100);
  s.string_array("study.joints", "[]", "-",
                 "a study: one run per joint set, each into its subfolder, "
                 "and the comparison tables (joint_study.md): \"none\" or "
                 "the active labels, e.g. [\"none\", \"DGJ\", \"ADGJM\"]");
  s.boolean("study.table1", "false", "-",
            "the paper's section I study: the elastic, plastic and "
            "viscoplastic HTC concrete at each level of "
            "study.reservoir_levels, into subfolders level_<m>/<model>; "
            "table1.csv/.md (the paper's Table 1)");
  s.real_array("study.reservoir_levels", "[]", "m",
               "reservoir levels of study.table1 above the crown's base, "
               "e.g. [275, 180] ([]: reservoir.level only; unused without "
               "study.table1)")
      .at_least(0);
  add_seismic_keys(s, arch_dam_directions(), "[]", "[]");
  return s;
}

namespace
{
/// The labels of the joints of the geometry (the active candidates).
std::string joint_labels(const geometry::JointDefinition& j)
{
  if (!j.active.empty())
    return j.active;
  const std::size_t n = j.positions.empty() ? static_cast<std::size_t>(j.count)
                                            : j.positions.size();
  std::string labels;
  for (std::size_t i = 0; i < n; ++i)
    labels += static_cast<char>('A' + i);
  return labels;
}

/// joints.model = "contact": friction and keys per joint, restitution,
/// static stage.
void read_joint_contact(const input::Case& c, ArchDamConfig& a)
{
  refuse_contact_keys_when_bonded(c, {"joints.friction", "joints.keyed"});
  if (c.string("joints.model") != "contact")
    return;
  a.joints = JointModel::contact;
  const std::string labels = joint_labels(a.geometry.joints);
  if (labels.empty())
    c.fail("joints.model", "is \"contact\" but the dam has no joints",
           "joints.count (or joints.positions) > 0");
  if (!a.geometry.mesh.split_joints)
    c.fail("joints.model",
           "is \"contact\" with mesh.split_joints = false (no joint faces)",
           "mesh.split_joints = true for contact joints");
  const auto friction = c.reals("joints.friction");
  if (!friction.empty() && friction.size() != labels.size())
    c.fail("joints.friction",
           "has " + std::to_string(friction.size()) + " values for " +
               std::to_string(labels.size()) + " joints (" + labels + ")",
           "one coefficient per joint in label order, or [] for 1.0");
  const JointConditions joint =
      read_joint_conditions(c, labels.size(), "label order " + labels);
  for (std::size_t i = 0; i < labels.size(); ++i)
  {
    a.friction[labels[i]] = friction.empty() ? 1.0 : friction[i];
    a.bonds[labels[i]] = {joint.tensile_strength[i], joint.cohesion[i]};
    a.initial_gap[labels[i]] = joint.initial_gap[i];
  }
  a.keyed = c.string("joints.keyed");
  for (char k : a.keyed)
  {
    if (labels.find(k) == std::string::npos)
      c.fail("joints.keyed",
             std::string("names joint ") + k + ", which is not a joint",
             "labels of the joints (" + labels + ")");
  }
  a.restitution = read_restitution(c);
  a.statics = read_joint_statics(c);
  a.history_points = read_joint_history_points(c);
  a.ncp = read_ncp_settings(c);
}
/// A reservoir level the mesh can follow: 0, or at least a tenth of
/// mesh.size from the base and the crest.
void check_water_line(const input::Case& c, const std::string& key,
                      double level, double h, double size)
{
  if (level > 0.0 && (level < 0.1 * size || level > h - 0.1 * size))
    c.fail(key,
           "is within a tenth of mesh.size of the base or of the crest, where "
           "the mesh cannot follow the water line",
           "0 (no reservoir) or a level between the base and the crest at "
           "least mesh.size / 10 from both");
}

/// study.table1 and its levels; one study at a time, bonded joints.
void read_table1_study(const input::Case& c, ArchDamConfig& a, double h)
{
  a.table1 = c.boolean("study.table1");
  a.table1_levels = c.reals("study.reservoir_levels");
  // (With study.table1 = false the levels stay unused: the study's case
  // file runs one model so.)
  if (!a.table1)
    return;
  if (a.table1_levels.empty())
    a.table1_levels = {a.seismic.reservoir.level};
  for (double level : a.table1_levels)
    check_water_line(c, "study.reservoir_levels", level, h,
                     a.geometry.mesh.size);
  if (!a.study_joints.empty() || c.boolean("study.foundation"))
    c.fail("study.table1", "is given with another study",
           "one study at a time (study.joints = [], study.foundation = "
           "false)");
  if (a.joints == JointModel::contact)
    c.fail("study.table1", "is the monolithic dam's study (bonded joints)",
           "joints.model = \"bonded\"; contact joints with HTC concrete "
           "run one model at a time (study.table1 = false)");
}

/// foundation.boundary = "mtf": the band in the mesh (around the block's
/// far faces, clear of the valley rims and of the dam), the formula's
/// order and drift, and the time step against s = c_p dt / dx <= 1 and
/// HHT alpha (check_transmitting_step; the explicit band's stable step is
/// checked when the run has its modes).
void read_transmitting(const input::Case& c, ArchDamConfig& a,
                       const geometry::ArchDamGeometry& shape)
{
  const bool active = a.boundary == FoundationBoundary::transmitting;
  if (active)
  {
    // The band's vertical cuts at the floor's edges and the rims
    // (geometry/arch_band) need walls that widen with height.
    const auto& p = shape.canyon_profile();
    for (std::size_t i = 0; i + 1 < p.size(); ++i)
      if (!(p[i + 1][1] < p[i][1] && p[i + 1][2] > p[i][2]))
        c.fail("canyon.x_left",
               "has a vertical or overhanging wall segment, which the "
               "multi-transmitting boundary's band cannot follow",
               "walls that widen with height (x_left decreasing, x_right "
               "increasing), or foundation.boundary = \"viscous_spring\"");
    if (a.joints == JointModel::contact &&
        a.concrete_model.kind == ConcreteModelKind::linear)
      c.fail("foundation.boundary",
             "mtf takes contact joints in the nonlinear engine only",
             "material.model = \"elastic\" (the same linear elastic dam in "
             "the nonlinear engine), or foundation.boundary = "
             "\"viscous_spring\"");
  }
  BandKeys band;
  a.transmitting = read_transmitting_keys(c, a.order, active, band);
  if (!active)
    return;
  const Transmitting& t = a.transmitting;
  auto& mesh = a.geometry.mesh;
  mesh.band_layers = band.layers;
  mesh.band_size = band.size;
  const double H = shape.height(), w = mesh.band_layers * mesh.band_size;
  const auto& f = a.geometry.foundation;
  const double room =
      H * std::min({f.upstream, f.downstream, f.below, f.beyond});
  if (!(w < room))
  {
    std::ostringstream problem, fix;
    problem << "makes the band (band_layers x band_size = " << w
            << " m) reach the dam, the valley's rims or the canyon floor ("
            << room << " m of rock)";
    fix << "a band thinner than " << room
        << " m, or larger foundation.extent_* (multiples of the height)";
    c.fail("foundation.band_size", problem.str(), fix.str());
  }
  // The stiffest rock the case runs (study.foundation's largest ratio).
  double E = a.rock.E;
  if (c.boolean("study.foundation"))
    for (double r : c.reals("study.foundation_ratios"))
      E = std::max(E, r * a.concrete.E);
  const boundary::Rock rock{E, a.rock.nu, a.rock_rho, false};
  check_transmitting_step(c, a.seismic.scheme.alpha, t,
                          a.concrete_model.kind != ConcreteModelKind::linear,
                          rock, a.seismic.scheme.dt);
}

/// study.joints: every set "none" or distinct candidate labels.
void read_joint_study(const input::Case& c, ArchDamConfig& a)
{
  a.study_joints = c.strings("study.joints");
  if (a.study_joints.empty())
    return;
  if (!a.geometry.joints.active.empty())
    c.fail("study.joints", "is given with joints.active",
           "joints.active = \"\" (each set of study.joints says which "
           "joints are active)");
  const std::string labels = candidate_labels(a);
  for (const std::string& set : a.study_joints)
  {
    if (set == "none")
      continue;
    if (set.empty())
      c.fail("study.joints", "has an empty set",
             "\"none\" for the dam without joints, or labels such as "
             "\"DGJ\"");
    for (std::size_t i = 0; i < set.size(); ++i)
    {
      if (labels.find(set[i]) == std::string::npos || set.find(set[i]) != i)
        c.fail("study.joints",
               "has the set \"" + set + "\": '" + set.substr(i, 1) + "' is " +
                   (labels.find(set[i]) == std::string::npos
                        ? "not a candidate joint"
                        : "repeated"),
               "distinct labels of the candidates (" + labels + ")");
    }
  }
}
} // namespace

ArchDamConfig read_arch_dam_config(const input::Case& c)
{
  ArchDamConfig a;
  a.geometry = geometry::read_arch_dam(c);
  // The mesh follows the water line: the wetted part of the upstream face
  // gets its own tag (upstream_wetted).
  a.geometry.mesh.water_level = c.real("reservoir.level");
  a.order = static_cast<int>(c.integer("mesh.order"));
  a.concrete = {c.real("material.E"), c.real("material.nu"),
                c.real("material.rho")};
  a.concrete_model = read_concrete_settings(c, a.concrete.E, a.concrete.nu);
  a.rock = {c.real("rock.E"), c.real("rock.nu"), 0.0};
  const geometry::ArchDamGeometry shape(a.geometry);
  const double h = shape.height();
  // Crown section: crest and base points on the upstream face.
  const auto crest = shape.face_point(h, 0.0, -1);
  const auto base = shape.face_point(0.0, 0.0, -1);
  a.seismic =
      read_seismic_settings(c, arch_dam_directions(), 3, h, crest, base);
  const double level = a.geometry.mesh.water_level;
  const double size = a.geometry.mesh.size;
  for (const auto& [key, x] :
       {std::pair{"output.crest_point", a.seismic.crest_point},
        std::pair{"output.base_point", a.seismic.base_point}})
  {
    check_output_point(c, key, x, 3, geometry::distance_from_model(shape, x),
                       size, "the dam or the foundation rock");
  }
  check_water_line(c, "reservoir.level", level, h, size);
  a.seismic.faces = {{"upstream", {tags::upstream_face, tags::upstream_wetted}},
                     {"downstream", {tags::downstream_face}}};
  read_joint_contact(c, a);
  read_joint_study(c, a);
  a.rock_rho = c.real("rock.rho");
  a.spring_factors = {c.real("foundation.spring_normal"),
                      c.real("foundation.spring_tangential")};
  const std::string boundary = c.string("foundation.boundary");
  a.boundary = boundary == "viscous_spring" ? FoundationBoundary::viscous_spring
               : boundary == "mtf"          ? FoundationBoundary::transmitting
                                            : FoundationBoundary::fixed;
  read_transmitting(c, a, shape);
  if (c.boolean("study.foundation"))
  {
    a.foundation_ratios = c.reals("study.foundation_ratios");
    if (a.foundation_ratios.empty())
      c.fail("study.foundation_ratios", "is empty",
             "ratios E_f / E_d such as [0.5, 1.0, 1.5]");
    if (!a.study_joints.empty())
      c.fail("study.foundation", "is given with study.joints",
             "one study at a time");
  }
  read_table1_study(c, a, h);
  if (a.boundary != FoundationBoundary::fixed)
    a = with_foundation(a, a.rock.E, a.boundary);
  return a;
}

ArchDamConfig with_reservoir_level(const ArchDamConfig& a, double level)
{
  ArchDamConfig c = a;
  c.geometry.mesh.water_level = level;
  c.seismic.reservoir.level = level;
  return c;
}

ArchDamConfig with_foundation(const ArchDamConfig& cfg, double E_f,
                              FoundationBoundary boundary)
{
  ArchDamConfig a = cfg;
  const bool with_mass = boundary != FoundationBoundary::fixed;
  a.rock.E = E_f;
  a.rock.rho = with_mass ? a.rock_rho : 0.0;
  a.wave.reset();
  a.seismic.gravity_regions.clear();
  if (!with_mass)
    return a;
  const geometry::ArchDamGeometry shape(a.geometry);
  const double h = shape.height();
  WaveFoundation w;
  w.boundary_tags = {tags::foundation_bottom, tags::foundation_sides,
                     tags::foundation_upstream, tags::foundation_downstream};
  w.centre = shape.face_point(0.0, 0.0, -1); // the crown's base
  w.factors = a.spring_factors;
  w.rock = {a.rock.E, a.rock.nu, a.rock.rho, false};
  // The model's bottom, and the crown's base (the canyon floor) as the
  // reference surface of the record's timing; each column's own ground is
  // its free surface (geometry::GroundSurface).
  w.z_base = -a.geometry.foundation.below * h;
  w.z_surface = w.centre[2];
  if (boundary == FoundationBoundary::transmitting)
    w.mtf = a.transmitting;
  a.wave = w;
  a.seismic.gravity_regions = {tags::dam};
  return a;
}

std::string candidate_labels(const ArchDamConfig& a)
{
  geometry::JointDefinition all = a.geometry.joints;
  all.active.clear();
  return joint_labels(all);
}

ArchDamConfig joint_study_case(const ArchDamConfig& a, const std::string& set)
{
  ArchDamConfig c = a;
  c.study_joints.clear();
  if (set == "none")
  {
    c.geometry.joints.count = 0;
    c.geometry.joints.positions.clear();
    c.geometry.joints.active.clear();
    c.joints = JointModel::bonded;
  }
  else
    c.geometry.joints.active = set;
  return c;
}

std::string joint_study_folder(const std::string& set)
{
  return set == "none" ? "joints_0"
                       : "joints_" + std::to_string(set.size()) + "_" + set;
}
} // namespace damseis::analysis
