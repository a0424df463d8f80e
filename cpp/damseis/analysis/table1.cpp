#include "table1.h"
#include <fstream>
#include <iomanip>

namespace damseis::analysis
{
namespace
{
/// The largest compression (most negative) and tension away from the
/// singular points: of the dam, or over the faces.
std::pair<double, double> away_extremes(const nlohmann::json& s, bool faces)
{
  const std::string C = "max_principal_compression_mpa",
                    T = "max_principal_tension_mpa";
  if (!faces)
  {
    const auto& away = s["away_from_singular_points"];
    return {away[C]["value"], away[T]["value"]};
  }
  double c = 0.0, t = 0.0;
  for (const auto& [name, f] : s["faces"].items())
  {
    const auto& away = f["away_from_singular_points"];
    c = std::min(c, away[C]["value"].get<double>());
    t = std::max(t, away[T]["value"].get<double>());
  }
  return {c, t};
}
} // namespace

void write_table1(const std::vector<Table1Run>& runs,
                  const std::filesystem::path& out_dir, bool faces)
{
  std::ofstream csv(out_dir / "table1.csv"), md(out_dir / "table1.md");
  const bool levels = !std::isnan(runs.front().level_m);
  const double radius =
      runs.front().summary["away_from_singular_points"]["radius_m"];
  const std::string away = faces ? "_faces_away_mpa" : "_away_mpa";
  csv << (levels ? "reservoir_level_m," : "")
      << "model,max_compression_mpa,max_tension_mpa,max_compression" << away
      << ",max_tension" << away
      << ","
         "crest_displacement_cm,max_kappa_t,max_strain_rate_per_s,"
         "newton_iterations_per_step,seconds_per_step,material_integration\n";
  md << std::setprecision(3) << (levels ? "| Reservoir level (m) " : "")
     << "| Model | Compression (MPa) | Tension (MPa) | Compression"
     << (faces ? " on the faces" : "") << " > " << radius
     << " m from corners (MPa) | Tension" << (faces ? " on the faces" : "")
     << " > " << radius
     << " m from corners (MPa) | Crest displacement (cm) | max kappa_t | "
        "max strain rate (1/s) | Newton it./step | s/step | integration |\n"
     << (levels ? "|---" : "")
     << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& [name, level, s] : runs)
  {
    const double c = s["max_principal_compression_mpa"]["value"];
    const double t = s["max_principal_tension_mpa"]["value"];
    const auto [ca, ta] = away_extremes(s, faces);
    const double u =
        s["crest_displacement_max_m"]["value"].get<double>() * 100.0;
    const double kt = s["max_kappa_t"]["value"];
    const double rate = s["max_strain_rate_per_s"]["value"];
    const double it = s["newton"]["iterations_per_step"];
    const double sps = s["seconds_per_step"];
    // The elastic model has nothing to integrate.
    const std::string integ =
        name == "elastic"
            ? "-"
            : s["concrete"]["material_integration"].get<std::string>();
    if (levels)
      csv << level << ",";
    csv << name << "," << c << "," << t << "," << ca << "," << ta << "," << u
        << "," << kt << "," << rate << "," << it << "," << sps << "," << integ
        << "\n";
    md << std::fixed;
    if (levels)
      md << "| " << std::setprecision(1) << level << " ";
    md << "| " << name << " | " << std::setprecision(2) << c << " | " << t
       << " | " << ca << " | " << ta << " | " << u << " | " << std::scientific
       << std::setprecision(2) << kt << " | " << rate << std::fixed << " | "
       << std::setprecision(2) << it << " | " << std::setprecision(4) << sps
       << " | " << integ << " |\n";
  }
}
} // namespace damseis::analysis
