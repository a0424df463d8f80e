// The main of the demos that need neither MPI nor DOLFINx (material_point,
// ground_motion): command line, case, config, output folder, the demo's own
// phases, manifest, exit codes (0 done, 1 internal error, 2 bad input, and
// whatever the demo's run returns, e.g. 4). The seismic demos use
// analysis/demo_main.
#pragma once

#include <cstdio>
#include <damseis/input/command_line.h>
#include <damseis/results/output_folder.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <string>

namespace damseis::results
{
/// Runs a core demo: parses the command line, loads and reads the case
/// (`read` throws input::InputError for bad input), checks and prepares
/// the output folder, writes case_used.toml, then returns run(case, config,
/// folder). Every exception ends in one line on stderr.
template <typename Config>
int core_demo_main(int argc, char** argv, const std::string& name,
                   const std::filesystem::path& default_case,
                   const input::Schema& schema,
                   Config (*read)(const input::Case&),
                   const std::function<int(const input::Case&, const Config&,
                                           const std::filesystem::path&)>& run)
{
  const auto start = std::filesystem::file_time_type::clock::now();
  std::optional<std::filesystem::path> folder;
  int status = 0;
  try
  {
    const auto cl =
        input::parse_command_line(argc, argv, name, default_case, schema);
    if (!cl)
      return 0;
    const auto c = input::Case::load(schema, cl->case_file, cl->overrides);
    const Config cfg = read(c);
    check_output_folder(cl->out_dir);
    const std::string line = prepare_output_folder(
        cl->out_dir, parse_overwrite(c.string("output.overwrite")));
    if (!line.empty())
      std::printf("%s\n", line.c_str());
    folder = cl->out_dir;
    if (c.keys_in_file() == 0)
      std::printf("warning: %s gives no keys: every value is a default or a "
                  "--set override\n",
                  c.file().c_str());
    std::filesystem::create_directories(cl->out_dir);
    std::ofstream(cl->out_dir / "case_used.toml") << c.to_toml();
    status = run(c, cfg, cl->out_dir);
  }
  catch (const input::InputError& e)
  {
    std::fprintf(stderr, "%s: error: %s\n", name.c_str(), e.what());
    status = 2;
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "%s: internal error: %s\n", name.c_str(), e.what());
    status = 1;
  }
  if (folder)
    write_manifest(*folder, start, false);
  return status;
}
} // namespace damseis::results
