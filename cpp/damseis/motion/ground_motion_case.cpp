#include "ground_motion_case.h"
#include <damseis/results/output_folder.h>
#include <sstream>
#include <stdexcept>

namespace damseis::motion
{
void add_target_keys(input::Schema& s, const std::string& p)
{
  s.string(p + ".code", "NB35047-2015", "-",
           "design spectrum: the Chinese hydraulic codes (DL 5073-2000: "
           "exponent 0.9; NB 35047-2015: 0.6), Eurocode 8 types 1/2, or a "
           "table",
           {"NB35047-2015", "DL5073-2000", "EC8-type1", "EC8-type2", "table"});
  s.string(p + ".dam", "arch", "-",
           "structure (Chinese codes: beta_max 2.5 arch, 2.0 gravity, 2.25 "
           "other concrete, 1.6 earth-rock)",
           {"arch", "gravity", "other_concrete", "earth_rock"});
  s.string(p + ".site_class", "I1", "-",
           "site class: DL 5073 I-IV; NB 35047 I0, I1, II, III, IV; "
           "Eurocode 8 ground A-E");
  s.real(p + ".tg_map", "0.40", "s",
         "NB 35047: characteristic period of the zoning map for class II "
         "sites (0.35, 0.40 or 0.45; GB 18306-2015)")
      .between(0.35, 0.45);
  s.real(p + ".pga_g", "0.321", "g",
         "design horizontal peak ground acceleration (Chinese a_h; "
         "Eurocode a_g)")
      .above(0)
      .at_most(2.0);
  s.real(p + ".vertical_ratio", "0.6667", "-",
         "Chinese codes: vertical / horizontal design acceleration")
      .above(0)
      .at_most(1.5);
  s.real(p + ".tg", "0.0", "s",
         "Chinese codes: Tg instead of the site-class table (0: the table; "
         "DL 5073 §4.3.6 adds 0.05 s for a fundamental period over 1 s at "
         "intensity 8 or less: give that here)")
      .at_least(0)
      .at_most(3.0);
  s.real(p + ".beta_max", "0.0", "-",
         "Chinese codes: beta_max instead of the dam-type value (0: that)")
      .at_least(0)
      .at_most(5.0);
  s.real(p + ".damping", "0.05", "-",
         "Eurocode 8: viscous damping ratio of the spectrum (eta)")
      .above(0)
      .below(1);
  s.real_array(p + ".table_period", "[]", "s",
               "table: periods, increasing (from 0, or give pga_g)")
      .at_least(0)
      .at_most(100);
  s.real_array(p + ".table_sa_g", "[]", "g",
               "table: pseudo-accelerations at table_period")
      .above(0)
      .at_most(20);
}

DesignSpectrum read_target(const input::Case& c, const std::string& p,
                           bool vertical)
{
  DesignSpectrumSettings d;
  d.code = parse_spectrum_code(c.string(p + ".code"));
  d.dam = parse_dam_type(c.string(p + ".dam"));
  d.site_class = c.string(p + ".site_class");
  d.tg_map = c.real(p + ".tg_map");
  d.pga = c.real(p + ".pga_g") * standard_gravity;
  d.vertical = vertical;
  d.vertical_ratio = c.real(p + ".vertical_ratio");
  if (c.real(p + ".tg") > 0)
    d.tg = c.real(p + ".tg");
  if (c.real(p + ".beta_max") > 0)
    d.beta_max = c.real(p + ".beta_max");
  d.damping = c.real(p + ".damping");
  d.table_period = c.reals(p + ".table_period");
  for (double sa : c.reals(p + ".table_sa_g"))
    d.table_sa.push_back(sa * standard_gravity);
  if (d.code == SpectrumCode::table && !c.is_set(p + ".pga_g"))
    d.pga = 0; // the table's Sa(0)
  try
  {
    return DesignSpectrum(d);
  }
  catch (const std::invalid_argument& e)
  {
    // The message names the value; the key is the code's settings.
    const std::string key =
        d.code == SpectrumCode::table ? p + ".table_period" : p + ".site_class";
    c.fail(key,
           "gives an invalid design spectrum (" + std::string(e.what()) + ")",
           "a spectrum the code defines (see --help for " + p + ".*)");
  }
}

void add_generation_keys(input::Schema& s, const std::string& p)
{
  s.real(p + ".duration", "20.0", "s", "length of the records")
      .between(2.0, 600.0);
  s.real(p + ".dt", "0.01", "s", "time step of the records")
      .between(0.001, 0.05);
  s.integer(p + ".seed", "1", "-",
            "random seed (the same seed gives the same records)")
      .between(0, 2147483647);
  s.real(p + ".rise", "2.0", "s", "envelope: (t / rise)^2 up to rise").above(0);
  s.real(p + ".strong_end", "12.0", "s",
         "envelope: strong phase (1) from rise to strong_end")
      .above(0);
  s.real(p + ".decay", "0.35", "1/s",
         "envelope: exp(-decay (t - strong_end)) after it")
      .above(0)
      .at_most(100);
  s.real(p + ".tolerance", "0.10", "-",
         "acceptance: |Sa / target - 1| at every control period")
      .between(0.01, 0.5);
  s.real(p + ".max_correlation", "0.16", "-",
         "largest |correlation| between components (SRP 3.7.1: 0.16, "
         "ASCE 4: 0.3)")
      .between(0.01, 1.0);
  s.real(p + ".period_min", "0.04", "s", "shortest control period").above(0);
  s.real(p + ".period_max", "4.0", "s", "longest control period").above(0);
  s.integer(p + ".periods", "100", "-",
            "control periods, log-spaced (at least 50 by practice)")
      .between(2, 1000);
}

ArtificialSettings read_generation(const input::Case& c, const std::string& p,
                                   const std::string& target)
{
  ArtificialSettings s;
  // The records are matched at the damping of the target spectrum:
  // Eurocode 8's (its eta), 5% for the Chinese codes and tables.
  const auto code = parse_spectrum_code(c.string(target + ".code"));
  if (code == SpectrumCode::ec8_type1 || code == SpectrumCode::ec8_type2)
    s.damping = c.real(target + ".damping");
  s.duration = c.real(p + ".duration");
  s.dt = c.real(p + ".dt");
  s.seed = static_cast<std::uint64_t>(c.integer(p + ".seed"));
  s.envelope = {c.real(p + ".rise"), c.real(p + ".strong_end"),
                c.real(p + ".decay")};
  s.tolerance = c.real(p + ".tolerance");
  s.max_correlation = c.real(p + ".max_correlation");
  const double t0 = c.real(p + ".period_min"), t1 = c.real(p + ".period_max");
  if (!(t0 < t1))
    c.fail(p + ".period_min", "is not below " + p + ".period_max",
           "period_min < period_max");
  if (!(t0 > 2 * s.dt))
    c.fail(p + ".period_min", "is not above 2 x " + p + ".dt",
           "control periods resolved by the time step");
  if (!(t1 <= s.duration / 2))
    c.fail(p + ".period_max", "is above half the duration",
           "period_max <= duration / 2");
  if (!(s.envelope.rise < s.envelope.strong_end &&
        s.envelope.strong_end < s.duration))
    c.fail(p + ".strong_end",
           "is not between " + p + ".rise and " + p + ".duration",
           "rise < strong_end < duration");
  s.control_periods =
      log_spaced(t0, t1, static_cast<int>(c.integer(p + ".periods")));
  // A table target must cover the control periods (the vertical one is
  // the same table scaled).
  const DesignSpectrum t = read_target(c, target, false);
  if (!(t.min_period() <= t0 && t.max_period() >= t1))
    c.fail(target + ".table_period", "does not cover the control periods",
           "a table over " + p + ".period_min to " + p + ".period_max");
  return s;
}

const std::vector<std::string>& component_names()
{
  static const std::vector<std::string> names = {"h1", "h2", "v"};
  return names;
}

input::Schema ground_motion_schema()
{
  input::Schema s;
  s.string("task", "generate", "-",
           "generate: three spectrum-compatible artificial records; "
           "spectrum: the response spectra of record files",
           {"generate", "spectrum"});
  add_target_keys(s, "target");
  s.boolean("target.compare", "true", "-",
            "spectrum task: plot and tabulate the target too");
  add_generation_keys(s, "generate");
  for (const auto& name : component_names())
    s.string("records." + name, "", "-",
             "spectrum task: record file of component " + name +
                 " (empty: none)");
  s.string("records.units", "g", "-", "units of the record values",
           {"g", "m/s2"});
  s.string("records.format", "auto", "-",
           "record layout (auto: .at2 is PEER, else columns)",
           {"auto", "at2", "columns"});
  s.real("records.dt", "0.0", "s", "time step of one-column records")
      .between(0, 1);
  s.real_array("spectra.damping", "[0.05]", "-",
               "damping ratios of the spectra written")
      .above(0)
      .below(1);
  s.real("spectra.period_min", "0.02", "s", "spectrum task: shortest period")
      .at_least(0.005);
  s.real("spectra.period_max", "10.0", "s", "spectrum task: longest period")
      .above(0)
      .at_most(100);
  s.integer("spectra.periods", "200", "-", "spectrum task: log-spaced periods")
      .between(2, 10000);
  s.boolean("output.plots", "true", "-",
            "write the PNG plots (needs python3-matplotlib)");
  results::add_overwrite_key(s);
  return s;
}

GroundMotionConfig read_ground_motion_config(const input::Case& c)
{
  GroundMotionConfig g;
  g.generate = c.string("task") == "generate";
  g.plots = c.boolean("output.plots");
  g.damping = c.reals("spectra.damping");
  if (g.damping.empty())
    c.fail("spectra.damping", "is empty", "at least one damping ratio");
  g.has_target = g.generate || c.boolean("target.compare");
  if (g.has_target)
  {
    const auto h = read_target(c, "target", false);
    g.targets = {h, h, read_target(c, "target", true)};
  }
  if (g.generate)
  {
    g.generation = read_generation(c, "generate", "target");
    return g;
  }
  const double t0 = c.real("spectra.period_min"),
               t1 = c.real("spectra.period_max");
  if (!(t0 < t1))
    c.fail("spectra.period_min", "is not below spectra.period_max",
           "period_min < period_max");
  g.periods =
      log_spaced(t0, t1, static_cast<int>(c.integer("spectra.periods")));
  if (g.has_target &&
      !(g.targets[0].min_period() <= t0 && g.targets[0].max_period() >= t1))
    c.fail("target.table_period", "does not cover the spectra's periods",
           "a table over spectra.period_min to spectra.period_max, or "
           "target.compare = false");
  // The records are read now, before anything is written.
  const Units units = parse_units(c.string("records.units"));
  const Format format = parse_format(c.string("records.format"));
  for (const auto& name : component_names())
  {
    const std::string key = "records." + name;
    if (c.string(key).empty())
      continue;
    try
    {
      g.records.push_back(
          {name, c.path(key),
           read_record(c.path(key), units, format, c.real("records.dt"))});
    }
    catch (const RecordError& e)
    {
      throw input::InputError(c.file().string() + ": " + key + ": " + e.what());
    }
    if (g.records.back().record.acceleration.size() < 2)
      c.fail(key, "holds fewer than two samples",
             "a record of at least two samples");
  }
  if (g.records.empty())
    c.fail("records.h1", "is empty, and so are the other components",
           "at least one record file for task = \"spectrum\"");
  return g;
}
} // namespace damseis::motion
