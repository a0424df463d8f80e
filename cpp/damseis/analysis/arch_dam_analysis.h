// The linear seismic analysis of a 3D arch dam on a massless foundation
// (demo `arch_dam`).
#pragma once

#include "arch_dam_case.h"
#include <filesystem>
#include <mpi.h>
#include <nlohmann/json.hpp>

namespace damseis::analysis
{
/// Builds the dam, canyon and foundation, ties the joints (bonded), runs the
/// linear seismic analysis and writes its results into `out_dir`, with
/// summary.json and the plots. Returns the summary.
nlohmann::json run_arch_dam_analysis(MPI_Comm comm, const ArchDamConfig& config,
                                     const std::filesystem::path& out_dir,
                                     const std::string& case_text);
} // namespace damseis::analysis
