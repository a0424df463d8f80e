// Single material point of the rate-dependent HTC concrete model along a
// prescribed strain/stress path; writes a CSV and its plot
// (scripts/plot_material_point.py) and the effective case. Exit codes: 0
// done, 1 internal error, 2 bad input, 4 a step that could not be solved.
//   build/bin/material_point [--case FILE] [--out DIR] [--set key=value ...]
// With no arguments it runs demos/material_point/material_point.toml.
#include <cstdio>
#include <cstdlib>
#include <damseis/case/command_line.h>
#include <damseis/material/material_point_case.h>
#include <damseis/results/output_folder.h>
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
  std::filesystem::create_directories(out_dir);
  std::ofstream(out_dir / "case_used.toml") << c.to_toml();
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
  const auto start = std::filesystem::file_time_type::clock::now();
  std::optional<std::filesystem::path> folder;
  int status = 0;
  try
  {
    const input::Schema schema = material::material_point_schema();
    const auto cl = input::parse_command_line(
        argc, argv, "material_point",
        DAMSEIS_SOURCE_DIR "/demos/material_point/material_point.toml", schema);
    if (!cl)
      return 0;
    const auto c = input::Case::load(schema, cl->case_file, cl->overrides);
    const auto cfg = material::read_material_point_config(c);
    results::check_output_folder(cl->out_dir);
    const std::string line = results::prepare_output_folder(
        cl->out_dir, results::parse_overwrite(c.string("output.overwrite")));
    if (!line.empty())
      std::printf("%s\n", line.c_str());
    folder = cl->out_dir;
    if (c.keys_in_file() == 0)
      std::printf("warning: %s gives no keys: every value is a default or a "
                  "--set override\n",
                  c.file().c_str());
    status = run(c, cfg, cl->out_dir);
  }
  catch (const input::InputError& e)
  {
    std::fprintf(stderr, "material_point: error: %s\n", e.what());
    status = 2;
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "material_point: internal error: %s\n", e.what());
    status = 1;
  }
  if (folder)
    results::write_manifest(*folder, start, false);
  return status;
}
