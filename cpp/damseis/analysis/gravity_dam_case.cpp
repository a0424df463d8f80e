#include "gravity_dam_case.h"
#include "transmitting_keys.h"
#include <damseis/geometry/mesh_estimate.h>
#include <damseis/geometry/tags.h>
#include <damseis/results/singular_points.h>
#include <sstream>

namespace damseis::analysis
{
const std::vector<Direction>& gravity_dam_directions()
{
  static const std::vector<Direction> d = {
      {"horizontal", 0, DAMSEIS_SOURCE_DIR "/data/records/elcentro_1940_ns.at2",
       0.38},
      {"vertical", 1, "", 0.0}};
  return d;
}

input::Schema gravity_dam_schema()
{
  input::Schema s;
  // Geometry (default: the Koyna dam, non-overflow monolith).
  // Plausibility: the tallest dams are about 300 m high, their bases less
  // than 1 km long.
  s.real("geometry.heel_x", "0.0", "m",
         "x of the heel and the vertical upstream face")
      .between(-2000, 2000);
  s.real("geometry.toe_x", "70.0", "m", "x of the toe").between(-2000, 2000);
  s.real("geometry.neck_x", "19.25", "m", "x of the downstream slope change")
      .between(-2000, 2000);
  s.real("geometry.neck_y", "66.5", "m",
         "elevation of the downstream slope change")
      .above(0)
      .at_most(1000);
  s.real("geometry.crest_down_x", "14.8", "m",
         "x of the downstream crest corner")
      .between(-2000, 2000);
  s.real("geometry.crest_y", "103.0", "m", "crest elevation (the base is at 0)")
      .above(0)
      .at_most(1000);
  s.real("mesh.size", "2.0", "m", "element size in the dam")
      .between(0.001, 1000);
  s.integer("mesh.order", "2", "-", "displacement polynomial degree (1 or 2)")
      .between(1, 2);
  s.integer("mesh.max_cells", "1000000", "-",
            "refuse a mesh estimated above this many cells before meshing "
            "(raise it if the machine has the memory: about 4 GB per "
            "million P2 cells)")
      .at_least(1);
  // Materials.
  s.real("material.E", "30e9", "Pa", "Young's modulus of the dam concrete")
      .between(1e8, 2e11);
  s.real("material.nu", "0.2", "-", "Poisson's ratio of the dam concrete")
      .between_exclusive(-1, 0.5);
  s.real("material.rho", "2500", "kg/m3", "mass density of the dam concrete")
      .between(100, 20000);
  s.string("material.plane", "plane_stress", "-", "2D idealisation",
           {"plane_stress", "plane_strain"});
  s.boolean("output.mesh_file", "false", "-",
            "also write the model as model.msh (gmsh, physical groups named "
            "dam, foundation, upstream_face, dam_base, ...)");
  s.boolean("foundation.enabled", "false", "-",
            "foundation block (else a rigid base)");
  s.string("foundation.boundary", "fixed", "-",
           "fixed: massless block fixed at its sides and bottom, the ground "
           "motion as base acceleration; viscous_spring: the block with "
           "mass (foundation.rho) and a viscous-spring boundary, the ground "
           "motion as the outcrop motion of vertically incident waves; mtf: "
           "the same with Liao's multi-transmitting boundary on a "
           "structured band of explicit elements (foundation.band_*, "
           "foundation.mtf_*)",
           {"fixed", "viscous_spring", "mtf"});
  add_transmitting_keys(s, "sides and bottom", "10.0");
  s.real("foundation.rho", "2640", "kg/m3",
         "mass density of the rock (with boundary = viscous_spring; the "
         "fixed block is massless)")
      .between(100, 20000);
  s.real("foundation.spring_normal", "1.0", "-",
         "viscous-spring boundary: normal spring alpha_n G / R (R from the "
         "middle of the dam base)")
      .above(0)
      .at_most(10);
  s.real("foundation.spring_tangential", "0.5", "-",
         "viscous-spring boundary: tangential spring alpha_t G / R")
      .above(0)
      .at_most(10);
  s.real("foundation.width", "300.0", "m",
         "width of the foundation block, centred on the dam base")
      .above(0)
      .at_most(20000);
  s.real("foundation.depth", "100.0", "m", "depth of the foundation block")
      .above(0)
      .at_most(10000);
  s.real("foundation.E", "30e9", "Pa", "Young's modulus of the foundation rock")
      .between(1e7, 2e11);
  s.real("foundation.nu", "0.2", "-", "Poisson's ratio of the foundation rock")
      .between_exclusive(-1, 0.5);
  s.string("foundation.split", "none", "-",
           "the block in two rock regions: none; side_by_side (split under "
           "the middle of the dam base: foundation.E on the left, "
           "foundation.E2 on the right); layers (foundation.E above "
           "foundation.split_depth, foundation.E2 below)",
           {"none", "side_by_side", "layers"});
  s.real("foundation.E2", "30e9", "Pa",
         "Young's modulus of the second rock region (foundation.split)")
      .between(1e7, 2e11);
  s.real("foundation.split_depth", "0.0", "m",
         "depth of the layers' interface below the base (0: half the "
         "block's depth)")
      .at_least(0)
      .at_most(10000);
  s.real("foundation.mesh_size", "0.0", "m",
         "element size at the far boundaries (0: 2.5 x mesh.size; else at "
         "least mesh.size / 10)")
      .at_least(0)
      .at_most(10000);
  add_seismic_keys(s, gravity_dam_directions(), "[0.0, 103.0]", "[0.0, 0.0]");
  s.set_default("design.dam", "\"gravity\"");
  add_concrete_keys(s);
  s.real("silt.level", "0.0", "m",
         "elevation of the silt surface against the upstream face (0: no "
         "silt)")
      .at_least(0);
  s.real("silt.unit_weight", "9000", "N/m3", "submerged unit weight of silt")
      .above(0);
  s.real("silt.friction_angle", "15", "deg", "internal friction angle of silt")
      .between(0, 45);
  s.boolean(
      "uplift.enabled", "false", "-",
      "uplift on the dam base (acts on the dam; with a foundation block)");
  s.real("uplift.tailwater", "0.0", "m",
         "tailwater level above the base (head at the toe)")
      .at_least(0);
  s.real("uplift.drain_x", "-1", "m",
         "x of the drainage line (negative: 10% of the base width from the "
         "heel)");
  s.real("uplift.alpha", "0.25", "-",
         "residual uplift ratio at the drainage line")
      .between(0, 1);
  s.boolean("study.table6", "false", "-",
            "the foundation models side by side (the paper's Table 6, "
            "seismic stresses): for each ratio of study.foundation_ratios, "
            "the massless block fixed at its far boundary and the block "
            "with mass and a viscous-spring boundary (with the massless "
            "run's Rayleigh damping), into subfolders; table6.csv/.md");
  s.real_array("study.foundation_ratios", "[0.5, 1.0, 2.0]", "-",
               "E_f / E_d of the table6 study")
      .between(0.01, 100);
  s.boolean("study.table6_inhomogeneous", "false", "-",
            "with study.table6: also the paper's cases 4 (E_f/E_d = 0.5 "
            "and 1 side by side) and 5 (0.5 over 1 in layers, the "
            "interface at half the block's depth), with interaction");
  s.boolean("study.table1", "false", "-",
            "run the elastic, plastic and viscoplastic models (subfolders) "
            "and write table1.csv/.md (the paper's Table 1); each model "
            "takes its own factors (concrete.dynamic_factor_* for elastic "
            "and plastic, concrete.viscoplastic_factor_* for viscoplastic)");
  // Koyna defaults for the shared keys.
  s.set_default("reservoir.level", "91.75");
  return s;
}

namespace
{
/// The multi-transmitting boundary's keys (boundary = mtf): the band in
/// the mesh, the formula's order and drift.
void read_transmitting(const input::Case& c, GravityDamConfig& g)
{
  auto& s = g.section;
  const bool active = g.boundary == FoundationBoundary::transmitting;
  BandKeys band;
  g.transmitting = read_transmitting_keys(c, g.order, active, band);
  if (!active)
    return;
  s.band_layers = band.layers;
  s.band_size = band.size;
  if (s.foundation_split != geometry::GravityDamSection::Split::none)
    c.fail("foundation.boundary",
           "mtf is not yet available with a split foundation block",
           "foundation.split = \"none\" or boundary = \"viscous_spring\"");
  const double w = s.band_layers * s.band_size;
  if (!(w < s.foundation_depth &&
        w < 0.5 * (s.foundation_width - (s.toe_x - s.heel_x))))
    c.fail("foundation.band_size",
           "makes the band (band_layers x band_size) reach the dam or the "
           "block's depth",
           "a band thinner than the block beside and below the dam");
}

/// The time step against the multi-transmitting formula (c_p of the
/// stiffest rock the case runs).
void check_transmitting_step(const input::Case& c, const GravityDamConfig& g,
                             double largest_E)
{
  if (g.boundary != FoundationBoundary::transmitting)
    return;
  const boundary::Rock rock{largest_E, g.rock.nu, g.rock_rho,
                            g.plane == fem::PlaneMode::plane_stress};
  analysis::check_transmitting_step(c, g.seismic.scheme.alpha, g.transmitting,
                                    g.concrete_model.kind !=
                                        ConcreteModelKind::linear,
                                    rock, g.seismic.scheme.dt);
}

/// The foundation block's keys: size, mesh, rock, split (the boundary
/// and the study are read with the seismic keys).
void read_foundation_block(const input::Case& c, GravityDamConfig& g)
{
  auto& s = g.section;
  s.foundation = c.boolean("foundation.enabled");
  s.foundation_width = c.real("foundation.width");
  s.foundation_depth = c.real("foundation.depth");
  s.foundation_mesh_size = c.real("foundation.mesh_size");
  using Split = geometry::GravityDamSection::Split;
  const std::string split = c.string("foundation.split");
  s.foundation_split = split == "side_by_side" ? Split::side_by_side
                       : split == "layers"     ? Split::layers
                                               : Split::none;
  s.split_depth = c.real("foundation.split_depth");
  if (s.split_depth == 0.0)
    s.split_depth = 0.5 * s.foundation_depth;
  if (s.foundation_split != Split::none && !s.foundation)
    c.fail("foundation.split", "needs a foundation block",
           "foundation.enabled = true");
  if (s.foundation_split == Split::layers &&
      !(s.split_depth < s.foundation_depth))
    c.fail("foundation.split_depth", "is not above the block's bottom",
           "a depth below the base smaller than foundation.depth");
  g.rock_E2 = c.real("foundation.E2");
  g.rock = {c.real("foundation.E"), c.real("foundation.nu"), 0.0};
  if (s.foundation && !(s.foundation_width > s.toe_x - s.heel_x))
  {
    c.fail("foundation.width", "is narrower than the dam base",
           "a width larger than toe_x - heel_x");
  }
  if (s.foundation_mesh_size > 0.0 &&
      s.foundation_mesh_size < 0.1 * s.mesh_size)
    c.fail("foundation.mesh_size", "is finer than a tenth of mesh.size",
           "0 (2.5 x mesh.size) or a size at least mesh.size / 10");
}

} // namespace

GravityDamConfig read_gravity_dam_config(const input::Case& c)
{
  GravityDamConfig g;
  auto& s = g.section;
  s.heel_x = c.real("geometry.heel_x");
  s.toe_x = c.real("geometry.toe_x");
  s.neck_x = c.real("geometry.neck_x");
  s.neck_y = c.real("geometry.neck_y");
  s.crest_down_x = c.real("geometry.crest_down_x");
  s.crest_y = c.real("geometry.crest_y");
  s.base_y = 0.0;
  if (!(s.toe_x > s.heel_x))
    c.fail("geometry.toe_x", "is not downstream of the heel", "toe_x > heel_x");
  if (!(s.crest_down_x > s.heel_x && s.neck_x >= s.crest_down_x &&
        s.neck_x < s.toe_x))
  {
    c.fail("geometry.neck_x", "does not give a valid section",
           "heel_x < crest_down_x <= neck_x < toe_x");
  }
  if (!(s.neck_y < s.crest_y))
    c.fail("geometry.neck_y", "is not below the crest", "neck_y < crest_y");
  s.mesh_size = c.real("mesh.size");
  if (s.mesh_size > 0.25 * (s.crest_y - s.base_y))
    c.fail("mesh.size", "is too coarse for the section",
           "at most a quarter of the dam height");
  g.order = static_cast<int>(c.integer("mesh.order"));

  g.concrete = {c.real("material.E"), c.real("material.nu"),
                c.real("material.rho")};
  g.concrete_model = read_concrete_settings(c, g.concrete.E, g.concrete.nu);
  g.table1 = c.boolean("study.table1");
  g.plane = c.string("material.plane") == "plane_strain"
                ? fem::PlaneMode::plane_strain
                : fem::PlaneMode::plane_stress;
  g.write_mesh_file = c.boolean("output.mesh_file");
  read_foundation_block(c, g);
  geometry::check_cell_estimate(c, geometry::estimated_cells(s));
  const std::string boundary = c.string("foundation.boundary");
  g.boundary = boundary == "viscous_spring" ? FoundationBoundary::viscous_spring
               : boundary == "mtf"          ? FoundationBoundary::transmitting
                                            : FoundationBoundary::fixed;
  const bool with_mass = g.boundary != FoundationBoundary::fixed;
  if (with_mass && !s.foundation)
    c.fail("foundation.boundary", "needs a foundation block",
           "foundation.enabled = true");
  read_transmitting(c, g);

  g.seismic = read_seismic_settings(c, gravity_dam_directions(), 2, s.crest_y,
                                    {s.heel_x, s.crest_y, 0.0},
                                    {s.heel_x, s.base_y, 0.0});
  for (const auto& [key, x] :
       {std::pair{"output.crest_point", g.seismic.crest_point},
        std::pair{"output.base_point", g.seismic.base_point}})
  {
    check_output_point(
        c, key, x, 2, geometry::distance_from_model(s, x[0], x[1]), s.mesh_size,
        s.foundation ? "the dam section or its foundation block"
                     : "the dam section");
  }
  {
    double largest_E = g.rock.E;
    if (c.boolean("study.table6"))
      for (double r : c.reals("study.foundation_ratios"))
        largest_E = std::max(largest_E, r * g.concrete.E);
    check_transmitting_step(c, g, largest_E);
  }
  s.water_level = g.seismic.reservoir.level;
  if (s.water_level > 0.0 && s.water_level < 0.1 * s.mesh_size)
    c.fail("reservoir.level",
           "is a film above the base that the mesh cannot "
           "follow",
           "0 (no reservoir) or a level of at least mesh.size / 10");
  g.silt.level = c.real("silt.level");
  g.silt.unit_weight = c.real("silt.unit_weight");
  g.silt.friction_angle_deg = c.real("silt.friction_angle");
  if (g.silt.level > g.seismic.reservoir.level)
    c.fail("silt.level", "is above the reservoir level",
           "a silt surface below reservoir.level");
  g.uplift_on = c.boolean("uplift.enabled");
  if (g.uplift_on && !s.foundation)
    c.fail("uplift.enabled",
           "needs a foundation block (on a rigid base the "
           "uplift acts on fixed nodes)",
           "foundation.enabled = true");
  g.uplift.head_upstream = g.seismic.reservoir.depth();
  g.uplift.head_downstream = c.real("uplift.tailwater");
  g.uplift.alpha = c.real("uplift.alpha");
  g.uplift.x_heel = s.heel_x;
  g.uplift.x_toe = s.toe_x;
  const double drain = c.real("uplift.drain_x");
  g.uplift.x_drain = drain < 0 ? s.heel_x + 0.1 * (s.toe_x - s.heel_x) : drain;
  if (g.uplift_on &&
      !(g.uplift.x_drain > s.heel_x && g.uplift.x_drain < s.toe_x))
    c.fail("uplift.drain_x", "is not between the heel and the toe",
           "heel_x < drain_x < toe_x");
  if (g.uplift_on && g.uplift.head_downstream > g.uplift.head_upstream)
    c.fail("uplift.tailwater", "is above the reservoir",
           "a tailwater below reservoir.level");
  g.rock_rho = c.real("foundation.rho");
  g.spring_factors = {c.real("foundation.spring_normal"),
                      c.real("foundation.spring_tangential")};
  if (c.boolean("study.table6"))
  {
    if (!s.foundation)
      c.fail("study.table6", "needs a foundation block",
             "foundation.enabled = true");
    if (g.concrete_model.kind != ConcreteModelKind::linear || g.table1)
      c.fail("study.table6", "compares linear analyses",
             "material.model = \"linear\" and study.table1 = false");
    g.table6_ratios = c.reals("study.foundation_ratios");
    g.table6_inhomogeneous = c.boolean("study.table6_inhomogeneous");
    if (g.table6_ratios.empty())
      c.fail("study.foundation_ratios", "is empty",
             "ratios E_f / E_d such as [0.5, 1.0, 2.0]");
  }
  if (with_mass)
    g = with_foundation(g, g.rock.E, g.boundary);
  g.seismic.faces = {{"upstream", {tags::upstream_face}},
                     {"downstream", {tags::downstream_face}}};
  // The section counterclockwise from the heel: heel and toe are singular
  // (base corners), and so is any re-entrant corner (the neck).
  const auto polygon = geometry::section_outline(s);
  const int base_corners[2] = {0, 1};
  g.seismic.singular_points = results::reflex_corners(polygon, base_corners);
  g.seismic.singular_where =
      "the heel, the toe and the re-entrant corners of the section";
  return g;
}
GravityDamConfig with_foundation(const GravityDamConfig& cfg, double E_f,
                                 FoundationBoundary boundary)
{
  GravityDamConfig g = cfg;
  const auto& s = g.section;
  g.rock.E = E_f;
  g.rock.rho = boundary != FoundationBoundary::fixed ? g.rock_rho : 0.0;
  g.wave.reset();
  g.seismic.gravity_regions.clear();
  if (boundary == FoundationBoundary::fixed)
    return g;
  WaveFoundation w;
  if (boundary == FoundationBoundary::transmitting)
    w.mtf = g.transmitting;
  w.boundary_tags = {tags::foundation_bottom, tags::foundation_sides};
  w.centre = {0.5 * (s.heel_x + s.toe_x), s.base_y, 0.0};
  w.factors = g.spring_factors;
  w.rock = {g.rock.E, g.rock.nu, g.rock.rho,
            g.plane == fem::PlaneMode::plane_stress};
  w.z_base = s.base_y - s.foundation_depth;
  w.z_surface = s.base_y;
  boundary::Rock second = w.rock;
  second.E = g.rock_E2;
  using Split = geometry::GravityDamSection::Split;
  if (s.foundation_split == Split::side_by_side)
    w.right = {{0.5 * (s.heel_x + s.toe_x), second}};
  else if (s.foundation_split == Split::layers)
    w.layers = {{s.base_y - s.split_depth, second}, {s.base_y, w.rock}};
  g.wave = w;
  g.seismic.gravity_regions = {tags::dam};
  return g;
}
} // namespace damseis::analysis
