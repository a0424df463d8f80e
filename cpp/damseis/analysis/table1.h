// The paper's Table 1 (section I): the largest principal compression and
// tension per concrete model (elastic, plastic, viscoplastic), and per
// reservoir level where a study runs several, as table1.csv and table1.md.
#pragma once

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace damseis::analysis
{
/// One run of a Table 1 study: its model, its reservoir level (NaN: the
/// study has one level and the tables no level column) and its summary.
struct Table1Run
{
  std::string model;
  double level_m = std::nan("");
  nlohmann::json summary;
};

/// table1.csv and table1.md in out_dir (call on one rank; `runs` not
/// empty, all with a level or none). The columns
/// "away from corners" take the extremes farther than the singular radius
/// from the singular points: of the whole dam, or (`faces`: a 3D dam,
/// whose base points next to the rock are not singular points but carry
/// its concentration) of the faces.
void write_table1(const std::vector<Table1Run>& runs,
                  const std::filesystem::path& out_dir, bool faces = false);
} // namespace damseis::analysis
