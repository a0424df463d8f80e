#include "foundation_study.h"
#include <damseis/results/progress.h>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace damseis::analysis
{
namespace
{
struct Row
{
  double ratio = 0.0;
  nlohmann::json massless, interaction;
};

double value(const nlohmann::json& s, const char* key)
{
  return s[key]["value"].get<double>();
}

double away(const nlohmann::json& s, const char* key)
{
  return s["away_from_singular_points"][key]["value"].get<double>();
}

std::string ratio_name(double r)
{
  std::ostringstream os;
  os << "ratio_" << r;
  return os.str();
}

void write_table6(const std::vector<Row>& rows,
                  const std::filesystem::path& dir)
{
  std::ofstream csv(dir / "table6.csv"), md(dir / "table6.md");
  csv << "ef_over_ed,foundation,max_tension_mpa,max_compression_mpa,"
         "max_tension_away_mpa,max_compression_away_mpa,crest_cm,f1_hz\n";
  for (const Row& r : rows)
    for (const auto& [name, s] : {std::pair{"viscous_spring", &r.interaction},
                                  std::pair{"massless", &r.massless}})
    {
      csv << r.ratio << "," << name << ","
          << value(*s, "max_principal_tension_mpa") << ","
          << value(*s, "max_principal_compression_mpa") << ","
          << away(*s, "max_principal_tension_mpa") << ","
          << away(*s, "max_principal_compression_mpa") << ","
          << 100.0 * std::abs(value(*s, "crest_displacement_max_m")) << ","
          << (*s)["frequencies_hz"][0].get<double>() << "\n";
    }
  const double radius =
      rows.front().massless["away_from_singular_points"]["radius_m"];
  md << "Seismic stress response of the section (MPa), as the paper's Table "
        "6. A: dam-foundation interaction (block with mass, viscous-spring "
        "boundary, vertically incident waves); B: massless foundation. "
        "Compression as a magnitude.\n\n| | |";
  for (const Row& r : rows)
    md << " E_f/E_d = " << r.ratio << " |";
  md << "\n|---|---|";
  for (std::size_t i = 0; i < rows.size(); ++i)
    md << "---|";
  md << "\n" << std::fixed << std::setprecision(2);
  auto line =
      [&](const char* group, const char* label, bool interaction, auto get)
  {
    md << "| " << group << " | " << label << " |";
    for (const Row& r : rows)
      md << " " << get(interaction ? r.interaction : r.massless) << " |";
    md << "\n";
  };
  for (bool a : {true, false})
  {
    const char* g = a ? "A" : "B";
    line(g, "max. ten. stress", a,
         [](const nlohmann::json& s)
         { return value(s, "max_principal_tension_mpa"); });
    line(g, "max. comp. stress", a,
         [](const nlohmann::json& s)
         { return -value(s, "max_principal_compression_mpa"); });
    std::ostringstream t, c;
    t << "max. ten. > " << radius << " m from corners";
    c << "max. comp. > " << radius << " m from corners";
    line(g, t.str().c_str(), a,
         [](const nlohmann::json& s)
         { return away(s, "max_principal_tension_mpa"); });
    line(g, c.str().c_str(), a,
         [](const nlohmann::json& s)
         { return -away(s, "max_principal_compression_mpa"); });
    line(g, "crest displacement (cm)", a,
         [](const nlohmann::json& s)
         { return 100.0 * std::abs(value(s, "crest_displacement_max_m")); });
  }
  md << "\nThe interaction runs use the Rayleigh damping of the massless "
        "runs (the same two frequencies). Ratio A/B of the stresses away "
        "from the corners (tension, compression):";
  for (const Row& r : rows)
    md << " " << r.ratio << ": "
       << away(r.interaction, "max_principal_tension_mpa") /
              away(r.massless, "max_principal_tension_mpa")
       << ", "
       << away(r.interaction, "max_principal_compression_mpa") /
              away(r.massless, "max_principal_compression_mpa")
       << ";";
  md << "\n";
}
} // namespace

nlohmann::json run_foundation_study(MPI_Comm comm, const GravityDamConfig& cfg,
                                    const std::filesystem::path& out_dir,
                                    const std::string& case_text,
                                    const GravityDamRun& analyse)
{
  std::vector<Row> rows;
  const double E_d = cfg.concrete_model.params.E;
  for (double ratio : cfg.table6_ratios)
  {
    Row row{ratio, {}, {}};
    const std::filesystem::path dir = out_dir / ratio_name(ratio);
    GravityDamConfig massless = with_foundation(cfg, ratio * E_d, false);
    massless.table6_ratios.clear();
    massless.seismic.stress_total = false; // Table 6: seismic stresses
    const std::string name = ratio_name(ratio).substr(6);
    results::print(comm, "== E_f / E_d = " + name + ": massless foundation ==");
    row.massless = analyse(comm, massless, {dir / "massless", case_text});
    GravityDamConfig wave = with_foundation(massless, ratio * E_d, true);
    wave.seismic.damping_frequencies_hz = {
        row.massless["damping"]["f1_hz"].get<double>(),
        row.massless["damping"]["f2_hz"].get<double>()};
    results::print(comm,
                   "== E_f / E_d = " + name + ": viscous-spring boundary ==");
    row.interaction = analyse(comm, wave, {dir / "viscous_spring", case_text});
    rows.push_back(std::move(row));
  }
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0)
    write_table6(rows, out_dir);
  return rows.back().interaction;
}
} // namespace damseis::analysis
