// The complete linear seismic analysis of a 2D gravity-dam section:
// static stage (dead weight, hydrostatic), modal analysis (with and without
// Westergaard added mass), time history under base excitation, and the
// outputs (XDMF fields and envelopes, crest history, summary, plots).
#pragma once

#include "gravity_dam_case.h"
#include <filesystem>
#include <mpi.h>
#include <nlohmann/json.hpp>

namespace damseis::analysis
{
/// Runs the analysis and writes its results into `out_dir` (created).
/// `case_text` (the effective case as TOML) is saved beside the results.
/// Returns the summary that is also written to summary.json.
nlohmann::json run_gravity_dam_analysis(MPI_Comm comm,
                                        const GravityDamConfig& config,
                                        const std::filesystem::path& out_dir,
                                        const std::string& case_text);
} // namespace damseis::analysis
