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

void write_table(const std::vector<Row>& rows, const std::filesystem::path& dir,
                 const std::string& table)
{
  std::ofstream csv(dir / (table + ".csv")), md(dir / (table + ".md"));
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
  md << "Stress response of the dam (MPa; " +
            rows.front().massless["stress"].get<std::string>() +
            " stresses; compression as a magnitude), as the paper's Table "
            "6. A: dam-foundation interaction (rock with mass, "
            "viscous-spring boundary, vertically incident waves); B: "
            "massless foundation.\n\n| | |";
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

nlohmann::json run_foundation_study(MPI_Comm comm,
                                    const std::vector<double>& ratios,
                                    const std::filesystem::path& out_dir,
                                    const std::string& table,
                                    const FoundationRun& run)
{
  std::vector<Row> rows;
  for (double ratio : ratios)
  {
    Row row{ratio, {}, {}};
    const std::filesystem::path dir = out_dir / ratio_name(ratio);
    const std::string name = ratio_name(ratio).substr(6);
    results::print(comm, "== E_f / E_d = " + name + ": massless foundation ==");
    row.massless = run(ratio, false, {}, dir / "massless");
    const std::vector<double> damping = {
        row.massless["damping"]["f1_hz"].get<double>(),
        row.massless["damping"]["f2_hz"].get<double>()};
    results::print(comm,
                   "== E_f / E_d = " + name + ": viscous-spring boundary ==");
    row.interaction = run(ratio, true, damping, dir / "viscous_spring");
    rows.push_back(std::move(row));
  }
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0)
    write_table(rows, out_dir, table);
  return rows.back().interaction;
}

nlohmann::json run_table6_study(MPI_Comm comm, const GravityDamConfig& cfg,
                                const std::filesystem::path& out_dir,
                                const std::string& case_text,
                                const GravityDamRun& analyse)
{
  const double E_d = cfg.concrete_model.params.E;
  return run_foundation_study(
      comm, cfg.table6_ratios, out_dir, "table6",
      [&](double ratio, bool viscous_spring,
          const std::vector<double>& damping_hz,
          const std::filesystem::path& dir)
      {
        GravityDamConfig c = with_foundation(cfg, ratio * E_d, viscous_spring);
        c.table6_ratios.clear();
        c.seismic.stress_total = false; // Table 6: seismic stresses
        if (!damping_hz.empty())
          c.seismic.damping_frequencies_hz = damping_hz;
        return analyse(comm, c, {dir, case_text});
      });
}
} // namespace damseis::analysis
