// The comparison tables of a joint study (arch_dam's study.joints: one run
// per set of active joints), laid out like the paper's Tables 2-5: per case
// and face (U upstream, D downstream) the largest opening, then sliding, of
// each joint A, B, ... in cm; and per case the largest stresses, crest
// displacement and the contact work.
#pragma once

#include <filesystem>
#include <mpi.h>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace damseis::analysis
{
/// One run of the study: its joint set ("none" or labels) and summary.
struct JointStudyRun
{
  std::string set;
  nlohmann::json summary;
};

/// Writes joint_study.md and joint_study.csv into `dir` (rank 0);
/// `labels`: all candidate joints, the tables' columns. With `plots`,
/// joint_study.png (scripts/plot_joint_study.py: opening and sliding along
/// the dam axis, one line per case).
void write_joint_study(MPI_Comm comm, const std::vector<JointStudyRun>& runs,
                       const std::string& labels,
                       const std::filesystem::path& dir, bool plots);
} // namespace damseis::analysis
