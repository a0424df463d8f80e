// The foundation models side by side (the paper's Table 6, study.table6):
// for each ratio E_f / E_d, the massless block fixed at its far boundary
// (case B) and the block with mass and a viscous-spring boundary under
// vertically incident waves (case A, dam-foundation interaction), seismic
// stresses only.
#pragma once

#include "gravity_dam_analysis.h"

namespace damseis::analysis
{
/// Runs the cases into out_dir/ratio_<r>/{massless,viscous_spring} and
/// writes table6.csv and table6.md. Each interaction run takes the Rayleigh
/// damping of its massless run (the same two frequencies), so that the two
/// differ by the foundation model alone. Returns the last summary.
nlohmann::json run_foundation_study(MPI_Comm comm, const GravityDamConfig& cfg,
                                    const std::filesystem::path& out_dir,
                                    const std::string& case_text,
                                    const GravityDamRun& analyse);
} // namespace damseis::analysis
