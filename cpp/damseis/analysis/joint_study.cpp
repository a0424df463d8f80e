#include "joint_study.h"
#include "linear_seismic.h"
#include <cstdio>
#include <fstream>
#include <map>

namespace damseis::analysis
{
namespace
{
std::string fixed(double v, int digits)
{
  char s[32];
  std::snprintf(s, sizeof s, "%.*f", digits, v);
  return s;
}

std::string case_name(const std::string& set)
{
  return set == "none" ? "0 joints"
                       : std::to_string(set.size()) + " joints (" + set + ")";
}

/// value[label] of `what` (e.g. "opening_upstream") in a run's joint table.
std::map<char, double> per_joint(const nlohmann::json& summary,
                                 const std::string& what)
{
  std::map<char, double> v;
  if (!summary.contains("joints") || !summary["joints"].contains("table"))
    return v;
  for (const auto& row : summary["joints"]["table"])
  {
    const std::string j = row["joint"].get<std::string>();
    if (j.size() == 1 && row.contains(what))
      v[j[0]] = row[what]["cm"].get<double>();
  }
  return v;
}

/// A Table 2/3 layout: rows case x face, columns the labels.
void joint_table(std::ostream& md, std::ostream& csv,
                 const std::vector<JointStudyRun>& runs,
                 const std::string& labels, const std::string& what)
{
  md << "| case | face |";
  for (char l : labels)
    md << " " << l << " |";
  md << "\n|---|---|";
  for (std::size_t k = 0; k < labels.size(); ++k)
    md << "---|";
  md << "\n";
  for (const auto& r : runs)
  {
    for (const auto& [face, key] :
         {std::pair{"U", "upstream"}, std::pair{"D", "downstream"}})
    {
      const auto v = per_joint(r.summary, what + "_" + key);
      md << "| " << case_name(r.set) << " | " << face << " |";
      csv << what << "," << r.set << "," << face;
      for (char l : labels)
      {
        const auto it = v.find(l);
        const std::string s = it == v.end() ? "" : fixed(it->second, 4);
        md << " " << s << " |";
        csv << "," << s;
      }
      md << "\n";
      csv << "\n";
    }
  }
}
} // namespace

void write_joint_study(MPI_Comm comm, const std::vector<JointStudyRun>& runs,
                       const std::string& labels,
                       const std::filesystem::path& dir, bool plots)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank != 0)
    return;
  std::ofstream md(dir / "joint_study.md"), csv(dir / "joint_study.csv");
  csv << "quantity,joints,face";
  for (char l : labels)
    csv << "," << l << "_cm";
  csv << "\n";
  md << "# Joint study\n\nLargest joint opening in the normal direction "
        "[cm] (the paper's Tables 2 and 4); U: upstream face, D: "
        "downstream face.\n\n";
  joint_table(md, csv, runs, labels, "opening");
  md << "\nLargest joint sliding in the tangential direction [cm] (the "
        "paper's Tables 3 and 5).\n\n";
  joint_table(md, csv, runs, labels, "sliding");
  md << "\nPer case, on the upstream (U) and downstream (D) faces away from "
        "the singular points: the largest principal tension and "
        "compression, the largest arch and cantilever tension [MPa]; the "
        "largest crest displacement [cm], the contact work and the wall "
        "time.\n\n"
        "| case | pairs | max opening [cm] | max sliding [cm] | tension U | "
        "tension D | compression U | compression D | arch tension U | arch "
        "tension D | cantilever tension U | cantilever tension D | crest "
        "[cm] | NCP iterations | wall [s] |\n|---|---|---|---|---|---|---|"
        "---|---|---|---|---|---|---|---|\n";
  for (const auto& r : runs)
  {
    const auto& s = r.summary;
    const auto& j = s["joints"];
    auto face = [&](const char* f, const char* what)
    {
      const auto& v = s["faces"][f]["away_from_singular_points"][what];
      return fixed(v["value"].get<double>(), 2);
    };
    auto direction = [&](const char* f, const char* what)
    {
      const auto& faces = s["faces"][f];
      const char* key = "arch_cantilever_away_from_singular_points";
      return faces.contains(key)
                 ? fixed(faces[key][what]["value"].get<double>(), 2)
                 : std::string("-");
    };
    const bool contact = j.contains("max_opening_cm");
    md << "| " << case_name(r.set) << " | " << j.value("pairs", 0) << " | "
       << (contact ? fixed(j["max_opening_cm"].get<double>(), 4) : "-") << " | "
       << (contact ? fixed(j["max_sliding_cm"].get<double>(), 4) : "-") << " | "
       << face("upstream", "max_principal_tension_mpa") << " | "
       << face("downstream", "max_principal_tension_mpa") << " | "
       << face("upstream", "max_principal_compression_mpa") << " | "
       << face("downstream", "max_principal_compression_mpa") << " | "
       << direction("upstream", "arch_tension_mpa") << " | "
       << direction("downstream", "arch_tension_mpa") << " | "
       << direction("upstream", "cantilever_tension_mpa") << " | "
       << direction("downstream", "cantilever_tension_mpa") << " | "
       << fixed(100.0 * s["crest_displacement_max_m"]["value"].get<double>(), 2)
       << " | "
       << (contact ? std::to_string(j["ncp_iterations"].get<long>()) : "-")
       << " | " << fixed(s["wall_seconds"].get<double>(), 0) << " |\n";
  }
  md.close();
  csv.close();
  if (plots)
    run_plot_script("plot_joint_study.py", dir);
}
} // namespace damseis::analysis
