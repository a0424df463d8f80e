#include "gravity_dam_case.h"
#include <cmath>
#include <damseis/motion/record.h>
#include <sstream>

namespace damseis::analysis
{
input::Schema gravity_dam_schema()
{
  input::Schema s;
  // Geometry (default: the Koyna dam, non-overflow monolith).
  s.real("geometry.heel_x", "0.0", "m",
         "x of the heel and the vertical upstream face");
  s.real("geometry.toe_x", "70.0", "m", "x of the toe");
  s.real("geometry.neck_x", "19.25", "m", "x of the downstream slope change");
  s.real("geometry.neck_y", "66.5", "m",
         "elevation of the downstream slope change")
      .above(0);
  s.real("geometry.crest_down_x", "14.8", "m",
         "x of the downstream crest corner");
  s.real("geometry.crest_y", "103.0", "m", "crest elevation (the base is at 0)")
      .above(0);
  s.real("mesh.size", "2.0", "m", "element size in the dam").above(0);
  s.integer("mesh.order", "2", "-", "displacement polynomial degree (1 or 2)")
      .between(1, 2);
  // Materials.
  s.real("material.E", "30e9", "Pa", "Young's modulus of the dam concrete")
      .above(0);
  s.real("material.nu", "0.2", "-", "Poisson's ratio of the dam concrete")
      .between_exclusive(-1, 0.5);
  s.real("material.rho", "2500", "kg/m3", "mass density of the dam concrete")
      .above(0);
  s.string("material.plane", "plane_stress", "-", "2D idealisation",
           {"plane_stress", "plane_strain"});
  s.boolean("foundation.enabled", "false", "-",
            "massless foundation block (else a rigid base)");
  s.real("foundation.width", "300.0", "m",
         "width of the foundation block, centred on the dam base")
      .above(0);
  s.real("foundation.depth", "100.0", "m", "depth of the foundation block")
      .above(0);
  s.real("foundation.E", "30e9", "Pa", "Young's modulus of the foundation rock")
      .above(0);
  s.real("foundation.nu", "0.2", "-", "Poisson's ratio of the foundation rock")
      .between_exclusive(-1, 0.5);
  s.real("foundation.mesh_size", "0.0", "m",
         "element size at the far boundaries (0: 2.5 x mesh.size)")
      .at_least(0);
  // Loads.
  s.real("loads.gravity", "9.81", "m/s2",
         "gravitational acceleration for the dead weight")
      .at_least(0);
  s.real("reservoir.level", "91.75", "m",
         "water level above the base (0: empty)")
      .at_least(0);
  s.real("reservoir.rho_w", "1000", "kg/m3", "water density").above(0);
  s.boolean("reservoir.westergaard", "true", "-",
            "Westergaard added mass on the wetted upstream face");
  s.boolean(
      "reservoir.load_floor", "false", "-",
      "hydrostatic pressure also on the reservoir floor (with a foundation)");
  // Modal analysis and damping.
  s.integer("modal.count", "6", "-", "number of natural modes computed")
      .between(1, 200);
  s.real("damping.ratio", "0.05", "-", "Rayleigh damping ratio").between(0, 1);
  s.integer_array(
      "damping.modes", "[1, 3]", "-",
      "the two modes (of the system with added mass) where the ratio is exact");
  s.real_array(
       "damping.frequencies_hz", "[]", "Hz",
       "two frequencies instead of damping.modes (empty: use the modes)")
      .above(0);
  // Time integration.
  s.real("time.dt", "0.01", "s", "time step").above(0);
  s.real("time.duration", "10.0", "s",
         "analysis duration (0: the record's length)")
      .at_least(0);
  s.real("time.hht_alpha", "0.0", "-",
         "HHT alpha in [-1/3, 0] (0: Newmark average acceleration)")
      .between(-1.0 / 3.0, 0);
  // Ground motion.
  for (const char* c : {"horizontal", "vertical"})
  {
    const std::string p = std::string("motion.") + c;
    const bool h = std::string(c) == "horizontal";
    s.string(
        p + ".record", h ? "../../data/records/elcentro_1940_ns.at2" : "", "-",
        std::string(c) +
            " record file: PEER .at2 or one/two-column text (empty: none)");
    s.string(p + ".units", "g", "-", "units of the record values",
             {"g", "m/s2"});
    s.string(p + ".format", "auto", "-", "record format",
             {"auto", "at2", "columns"});
    s.real(p + ".dt", "0.0", "s", "sample interval of a one-column record")
        .at_least(0);
    s.real(p + ".peak_g", h ? "0.38" : "0.0", "g",
           "peak acceleration after scaling (0: unscaled)")
        .at_least(0);
  }
  // Output and solver.
  s.integer("output.every", "10", "-", "steps between XDMF field outputs")
      .at_least(1);
  s.string("output.stress", "total", "-", "stresses in envelopes and summary",
           {"total", "seismic"});
  s.real_array("output.crest_point", "[0.0, 103.0]", "m",
               "point whose displacement history is recorded");
  s.real_array("output.base_point", "[0.0, 0.0]", "m",
               "reference point: crest displacement is relative to it");
  s.boolean("output.plots", "true", "-",
            "write PNG plots (needs python3-matplotlib)");
  s.string("solver.factorization", "auto", "-",
           "sparse Cholesky used (auto: petsc serial, mumps in parallel)",
           {"auto", "petsc", "mumps", "cholmod"});
  return s;
}

namespace
{
GroundMotion read_motion(const input::Case& c, const std::string& which,
                         double dt, double& duration)
{
  const std::string p = "motion." + which;
  GroundMotion gm;
  if (c.string(p + ".record").empty())
    return gm;
  const auto file = c.path(p + ".record");
  motion::Record r;
  try
  {
    r = motion::read_record(file, motion::parse_units(c.string(p + ".units")),
                            motion::parse_format(c.string(p + ".format")),
                            c.real(p + ".dt"));
  }
  catch (const motion::RecordError& e)
  {
    // The record error already says what is wrong and what is expected.
    throw input::InputError(c.file().string() + ": " + p +
                            ".record: " + e.what());
  }
  if (duration == 0.0)
    duration = r.duration();
  gm.active = true;
  gm.record = file.string();
  gm.description = r.description;
  gm.acceleration = motion::resample(r, dt, duration);
  gm.peak_g = c.real(p + ".peak_g");
  if (gm.peak_g > 0.0)
  {
    try
    {
      motion::scale_to_peak(gm.acceleration,
                            gm.peak_g * motion::standard_gravity);
    }
    catch (const motion::RecordError& e)
    {
      c.fail(p + ".record", e.what(), "a record with non-zero values");
    }
  }
  else
  {
    double peak = 0.0;
    for (double a : gm.acceleration)
      peak = std::max(peak, std::abs(a));
    gm.peak_g = peak / motion::standard_gravity;
  }
  return gm;
}

std::array<double, 3> point(const input::Case& c, const std::string& key)
{
  auto v = c.reals(key);
  if (v.size() != 2)
    c.fail(key, "has " + std::to_string(v.size()) + " values", "[x, y]");
  return {v[0], v[1], 0.0};
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
  g.plane = c.string("material.plane") == "plane_strain"
                ? fem::PlaneMode::plane_strain
                : fem::PlaneMode::plane_stress;
  s.foundation = c.boolean("foundation.enabled");
  s.foundation_width = c.real("foundation.width");
  s.foundation_depth = c.real("foundation.depth");
  s.foundation_mesh_size = c.real("foundation.mesh_size");
  g.rock = {c.real("foundation.E"), c.real("foundation.nu"), 0.0};
  if (s.foundation && !(s.foundation_width > s.toe_x - s.heel_x))
  {
    c.fail("foundation.width", "is narrower than the dam base",
           "a width larger than toe_x - heel_x");
  }

  g.gravity = c.real("loads.gravity");
  g.reservoir.level = c.real("reservoir.level");
  g.reservoir.bottom = s.base_y;
  g.reservoir.rho_w = c.real("reservoir.rho_w");
  g.reservoir.g = g.gravity;
  g.reservoir.load_floor = c.boolean("reservoir.load_floor");
  g.westergaard = c.boolean("reservoir.westergaard");
  if (g.reservoir.level > s.crest_y)
  {
    std::ostringstream problem, expected;
    problem << "= " << g.reservoir.level << " m is above the crest";
    expected << "a level between 0 and geometry.crest_y = " << s.crest_y
             << " m";
    c.fail("reservoir.level", problem.str(), expected.str());
  }
  s.water_level = g.reservoir.level;

  g.modes = static_cast<int>(c.integer("modal.count"));
  g.damping_ratio = c.real("damping.ratio");
  g.damping_modes = c.integers("damping.modes");
  g.damping_frequencies_hz = c.reals("damping.frequencies_hz");
  if (!g.damping_frequencies_hz.empty())
  {
    if (g.damping_frequencies_hz.size() != 2 ||
        g.damping_frequencies_hz[0] == g.damping_frequencies_hz[1])
    {
      c.fail("damping.frequencies_hz", "must hold two distinct frequencies",
             "[f1, f2] in Hz, or [] to use damping.modes");
    }
  }
  else
  {
    const auto& m = g.damping_modes;
    if (m.size() != 2 || m[0] < 1 || m[1] < 1 || m[0] == m[1] ||
        m[0] > g.modes || m[1] > g.modes)
    {
      c.fail("damping.modes", "must name two distinct computed modes",
             "two mode numbers between 1 and modal.count");
    }
  }

  g.scheme.dt = c.real("time.dt");
  g.scheme.alpha = c.real("time.hht_alpha");
  double duration = c.real("time.duration");
  g.horizontal = read_motion(c, "horizontal", g.scheme.dt, duration);
  g.vertical = read_motion(c, "vertical", g.scheme.dt, duration);
  if (!g.horizontal.active && !g.vertical.active)
  {
    c.fail("motion.horizontal.record",
           "and motion.vertical.record are both empty",
           "at least one ground-motion record");
  }
  if (!(duration >= g.scheme.dt))
    c.fail("time.duration", "is shorter than one step", "duration >= time.dt");
  g.steps = static_cast<int>(std::floor(duration / g.scheme.dt + 1e-9));
  // Every component gets exactly steps + 1 samples (t_0 .. t_steps).
  for (GroundMotion* m : {&g.horizontal, &g.vertical})
  {
    if (m->active)
      m->acceleration.resize(g.steps + 1, 0.0);
    else
      m->acceleration.assign(g.steps + 1, 0.0);
  }

  g.output_every = static_cast<int>(c.integer("output.every"));
  g.stress_total = c.string("output.stress") == "total";
  g.crest_point = point(c, "output.crest_point");
  g.base_point = point(c, "output.base_point");
  g.plots = c.boolean("output.plots");
  g.factorization = fem::parse_factorization(c.string("solver.factorization"));
  return g;
}
} // namespace damseis::analysis
