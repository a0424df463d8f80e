// Single material point of the rate-dependent HTC concrete model along a
// prescribed strain/stress path; writes a CSV and its plot
// (scripts/plot_material_point.py) and the effective case. Exit codes: 0
// done, 1 internal error, 2 bad input, 4 a step that could not be solved.
//   build/bin/material_point [--case FILE] [--out DIR] [--set key=value ...]
// With no arguments it runs demos/material_point/material_point.toml.
#include <cstdio>
#include <cstdlib>
#include <damseis/input/command_line.h>
#include <damseis/material/material_point_case.h>
#include <damseis/results/core_demo.h>
#include <filesystem>
#include <fstream>
#include <optional>

namespace
{
using namespace damseis;

/// Phases of the run: path, files, plot. Returns the exit code.
int run(const input::Case& c, const material::MaterialPointConfig& cfg,
        const std::filesystem::path& out_dir)
{
  const material::HtcConcrete model(cfg.material);
  const auto result = material::run_path(model, cfg.segments);
  const auto csv = out_dir / cfg.csv_name;
  {
    std::ofstream out(csv);
    material::write_csv(out, result);
  }
  double smax = 0, smin = 0;
  for (const auto& p : result.points)
  {
    smax = std::max(smax, p.state.stress[0]);
    smin = std::min(smin, p.state.stress[0]);
  }
  std::printf("material_point: %zu points -> %s\n", result.points.size(),
              csv.c_str());
  std::printf("  sigma11 range [%.4g, %.4g] Pa; ft0_eff = %.4g Pa "
              "(l_ch = %.3g m)\n",
              smin, smax, model.derived().ft0, model.derived().l_ch);
  std::fflush(stdout);
  if (cfg.plots)
  {
    const std::string cmd =
        std::string(DAMSEIS_PYTHON) + " " + DAMSEIS_SOURCE_DIR +
        "/scripts/plot_material_point.py \"" + csv.string() + "\"";
    if (std::system(cmd.c_str()) != 0)
      std::fprintf(stderr, "material_point: warning: plotting failed: %s\n",
                   cmd.c_str());
  }
  if (!result.completed)
  {
    // Like the demos' exit code 4: a step that could not be solved (the
    // points so far are written).
    std::fprintf(stderr,
                 "material_point: error: %s; try a smaller path.strain_step\n",
                 result.message.c_str());
    return 4;
  }
  return 0;
}
} // namespace

int main(int argc, char** argv)
{
  return results::core_demo_main<material::MaterialPointConfig>(
      argc, argv, "material_point",
      DAMSEIS_SOURCE_DIR "/demos/material_point/material_point.toml",
      material::material_point_schema(), material::read_material_point_config,
      run);
}
