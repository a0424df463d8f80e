#include "ground_motion_output.h"
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace damseis::motion
{
namespace
{
using nlohmann::json;

std::string zeta_name(double d)
{
  std::ostringstream s;
  s << "zeta_" << d;
  return s.str();
}

json measures_json(const Measures& m)
{
  return {{"pga_m_s2", m.pga},
          {"pga_g", m.pga / standard_gravity},
          {"pgv_m_s", m.pgv},
          {"pgd_m", m.pgd},
          {"final_velocity_m_s", m.final_velocity},
          {"final_displacement_m", m.final_displacement},
          {"arias_intensity_m_s", m.arias},
          {"t5_s", m.t5},
          {"t95_s", m.t95},
          {"significant_duration_5_95_s", m.significant_duration}};
}

/// spectra.csv: period_s, then one column per (series, damping).
void write_spectra_csv(const std::filesystem::path& file,
                       const std::vector<double>& periods,
                       const std::vector<std::string>& names,
                       const std::vector<std::vector<double>>& columns)
{
  std::ofstream out(file);
  out << "period_s";
  for (const auto& n : names)
    out << "," << n;
  out << "\n";
  char cell[32];
  for (std::size_t i = 0; i < periods.size(); ++i)
  {
    std::snprintf(cell, sizeof cell, "%.6g", periods[i]);
    out << cell;
    for (const auto& col : columns)
    {
      std::snprintf(cell, sizeof cell, ",%.8g", col[i]);
      out << cell;
    }
    out << "\n";
  }
  if (!out)
    throw std::runtime_error("cannot write " + file.string());
}

void write_target_csv(const std::filesystem::path& file,
                      const std::vector<double>& periods,
                      const std::vector<DesignSpectrum>& targets)
{
  std::vector<std::vector<double>> cols(2);
  for (double t : periods)
  {
    cols[0].push_back(targets[0](t));
    cols[1].push_back(targets[2](t));
  }
  write_spectra_csv(file, periods, {"horizontal_m_s2", "vertical_m_s2"}, cols);
}

void write_json(const std::filesystem::path& file, const json& j)
{
  std::ofstream out(file);
  out << j.dump(2) << "\n";
  if (!out)
    throw std::runtime_error("cannot write " + file.string());
}
} // namespace

json write_generated(const std::filesystem::path& dir,
                     const GroundMotionConfig& cfg,
                     const ArtificialMotion& motion)
{
  const ArtificialSettings& s = cfg.generation;
  const auto& names = component_names();
  json components = json::array();
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;
  for (std::size_t i = 0; i < motion.components.size(); ++i)
  {
    const ArtificialComponent& c = motion.components[i];
    Record r;
    r.dt = s.dt;
    r.acceleration = c.acceleration;
    r.description = "damseis artificial record " + names[i] + ", seed " +
                    std::to_string(s.seed) + ", target " +
                    cfg.targets[i].describe();
    write_columns(dir / (names[i] + ".txt"), r);
    write_at2(dir / (names[i] + ".at2"), r);
    for (double d : cfg.damping)
    {
      columns.push_back(names[i] + "_" + zeta_name(d));
      values.push_back(
          response_spectrum(c.acceleration, s.dt, s.control_periods, d).psa);
    }
    json entry = measures_json(c.measures);
    entry["name"] = names[i];
    entry["files"] = {names[i] + ".txt", names[i] + ".at2"};
    entry["target"] = cfg.targets[i].describe();
    entry["worst_ratio"] = c.worst_ratio;
    entry["worst_period_s"] = c.worst_period;
    entry["within_tolerance"] = c.accepted;
    entry["iterations"] = c.iterations;
    components.push_back(entry);
  }
  write_spectra_csv(dir / "spectra.csv", s.control_periods, columns, values);
  write_target_csv(dir / "target_spectrum.csv", s.control_periods, cfg.targets);
  json summary = {
      {"task", "generate"},
      {"seed", s.seed},
      {"duration_s", s.duration},
      {"dt_s", s.dt},
      {"envelope",
       {{"rise_s", s.envelope.rise},
        {"strong_end_s", s.envelope.strong_end},
        {"decay_1_s", s.envelope.decay}}},
      {"control_periods",
       {{"count", s.control_periods.size()},
        {"min_s", s.control_periods.front()},
        {"max_s", s.control_periods.back()}}},
      {"tolerance", s.tolerance},
      {"max_correlation", s.max_correlation},
      {"correlations",
       {{"h1_h2", motion.correlations.at(0)},
        {"h1_v", motion.correlations.at(1)},
        {"h2_v", motion.correlations.at(2)}}},
      {"accepted", motion.accepted},
      {"components", components},
      {"method",
       "stationary Gaussian process x envelope, 5 frequency-domain "
       "iterations (SIMQKE), then time-domain wavelets at each period's "
       "peak (Al Atik & Abrahamson 2010); baseline: envelope-shaped "
       "correction to zero final velocity and displacement; PGA by "
       "zero-area pulses"}};
  write_json(dir / "summary.json", summary);
  return summary;
}

json write_record_spectra(const std::filesystem::path& dir,
                          const GroundMotionConfig& cfg)
{
  json records = json::array();
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;
  for (const auto& [name, file, r] : cfg.records)
  {
    for (double d : cfg.damping)
    {
      columns.push_back(name + "_" + zeta_name(d));
      values.push_back(
          response_spectrum(r.acceleration, r.dt, cfg.periods, d).psa);
    }
    json entry = measures_json(measures(r.acceleration, r.dt));
    entry["name"] = name;
    entry["file"] = file.string();
    entry["description"] = r.description;
    entry["dt_s"] = r.dt;
    entry["samples"] = r.acceleration.size();
    records.push_back(entry);
  }
  write_spectra_csv(dir / "spectra.csv", cfg.periods, columns, values);
  json summary = {{"task", "spectrum"}, {"records", records}};
  if (cfg.has_target)
  {
    write_target_csv(dir / "target_spectrum.csv", cfg.periods, cfg.targets);
    summary["target"] = cfg.targets[0].describe();
  }
  write_json(dir / "summary.json", summary);
  return summary;
}
} // namespace damseis::motion
