#include "targets.h"
#include "mutator.h"
#include <cmath>
#include <damseis/analysis/arch_dam_case.h>
#include <damseis/analysis/dam_model_case.h>
#include <damseis/analysis/gravity_dam_case.h>
#include <damseis/checkpoint/checkpoint_file.h>
#include <damseis/material/material_point_case.h>
#include <damseis/motion/ground_motion_case.h>
#include <damseis/results/progress.h>
#include <fstream>
#include <set>
#include <sstream>

namespace damseis::fuzz
{
namespace fs = std::filesystem;
namespace
{
std::string contents(const fs::path& file)
{
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return std::move(bytes).str();
}

std::vector<std::string> files_in(const fs::path& dir, const std::string& ext,
                                  const std::string& prefix = "")
{
  std::vector<std::string> out;
  std::set<fs::path> sorted;
  for (const auto& e : fs::directory_iterator(dir))
  {
    const auto name = e.path().filename().string();
    if (e.path().extension() == ext && name.starts_with(prefix))
      sorted.insert(e.path());
  }
  for (const auto& p : sorted)
    out.push_back(contents(p));
  return out;
}

void write(const fs::path& file, std::string_view bytes)
{
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

/// The promise of every input error: one line, not empty, no control
/// characters (raw bytes of a binary file are not echoed).
void check_message(const std::string& what)
{
  if (what.empty())
    throw Finding("empty error message");
  for (char ch : what)
  {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7f)
      throw Finding("error message with control character " +
                    std::to_string(c) + ": " + what.substr(0, 300));
  }
  if (what.size() > 2000)
    throw Finding("error message of " + std::to_string(what.size()) +
                  " characters: " + what.substr(0, 300) + "...");
}

void check_finite(double v, const std::string& what)
{
  if (!std::isfinite(v))
    throw Finding("accepted a non-finite " + what);
}

template <typename Range>
void check_all_finite(const Range& values, const std::string& what)
{
  for (double v : values)
    check_finite(v, what);
}

/// Runs `read` on the input; an InputError is a clean rejection, anything
/// else escaping is a finding.
template <typename Read>
Outcome guarded(Read&& read)
{
  try
  {
    read();
    return Outcome::accepted;
  }
  catch (const input::InputError& e)
  {
    check_message(e.what());
    return Outcome::rejected;
  }
  catch (const Finding&)
  {
    throw;
  }
  catch (const std::exception& e)
  {
    throw Finding(std::string("uncaught ") + typeid(e).name() + ": " +
                  std::string(e.what()).substr(0, 300));
  }
  catch (...)
  {
    throw Finding("uncaught non-standard exception");
  }
}

/// Keys and tables of a schema for the mutator.
void describe(const input::Schema& schema, Target& t)
{
  std::set<std::string> leaves, tables;
  for (const auto& key : schema.keys())
  {
    const auto dot = key.path.rfind('.');
    leaves.insert(key.path.substr(dot + 1));
    if (dot != std::string::npos)
      tables.insert("\n[" + key.path.substr(0, dot) + "]\n");
  }
  t.keys.assign(leaves.begin(), leaves.end());
  t.dictionary.assign(tables.begin(), tables.end());
  for (const auto& leaf : leaves)
    t.dictionary.push_back("\n" + leaf + " = ");
  for (const auto& literal : extreme_literals())
    t.dictionary.push_back(literal);
}

void check_motion(const analysis::SeismicSettings& s)
{
  for (const auto& m : s.motion)
  {
    check_all_finite(m.acceleration, "ground acceleration");
    check_finite(m.peak_g, "peak_g");
  }
  check_finite(s.scheme.dt, "time step");
  if (s.steps < 1)
    throw Finding("accepted a case with " + std::to_string(s.steps) + " steps");
}

/// The case file of a demo, read and cross-checked as the demo does.
template <typename Config>
Target case_target(std::string name, const input::Schema& schema,
                   std::vector<std::string> seeds,
                   Config (*read)(const input::Case&), const fs::path& scratch,
                   std::function<void(const Config&)> check)
{
  Target t;
  t.name = std::move(name);
  t.help = "a case file of the demo, read and checked (Case::load and the "
           "demo's config reader, records loaded)";
  t.seeds = std::move(seeds);
  describe(schema, t);
  const fs::path file = scratch / "cases" / "case" / "case.toml";
  t.run = [schema, read, check, file](std::string_view input, const fs::path&)
  {
    write(file, input);
    return guarded(
        [&]
        {
          const auto c = input::Case::load(schema, file);
          check(read(c));
        });
  };
  return t;
}

/// A ground-motion record given to the koyna case (the demo's whole record
/// path: reading, scaling, resampling, the step count), with the record's
/// own length (time.duration = 0) or 4 s, scaled to 0.3 g or unscaled.
Target record_target(bool at2, const fs::path& source_dir,
                     const fs::path& scratch)
{
  Target t;
  t.name = at2 ? "record_at2" : "record_columns";
  t.help = "a ground-motion record file read by the koyna case";
  const auto tests = source_dir / "tests" / "data";
  if (at2)
  {
    t.seeds = files_in(source_dir / "data" / "records", ".at2");
    for (auto& s : files_in(tests, ".at2", "record_"))
      t.seeds.push_back(std::move(s));
    t.dictionary = {"NPTS=",
                    "DT=",
                    " SEC",
                    "NPTS, DT",
                    "\n",
                    "D+02",
                    "E-03",
                    "-0.00128-0.00133",
                    "NPTS=  1559, DT= .02000 SEC\n"};
  }
  else
  {
    t.seeds = files_in(tests, ".txt", "record_");
    t.dictionary = {"# t a\n", "% x\n", ",", "\n", "0.0 0.1\n0.01 0.2\n"};
  }
  for (const auto& literal : extreme_literals())
    t.dictionary.push_back(literal);
  const auto dir = scratch / "cases" / "record";
  const auto record = dir / (at2 ? "record.at2" : "record.txt");
  auto schema = std::make_shared<input::Schema>(analysis::gravity_dam_schema());
  t.run = [schema, dir, record](std::string_view input, const fs::path&)
  {
    write(record, input);
    // The variant follows from the input, so a saved input reproduces.
    const std::size_t h = std::hash<std::string_view>{}(input);
    std::ostringstream text;
    text << "[mesh]\nsize = 8.0\n[time]\ndt = 0.01\nduration = "
         << (h % 2 ? "0.0" : "4.0") << "\n[motion.horizontal]\nrecord = \""
         << record.filename().string()
         << "\"\nunits = \"g\"\ndt = 0.02\npeak_g = "
         << (h / 2 % 2 ? "0.0" : "0.3") << "\n";
    write(dir / "case.toml", text.str());
    return guarded(
        [&]
        {
          const auto c = input::Case::load(*schema, dir / "case.toml");
          check_motion(analysis::read_gravity_dam_config(c).seismic);
        });
  };
  return t;
}

checkpoint::CheckpointData sample_checkpoint(int step, std::size_t n)
{
  checkpoint::CheckpointData d;
  d.step = step;
  for (const char* name : {"u", "v", "a", "state"})
  {
    auto& values = d.arrays[name];
    for (std::size_t i = 0; i < n; ++i)
      values.push_back(std::sin(1.0 + static_cast<double>(i)) * 1e-3);
  }
  d.arrays["empty"] = {};
  return d;
}

constexpr std::uint64_t fuzz_print = 0x5eed5eed5eedull;

Target checkpoint_rank_target()
{
  Target t;
  t.name = "checkpoint_rank";
  t.help = "a rank file of a checkpoint (checkpoint::decode_rank)";
  t.binary = true;
  for (std::size_t n : {0u, 1u, 3u, 40u})
    t.seeds.push_back(
        checkpoint::encode_rank(sample_checkpoint(7, n), fuzz_print));
  t.run = [](std::string_view input, const fs::path&)
  {
    return guarded(
        [&]
        {
          checkpoint::CheckpointData d;
          const auto status = checkpoint::decode_rank(input, fuzz_print, 7, d);
          if (status != checkpoint::RankFile::ok)
            throw input::InputError("refused");
          std::size_t bytes = 32;
          for (const auto& [name, values] : d.arrays)
          {
            check_all_finite(values, "checkpoint value");
            bytes += 16 + name.size() + 8 * values.size();
          }
          if (bytes != input.size())
            throw Finding("decoded " + std::to_string(bytes) + " of " +
                          std::to_string(input.size()) + " bytes");
        });
  };
  return t;
}

Target checkpoint_meta_target()
{
  Target t;
  t.name = "checkpoint_meta";
  t.help = "a checkpoint.json (checkpoint::decode_meta)";
  t.seeds = {checkpoint::encode_meta({7, 1}), checkpoint::encode_meta({0, 2}),
             "{\"ranks\": 4, \"step\": 120}\n"};
  t.keys = {"\"step\":", "\"ranks\":"};
  t.dictionary = {"{", "}", "[",    "]",           "\"step\"", "\"ranks\"",
                  ":", ",", "null", "\"\\u0000\"", "1e999"};
  t.run = [](std::string_view input, const fs::path&)
  {
    return guarded(
        [&]
        {
          const auto m = checkpoint::decode_meta(input, "checkpoint.json");
          if (m.step < 0 || m.step > checkpoint::max_step || m.ranks < 1 ||
              m.ranks > checkpoint::max_ranks)
            throw Finding("accepted step " + std::to_string(m.step) +
                          ", ranks " + std::to_string(m.ranks));
        });
  };
  return t;
}
} // namespace

std::vector<Target> all_targets(const fs::path& source_dir,
                                const fs::path& scratch)
{
  fs::create_directories(scratch / "cases" / "case");
  fs::create_directories(scratch / "cases" / "record");
  std::error_code ec;
  fs::create_directory_symlink(source_dir / "data", scratch / "data", ec);

  const auto demos = source_dir / "demos";
  auto gravity_seeds = files_in(demos / "koyna", ".toml");
  for (auto& s : files_in(demos / "rcc_gravity", ".toml"))
    gravity_seeds.push_back(std::move(s));
  // arch_dam.toml (not section1_xiluodu.toml: its generated motions take
  // 0.5-1.5 s per accepted input; generation is tested in core_tests).
  auto arch_seeds = files_in(demos / "arch_dam", ".toml", "arch_dam");
  for (auto& s : files_in(demos / "arch_dam" / "presets", ".toml"))
    arch_seeds.push_back(std::move(s));

  std::vector<Target> targets;
  targets.push_back(case_target<analysis::GravityDamConfig>(
      "case_gravity", analysis::gravity_dam_schema(), gravity_seeds,
      analysis::read_gravity_dam_config, scratch,
      [](const analysis::GravityDamConfig& g) { check_motion(g.seismic); }));
  targets.push_back(case_target<analysis::ArchDamConfig>(
      "case_arch", analysis::arch_dam_schema(), arch_seeds,
      analysis::read_arch_dam_config, scratch,
      [](const analysis::ArchDamConfig& a) { check_motion(a.seismic); }));
  // dam_model: the case and the mesh it names (the examples' meshes are
  // reachable from the scratch case as from the demo's folder).
  fs::create_directory_symlink(demos / "dam_model" / "meshes",
                               scratch / "cases" / "case" / "meshes", ec);
  targets.push_back(case_target<analysis::DamModelConfig>(
      "case_dam_model", analysis::dam_model_schema(),
      files_in(demos / "dam_model", ".toml"), analysis::read_dam_model_config,
      scratch,
      [](const analysis::DamModelConfig& d)
      {
        check_motion(d.seismic);
        for (const auto& r : d.regions)
          check_finite(r.material.E, "region E");
        check_all_finite(d.traction_history, "traction history");
      }));
  targets.push_back(case_target<material::MaterialPointConfig>(
      "case_material_point", material::material_point_schema(),
      files_in(demos / "material_point", ".toml"),
      material::read_material_point_config, scratch,
      [](const material::MaterialPointConfig& m)
      {
        // Run short paths whole: every point finite (a step that cannot be
        // solved stops the path with a message, which is allowed).
        long steps = 0;
        for (const auto& s : m.segments)
          steps += s.steps;
        if (steps > 400)
          return;
        const material::HtcConcrete model(m.material);
        const auto result = material::run_path(model, m.segments);
        for (const auto& p : result.points)
        {
          check_all_finite(p.state.stress, "stress");
          check_all_finite(p.strain, "strain");
        }
      }));
  targets.push_back(case_target<motion::GroundMotionConfig>(
      "case_ground_motion", motion::ground_motion_schema(),
      files_in(demos / "ground_motion", ".toml"),
      motion::read_ground_motion_config, scratch,
      [](const motion::GroundMotionConfig& g)
      {
        // The targets at the control periods, and the records read.
        for (const auto& t : g.targets)
          for (double p : g.generation.control_periods)
            check_finite(t(p), "target spectrum");
        for (const auto& r : g.records)
          check_all_finite(r.record.acceleration, "record value");
      }));
  targets.push_back(record_target(true, source_dir, scratch));
  targets.push_back(record_target(false, source_dir, scratch));
  targets.push_back(checkpoint_meta_target());
  targets.push_back(checkpoint_rank_target());
  return targets;
}
} // namespace damseis::fuzz
