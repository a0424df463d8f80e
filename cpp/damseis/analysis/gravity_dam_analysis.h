// The linear seismic analysis of a 2D gravity-dam section (demo `koyna`):
// the section and its model, then the shared linear seismic analysis.
#pragma once

#include "gravity_dam_case.h"
#include <filesystem>
#include <mpi.h>
#include <nlohmann/json.hpp>

namespace damseis::analysis
{
/// Builds the section (rigid base or massless foundation block), runs the
/// linear seismic analysis and writes its results into `out_dir`, with
/// summary.json and the plots. Returns the summary.
nlohmann::json run_gravity_dam_analysis(MPI_Comm comm,
                                        const GravityDamConfig& config,
                                        const std::filesystem::path& out_dir,
                                        const std::string& case_text);
} // namespace damseis::analysis
