// Design ground motions: three spectrum-compatible artificial records
// (task = "generate") or the response spectra of record files (task =
// "spectrum"), with CSV, AT2, summary.json and PNG plots
// (scripts/plot_ground_motion.py). Exit codes: 0 done, 1 internal error,
// 2 bad input, 4 records that could not be matched within the tolerance
// (written all the same, and said).
//   build/bin/ground_motion [--case FILE] [--out DIR] [--set key=value ...]
// With no arguments it runs demos/ground_motion/ground_motion.toml.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <damseis/input/command_line.h>
#include <damseis/motion/ground_motion_output.h>
#include <damseis/results/core_demo.h>
#include <filesystem>
#include <fstream>
#include <optional>

namespace
{
using namespace damseis;

/// Phases of the generation: match, files, report. Returns the exit code.
int generate(const motion::GroundMotionConfig& cfg,
             const std::filesystem::path& out)
{
  const auto start = std::chrono::steady_clock::now();
  const motion::ArtificialMotion m =
      motion::generate_motion(cfg.targets, cfg.generation);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  motion::write_generated(out, cfg, m);
  for (std::size_t i = 0; i < m.components.size(); ++i)
  {
    const auto& c = m.components[i];
    std::printf("%-2s PGA %.3f g, Sa / target within %+.1f%% (worst at "
                "%.3f s), %d iterations%s\n",
                motion::component_names()[i].c_str(),
                c.measures.pga / motion::standard_gravity,
                100 * (c.worst_ratio - 1), c.worst_period, c.iterations,
                c.accepted ? "" : "  NOT WITHIN THE TOLERANCE");
  }
  std::printf("correlations %.3f %.3f %.3f; generated in %.2f s\n",
              m.correlations[0], m.correlations[1], m.correlations[2], seconds);
  if (!m.accepted)
  {
    std::fprintf(stderr,
                 "ground_motion: error: the records do not meet the "
                 "acceptance (summary.json); try another generate.seed or a "
                 "longer generate.duration\n");
    return 4;
  }
  return 0;
}

void plot(const std::filesystem::path& out)
{
  const std::string cmd =
      std::string(DAMSEIS_PYTHON) + " " + DAMSEIS_SOURCE_DIR +
      "/scripts/plot_ground_motion.py \"" + out.string() + "\"";
  if (std::system(cmd.c_str()) != 0)
    std::fprintf(stderr, "ground_motion: warning: plotting failed: %s\n",
                 cmd.c_str());
}

/// The phases of the task.
int run(const input::Case&, const motion::GroundMotionConfig& cfg,
        const std::filesystem::path& out)
{
  int status = 0;
  if (cfg.generate)
    status = generate(cfg, out);
  else
  {
    motion::write_record_spectra(out, cfg);
    std::printf("spectra of %zu records at %zu periods -> %s\n",
                cfg.records.size(), cfg.periods.size(),
                (out / "spectra.csv").c_str());
  }
  if (cfg.plots)
    plot(out);
  return status;
}
} // namespace

int main(int argc, char** argv)
{
  return results::core_demo_main<motion::GroundMotionConfig>(
      argc, argv, "ground_motion",
      DAMSEIS_SOURCE_DIR "/demos/ground_motion/ground_motion.toml",
      motion::ground_motion_schema(), motion::read_ground_motion_config, run);
}
