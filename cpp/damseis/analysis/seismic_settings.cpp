#include "seismic_settings.h"
#include <cmath>
#include <damseis/motion/ground_motion_case.h>
#include <damseis/motion/record.h>
#include <damseis/results/output_folder.h>
#include <damseis/results/progress.h>
#include <map>
#include <mpi.h>
#include <sstream>

namespace damseis::analysis
{
void add_seismic_keys(input::Schema& s,
                      const std::vector<Direction>& directions,
                      const std::string& crest_point,
                      const std::string& base_point)
{
  s.real("loads.gravity", "9.81", "m/s2",
         "gravitational acceleration for the dead weight")
      .between(0, 100);
  s.real("reservoir.level", "0.0", "m",
         "water level (elevation of the free surface; 0: empty)")
      .at_least(0);
  s.real("reservoir.rho_w", "1000", "kg/m3", "water density")
      .between(500, 2000);
  s.boolean("reservoir.westergaard", "true", "-",
            "Westergaard added mass on the wetted upstream face");
  s.boolean("reservoir.load_floor", "false", "-",
            "hydrostatic pressure also on the reservoir floor (with a "
            "foundation)");
  s.integer("modal.count", "6", "-", "number of natural modes computed")
      .between(1, 200);
  s.real("damping.ratio", "0.05", "-", "Rayleigh damping ratio").between(0, 1);
  s.integer_array("damping.modes", "[1, 3]", "-",
                  "the two modes (of the system with added mass) where the "
                  "ratio is exact");
  s.real_array("damping.frequencies_hz", "[]", "Hz",
               "two frequencies instead of damping.modes (empty: use the "
               "modes)")
      .above(0);
  s.real("time.dt", "0.01", "s", "time step").above(0).at_most(1.0);
  s.real("time.duration", "10.0", "s",
         "analysis duration (0: the longest record's length)")
      .between(0, 3600);
  s.real("time.hht_alpha", "0.0", "-",
         "HHT alpha in [-1/3, 0] (0: Newmark average acceleration)")
      .between(-1.0 / 3.0, 0);
  for (const Direction& d : directions)
  {
    const std::string p = "motion." + d.name;
    s.string(p + ".source", "record", "-",
             d.name + " motion: a record file (motion." + d.name +
                 ".record), or an artificial record matched to the design "
                 "spectrum ([design])",
             {"record", "generated"});
    s.string(p + ".record", d.default_record, "-",
             d.name +
                 " record: PEER .at2 or one/two-column text (empty: none)");
    s.string(p + ".units", "g", "-", "units of the record values",
             {"g", "m/s2"});
    s.string(p + ".format", "auto", "-", "record format",
             {"auto", "at2", "columns"});
    s.real(p + ".dt", "0.0", "s", "sample interval of a one-column record")
        .between(0, 1.0);
    std::ostringstream peak;
    peak << d.default_peak_g;
    s.real(p + ".peak_g", peak.str(), "g",
           "peak acceleration after scaling (0: unscaled)")
        .between(0, 5.0);
  }
  // The design motion of generated components (ground_motion's keys).
  motion::add_target_keys(s, "design");
  motion::add_generation_keys(s, "design");
  s.integer("output.every", "10", "-", "steps between XDMF field outputs")
      .at_least(1);
  s.string("output.stress", "total", "-", "stresses in envelopes and summary",
           {"total", "seismic"});
  s.real_array("output.crest_point", crest_point, "m",
               "point whose displacement history is recorded (empty: the "
               "crest of the crown section)");
  s.real_array("output.base_point", base_point, "m",
               "reference point: crest displacement is relative to it "
               "(empty: the base of the crown section)");
  s.real("output.singular_radius", "0", "m",
         "radius around the singular points (heel, toe, re-entrant corners; "
         "in 3D the dam-rock contact lines on the faces) left out of the "
         "mesh-objective stress extremes (0: 5% of the dam height)")
      .at_least(0);
  s.boolean("output.plots", "true", "-",
            "write PNG plots (needs python3-matplotlib)");
  results::add_overwrite_key(s);
  s.integer("run.checkpoint_every", "0", "-",
            "steps between checkpoints (0: none)")
      .at_least(0);
  s.boolean("run.restart", "false", "-",
            "resume from the checkpoint in the output folder");
  s.integer("run.stop_at_step", "0", "-",
            "write a checkpoint and stop at this step (0: run to the end)")
      .at_least(0);
  s.string("solver.factorization", "auto", "-",
           "sparse factorisation (auto: 2D petsc serially, redundant in "
           "parallel up to 1e5 unknowns; else mumps)",
           {"auto", "petsc", "mumps", "cholmod", "redundant"});
}

namespace
{
/// Most time steps of an analysis.
constexpr double max_steps = 1e7;

[[noreturn]] void fail_steps(const input::Case& c, double steps)
{
  std::ostringstream problem;
  problem << "gives " << steps << " steps";
  c.fail("time.dt", problem.str(),
         "at most 1e7 steps: a larger time.dt or a shorter time.duration "
         "(time.duration = 0 runs the whole record)");
}

/// The generated components of the case (source = "generated"), matched to
/// [design]: horizontal directions to the horizontal target, the vertical
/// (component dim - 1) to the vertical one; independent streams of
/// design.seed in the directions' order.
std::map<std::string, motion::Record>
generated_motions(const input::Case& c,
                  const std::vector<Direction>& directions, int dim)
{
  std::vector<const Direction*> generated;
  for (const Direction& d : directions)
    if (c.string("motion." + d.name + ".source") == "generated")
      generated.push_back(&d);
  if (generated.empty())
    return {};
  const motion::ArtificialSettings settings =
      motion::read_generation(c, "design", "design");
  std::vector<motion::DesignSpectrum> targets;
  for (const Direction* d : generated)
  {
    const std::string key = "motion." + d->name + ".peak_g";
    if (c.is_set(key) && c.real(key) > 0)
      results::warn(MPI_COMM_WORLD,
                    key + " is not used: the generated record has the design "
                          "acceleration (design.pga_g)");
    targets.push_back(
        motion::read_target(c, "design", d->component == dim - 1));
  }
  // Generated on rank 0 and broadcast: every rank drives the model with
  // the same samples (FFTW's code paths can depend on buffer alignment, so
  // independent generations could differ in the last bits).
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  std::vector<std::vector<double>> samples(generated.size());
  std::vector<double> worst(generated.size()), at(generated.size());
  std::vector<int> accepted(generated.size());
  if (rank == 0)
  {
    const auto m = motion::generate_motion(targets, settings);
    for (std::size_t i = 0; i < generated.size(); ++i)
    {
      samples[i] = m.components[i].acceleration;
      worst[i] = m.components[i].worst_ratio;
      at[i] = m.components[i].worst_period;
      accepted[i] = m.components[i].accepted;
    }
  }
  const auto n = static_cast<int>(generated.size());
  MPI_Bcast(worst.data(), n, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  MPI_Bcast(at.data(), n, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  MPI_Bcast(accepted.data(), n, MPI_INT, 0, MPI_COMM_WORLD);
  std::map<std::string, motion::Record> out;
  for (std::size_t i = 0; i < generated.size(); ++i)
  {
    auto length = static_cast<long long>(samples[i].size());
    MPI_Bcast(&length, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
    samples[i].resize(static_cast<std::size_t>(length));
    MPI_Bcast(samples[i].data(), static_cast<int>(length), MPI_DOUBLE, 0,
              MPI_COMM_WORLD);
    motion::Record r;
    r.dt = settings.dt;
    r.acceleration = std::move(samples[i]);
    std::ostringstream description;
    description.precision(3);
    description << "artificial record (seed " << settings.seed << ", "
                << targets[i].describe() << "; spectrum within "
                << 100 * (worst[i] - 1) << "% at " << at[i] << " s)";
    r.description = description.str();
    if (!accepted[i])
      results::warn(MPI_COMM_WORLD,
                    "motion." + generated[i]->name +
                        ": the generated record is not within "
                        "design.tolerance of the design spectrum (" +
                        r.description + ")");
    out.emplace(generated[i]->name, std::move(r));
  }
  return out;
}

GroundMotion read_motion(const input::Case& c, const std::string& p, double dt,
                         double duration,
                         const std::map<std::string, motion::Record>& generated)
{
  GroundMotion gm;
  const auto it = generated.find(p.substr(p.find('.') + 1));
  if (it == generated.end() && c.string(p + ".record").empty())
    return gm;
  const auto file = c.path(p + ".record");
  motion::Record r;
  if (it != generated.end())
    r = it->second;
  else
  {
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
  }
  gm.active = true;
  const bool made = it != generated.end();
  gm.record = made ? "generated (" + it->first + ", design.seed " +
                         std::to_string(c.integer("design.seed")) + ")"
                   : file.string();
  const std::string shown =
      made ? "the generated record" : file.filename().string();
  gm.description = r.description;
  // The whole record is scaled to the target peak (so a run shorter than
  // the record sees the same signal), then resampled; duration < 0 means the
  // record's own length.
  gm.peak_g = made ? 0.0 : c.real(p + ".peak_g");
  // An unscaled record must be a ground acceleration (a record in cm/s2
  // read as g is not).
  if (gm.peak_g == 0.0 && r.peak() > 5.0 * motion::standard_gravity)
  {
    std::ostringstream problem;
    problem << shown << " peaks at " << r.peak() / motion::standard_gravity
            << " g, not a ground acceleration";
    c.fail(p + ".record", problem.str(),
           "a record in the units of " + p +
               ".units (g or m/s2) below 5 g, "
               "or a target " +
               p + ".peak_g");
  }
  if (gm.peak_g > 0.0)
  {
    try
    {
      motion::scale_to_peak(r.acceleration,
                            gm.peak_g * motion::standard_gravity);
    }
    catch (const motion::RecordError& e)
    {
      throw input::InputError(c.file().string() + ": " + p +
                              ".record: " + e.what());
    }
  }
  else
    gm.peak_g = r.peak() / motion::standard_gravity;
  // The step count is checked before the resampled record is allocated.
  const double length = duration < 0 ? r.duration() : duration;
  if (length / dt > max_steps)
    fail_steps(c, length / dt);
  gm.acceleration = motion::resample(r, dt, length);
  if (duration > r.duration())
  {
    std::ostringstream w;
    w << p << ": " << shown << " lasts " << r.duration()
      << " s, time.duration is " << duration
      << " s: the ground acceleration is zero after " << r.duration() << " s";
    results::warn(MPI_COMM_WORLD, w.str());
  }
  return gm;
}

std::array<double, 3> point(const input::Case& c, const std::string& key,
                            int dim, const std::array<double, 3>& automatic)
{
  auto v = c.reals(key);
  if (v.empty())
    return automatic;
  if (static_cast<int>(v.size()) != dim)
  {
    c.fail(key, "has " + std::to_string(v.size()) + " coordinates",
           std::to_string(dim) + " coordinates");
  }
  std::array<double, 3> x = {0, 0, 0};
  std::copy(v.begin(), v.end(), x.begin());
  return x;
}
} // namespace

SeismicSettings read_seismic_settings(const input::Case& c,
                                      const std::vector<Direction>& directions,
                                      int dim, double crest_elevation,
                                      const std::array<double, 3>& crest,
                                      const std::array<double, 3>& base,
                                      bool motion_optional)
{
  SeismicSettings g;
  g.gravity = c.real("loads.gravity");
  g.reservoir.level = c.real("reservoir.level");
  g.reservoir.bottom = 0.0;
  g.reservoir.rho_w = c.real("reservoir.rho_w");
  g.reservoir.g = g.gravity;
  g.reservoir.load_floor = c.boolean("reservoir.load_floor");
  g.westergaard = c.boolean("reservoir.westergaard");
  if (g.reservoir.level > crest_elevation)
  {
    std::ostringstream problem, expected;
    problem << "= " << g.reservoir.level << " m is above the crest";
    expected << "a level between 0 and the crest elevation " << crest_elevation
             << " m";
    c.fail("reservoir.level", problem.str(), expected.str());
  }

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
  const double duration = c.real("time.duration");
  bool any = false;
  const auto generated = generated_motions(c, directions, dim);
  for (const Direction& d : directions)
  {
    GroundMotion m = read_motion(c, "motion." + d.name, g.scheme.dt,
                                 duration > 0 ? duration : -1.0, generated);
    any = any || m.active;
    g.motion[d.component] = std::move(m);
  }
  if (!any && !motion_optional)
  {
    c.fail("motion." + directions.front().name + ".record",
           "is empty, and so are the other components",
           "at least one ground-motion record");
  }
  if (!any && duration > 0.0)
  {
    // No ground motion (other loads drive the model): the steps of the
    // duration.
    if (duration / g.scheme.dt > max_steps)
      fail_steps(c, duration / g.scheme.dt);
    g.motion[0].acceleration.assign(
        static_cast<std::size_t>(std::llround(duration / g.scheme.dt)) + 1,
        0.0);
  }
  // With duration 0, shorter records are padded with zeros to the longest.
  std::size_t samples = 0;
  for (const GroundMotion& m : g.motion)
    samples = std::max(samples, m.acceleration.size());
  for (const Direction& d : directions)
  {
    const GroundMotion& m = g.motion[d.component];
    if (duration == 0.0 && m.active && m.acceleration.size() < samples)
    {
      results::warn(
          MPI_COMM_WORLD,
          "motion." + d.name +
              ".record is shorter than the "
              "longest record: its acceleration is zero after " +
              std::to_string((m.acceleration.size() - 1) * g.scheme.dt) + " s");
    }
  }
  if (samples < 2)
    c.fail("time.duration", "is shorter than one step", "duration >= time.dt");
  if (samples - 1 > max_steps)
    fail_steps(c, static_cast<double>(samples - 1));
  g.steps = static_cast<int>(samples) - 1;
  for (GroundMotion& m : g.motion)
    m.acceleration.resize(samples, 0.0);

  g.output_every = static_cast<int>(c.integer("output.every"));
  g.stress_total = c.string("output.stress") == "total";
  g.crest_point = point(c, "output.crest_point", dim, crest);
  g.base_point = point(c, "output.base_point", dim, base);
  g.plots = c.boolean("output.plots");
  g.singular_radius = c.real("output.singular_radius");
  if (g.singular_radius == 0.0)
    g.singular_radius = 0.05 * crest_elevation;
  g.checkpoint_every = static_cast<int>(c.integer("run.checkpoint_every"));
  g.restart = c.boolean("run.restart");
  g.stop_at_step = static_cast<int>(c.integer("run.stop_at_step"));
  g.factorization =
      linalg::parse_factorization(c.string("solver.factorization"));
  // PETSc's own (non-supernodal) factorisation is the fastest for 2D
  // sections but far too slow in 3D, where MUMPS wins (bench/).
  if (g.factorization == linalg::Factorization::automatic && dim == 3)
    g.factorization = linalg::Factorization::mumps;
  return g;
}

void check_output_point(const input::Case& c, const std::string& key,
                        const std::array<double, 3>& x, int dim,
                        double distance, double tolerance,
                        const std::string& model)
{
  if (distance <= tolerance)
    return;
  std::ostringstream problem;
  problem << "= [";
  for (int i = 0; i < dim; ++i)
    problem << (i ? ", " : "") << x[i];
  problem << "] is " << distance << " m outside the model";
  c.fail(key, problem.str(),
         "a point in " + model +
             " (within one mesh.size of it), or [] for the default");
}
} // namespace damseis::analysis
