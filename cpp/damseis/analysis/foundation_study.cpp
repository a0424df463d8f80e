#include "foundation_study.h"
#include <damseis/results/progress.h>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace damseis::analysis
{
namespace
{
/// The interaction models' folders and CSV names, table groups and titles.
struct ModelName
{
  const char* key;
  const char* group;
  const char* title;
};
ModelName model_name(FoundationBoundary b)
{
  switch (b)
  {
  case FoundationBoundary::viscous_spring:
    return {"viscous_spring", "A",
            "dam-foundation interaction (rock with mass, viscous-spring "
            "boundary, vertically incident waves)"};
  case FoundationBoundary::transmitting:
    return {"mtf", "A'",
            "dam-foundation interaction (rock with mass, Liao's multi-"
            "transmitting boundary, vertically incident waves)"};
  default:
    return {"massless", "B", "massless foundation"};
  }
}

struct Row
{
  std::string label;       ///< the column's title ("E_f/E_d = 0.5", "case 4")
  std::string key;         ///< the CSV's first column
  nlohmann::json massless; ///< null for extra cases
  /// Per interaction model (as run_foundation_study's `models`; null
  /// where not run).
  std::vector<nlohmann::json> interaction;
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

void write_csv(const std::vector<Row>& rows,
               const std::vector<FoundationBoundary>& models,
               const std::filesystem::path& file)
{
  std::ofstream csv(file);
  csv << "case,foundation,max_tension_mpa,max_compression_mpa,"
         "max_tension_away_mpa,max_compression_away_mpa,crest_cm,"
         "system_f1_hz\n";
  for (const Row& r : rows)
  {
    std::vector<std::pair<const char*, const nlohmann::json*>> runs;
    for (std::size_t m = 0; m < models.size(); ++m)
      runs.emplace_back(model_name(models[m]).key, &r.interaction[m]);
    runs.emplace_back("massless", &r.massless);
    for (const auto& [name, s] : runs)
    {
      if (s->is_null())
        continue;
      csv << r.key << "," << name << ","
          << value(*s, "max_principal_tension_mpa") << ","
          << value(*s, "max_principal_compression_mpa") << ","
          << away(*s, "max_principal_tension_mpa") << ","
          << away(*s, "max_principal_compression_mpa") << ","
          << 100.0 * std::abs(value(*s, "crest_displacement_max_m")) << ","
          << (*s)["frequencies_hz"][0].get<double>() << "\n";
    }
  }
}

void write_markdown(const std::vector<Row>& rows,
                    const std::vector<FoundationBoundary>& models,
                    const std::filesystem::path& file)
{
  std::ofstream md(file);
  const nlohmann::json& first = rows.front().interaction.front();
  const double radius = first["away_from_singular_points"]["radius_m"];
  md << "Stress response of the dam (MPa; " +
            first["stress"].get<std::string>() +
            " stresses; compression as a magnitude).";
  for (FoundationBoundary b : models)
    md << " " << model_name(b).group << ": " << model_name(b).title << ";";
  md << " B: massless foundation.\n\n| | |";
  for (const Row& r : rows)
    md << " " << r.label << " |";
  md << "\n|---|---|";
  for (std::size_t i = 0; i < rows.size(); ++i)
    md << "---|";
  md << "\n" << std::fixed << std::setprecision(2);
  // model: index into `models`, or -1 for the massless runs.
  auto line =
      [&](const char* group, const std::string& label, int model, auto get)
  {
    md << "| " << group << " | " << label << " |";
    for (const Row& r : rows)
    {
      const nlohmann::json& s = model < 0 ? r.massless : r.interaction[model];
      if (s.is_null())
        md << " - |";
      else
        md << " " << get(s) << " |";
    }
    md << "\n";
  };
  std::ostringstream far;
  far << " > " << radius << " m from corners";
  for (int m = 0; m <= static_cast<int>(models.size()); ++m)
  {
    const int model = m < static_cast<int>(models.size()) ? m : -1;
    const char* g = model < 0 ? "B" : model_name(models[model]).group;
    line(g, "max. ten. stress", model,
         [](const nlohmann::json& s)
         { return value(s, "max_principal_tension_mpa"); });
    line(g, "max. comp. stress", model,
         [](const nlohmann::json& s)
         { return -value(s, "max_principal_compression_mpa"); });
    line(g, "max. ten." + far.str(), model,
         [](const nlohmann::json& s)
         { return away(s, "max_principal_tension_mpa"); });
    line(g, "max. comp." + far.str(), model,
         [](const nlohmann::json& s)
         { return -away(s, "max_principal_compression_mpa"); });
    line(g, "crest displacement (cm)", model,
         [](const nlohmann::json& s)
         { return 100.0 * std::abs(value(s, "crest_displacement_max_m")); });
  }
  md << "\nThe interaction runs use the Rayleigh damping of the massless "
        "runs (the same two frequencies; the extra cases that of E_f/E_d = "
        "1, or the first).";
  for (std::size_t m = 0; m < models.size(); ++m)
  {
    md << " Ratio " << model_name(models[m]).group
       << "/B of the stresses away from the corners (tension, "
          "compression):";
    for (const Row& r : rows)
    {
      if (r.massless.is_null() || r.interaction[m].is_null())
        continue;
      md << " " << r.label << ": "
         << away(r.interaction[m], "max_principal_tension_mpa") /
                away(r.massless, "max_principal_tension_mpa")
         << ", "
         << away(r.interaction[m], "max_principal_compression_mpa") /
                away(r.massless, "max_principal_compression_mpa")
         << ";";
    }
  }
  md << "\n";
}
} // namespace

nlohmann::json
run_foundation_study(MPI_Comm comm, const std::vector<double>& ratios,
                     const std::filesystem::path& out_dir,
                     const std::string& table, const FoundationRun& run,
                     const std::vector<ExtraCase>& extra,
                     const std::vector<FoundationBoundary>& models)
{
  std::vector<Row> rows;
  std::vector<double> reference_damping;
  for (double ratio : ratios)
  {
    const std::string name = ratio_name(ratio).substr(6);
    Row row{"E_f/E_d = " + name, name, {}, {}};
    const std::filesystem::path dir = out_dir / ratio_name(ratio);
    results::print(comm, "== E_f / E_d = " + name + ": massless foundation ==");
    row.massless = run(ratio, FoundationBoundary::fixed, {}, dir / "massless");
    const std::vector<double> damping = {
        row.massless["damping"]["f1_hz"].get<double>(),
        row.massless["damping"]["f2_hz"].get<double>()};
    if (reference_damping.empty() || ratio == 1.0)
      reference_damping = damping;
    for (FoundationBoundary b : models)
    {
      results::print(comm, "== E_f / E_d = " + name + ": " + model_name(b).key +
                               " boundary ==");
      row.interaction.push_back(
          run(ratio, b, damping, dir / model_name(b).key));
    }
    rows.push_back(std::move(row));
  }
  for (const ExtraCase& e : extra)
  {
    results::print(comm, "== " + e.label + " ==");
    Row row{e.label, e.folder, nullptr, {}};
    row.interaction.resize(models.size());
    row.interaction.front() = e.run(reference_damping, out_dir / e.folder);
    rows.push_back(std::move(row));
  }
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0)
  {
    write_csv(rows, models, out_dir / (table + ".csv"));
    write_markdown(rows, models, out_dir / (table + ".md"));
  }
  return rows.back().interaction.front();
}

nlohmann::json run_table6_study(MPI_Comm comm, const GravityDamConfig& cfg,
                                const std::filesystem::path& out_dir,
                                const std::string& case_text,
                                const GravityDamRun& analyse)
{
  const double E_d = cfg.concrete_model.params.E;
  auto seismic = [&](GravityDamConfig c, const std::vector<double>& damping)
  {
    c.table6_ratios.clear();
    c.seismic.stress_total = false; // Table 6: seismic stresses
    if (!damping.empty())
      c.seismic.damping_frequencies_hz = damping;
    return c;
  };
  std::vector<ExtraCase> extra;
  if (cfg.table6_inhomogeneous)
  {
    // The paper's cases 4 and 5 (its Fig. 28 is not in the text: assumed
    // the split under the middle of the base, and the interface at half
    // the block's depth): E_1 = 0.5 E_d and E_2 = E_d side by side; E_3 =
    // 0.5 E_d over E_4 = E_d.
    using Split = geometry::GravityDamSection::Split;
    for (auto [label, folder, split] :
         {std::tuple{"case 4: 0.5 E_d beside E_d", "case_4",
                     Split::side_by_side},
          std::tuple{"case 5: 0.5 E_d over E_d", "case_5", Split::layers}})
    {
      const Split how = split;
      extra.push_back(
          {label, folder,
           [&, how](const std::vector<double>& damping,
                    const std::filesystem::path& dir)
           {
             GravityDamConfig c = cfg;
             c.section.foundation_split = how;
             c.section.band_layers = 0; // (a split block has no band)
             c.section.split_depth = 0.5 * c.section.foundation_depth;
             c.rock_E2 = E_d;
             c = seismic(with_foundation(c, 0.5 * E_d,
                                         FoundationBoundary::viscous_spring),
                         damping);
             return analyse(comm, c, {dir, case_text});
           }});
    }
  }
  // With boundary = mtf the multi-transmitting boundary runs beside the
  // viscous-spring one (on the same mesh, with its band).
  std::vector<FoundationBoundary> models = {FoundationBoundary::viscous_spring};
  if (cfg.boundary == FoundationBoundary::transmitting)
    models.push_back(FoundationBoundary::transmitting);
  return run_foundation_study(
      comm, cfg.table6_ratios, out_dir, "table6",
      [&](double ratio, FoundationBoundary boundary,
          const std::vector<double>& damping_hz,
          const std::filesystem::path& dir)
      {
        return analyse(
            comm,
            seismic(with_foundation(cfg, ratio * E_d, boundary), damping_hz),
            {dir, case_text});
      },
      extra, models);
}
} // namespace damseis::analysis
