// Single material point of the rate-dependent HTC concrete model along a
// prescribed strain/stress path; writes a CSV (plot it with
// scripts/plot_material_point.py).
//   build/bin/material_point [--case FILE] [--out DIR] [--set key=value ...]
// With no arguments it runs demos/material_point/material_point.toml.
#include <cstdio>
#include <damseis/case/command_line.h>
#include <damseis/material/material_point_case.h>
#include <filesystem>
#include <fstream>

int main(int argc, char** argv)
{
  using namespace damseis;
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
    const material::HtcConcrete model(cfg.material);
    const auto result = material::run_path(model, cfg.segments);
    std::filesystem::create_directories(cl->out_dir);
    std::ofstream(cl->out_dir / "case.toml") << c.to_toml();
    const auto csv = cl->out_dir / cfg.csv_name;
    std::ofstream out(csv);
    material::write_csv(out, result);
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
    if (!result.completed)
    {
      std::fprintf(stderr, "material_point: warning: %s\n",
                   result.message.c_str());
      return 1;
    }
  }
  catch (const input::InputError& e)
  {
    std::fprintf(stderr, "material_point: error: %s\n", e.what());
    return 2;
  }
  return 0;
}
