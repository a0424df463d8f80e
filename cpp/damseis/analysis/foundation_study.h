// The foundation models side by side (the paper's Table 6 for the Koyna
// section, Figs. 22-27 for the 102 m arch dam): for each ratio E_f / E_d,
// the massless foundation fixed at its far boundary (case B) and the rock
// with mass and a viscous-spring boundary under vertically incident waves
// (case A, dam-foundation interaction), and for the Koyna section with a
// banded block the multi-transmitting boundary too (A').
#pragma once

#include "gravity_dam_analysis.h"
#include <functional>

namespace damseis::analysis
{
/// One run of the study into `dir`: the foundation of modulus ratio
/// E_f / E_d, with mass and a viscous-spring boundary or massless, the
/// Rayleigh damping fitted at `damping_hz` (empty: at the run's own
/// modes); returns its summary.
using FoundationRun = std::function<nlohmann::json(
    double ratio, FoundationBoundary boundary,
    const std::vector<double>& damping_hz, const std::filesystem::path& dir)>;

/// A case beside the ratios (the paper's inhomogeneous rock): run with
/// interaction only, with the damping frequencies given, into `dir`.
struct ExtraCase
{
  std::string label, folder;
  std::function<nlohmann::json(const std::vector<double>& damping_hz,
                               const std::filesystem::path& dir)>
      run;
};

/// Runs the cases into out_dir/ratio_<r>/{massless,viscous_spring,mtf}
/// (the interaction `models`; the extra cases, with the first model, into
/// out_dir/<folder>) and writes <table>.csv and <table>.md. Each
/// interaction run takes the Rayleigh damping of its massless run (the
/// same two frequencies), so that they differ by the foundation model
/// alone; the extra cases that of E_f/E_d = 1 (or the first ratio).
/// Returns the last summary.
nlohmann::json
run_foundation_study(MPI_Comm comm, const std::vector<double>& ratios,
                     const std::filesystem::path& out_dir,
                     const std::string& table, const FoundationRun& run,
                     const std::vector<ExtraCase>& extra = {},
                     const std::vector<FoundationBoundary>& models = {
                         FoundationBoundary::viscous_spring});

/// The gravity-dam section's study (study.table6): seismic stresses, into
/// table6.csv and table6.md; with study.table6_inhomogeneous the paper's
/// cases 4 and 5 too.
nlohmann::json run_table6_study(MPI_Comm comm, const GravityDamConfig& cfg,
                                const std::filesystem::path& out_dir,
                                const std::string& case_text,
                                const GravityDamRun& analyse);
} // namespace damseis::analysis
