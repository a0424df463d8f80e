/// @file ground_motion_output.h
/// Files of the ground_motion demo: records (two-column text and PEER AT2),
/// spectra.csv, target_spectrum.csv, summary.json.
#pragma once

#include "artificial.h"
#include "ground_motion_case.h"
#include <filesystem>
#include <nlohmann/json.hpp>

namespace damseis::motion
{
/// Writes the generated components (<name>.txt, <name>.at2), spectra.csv
/// (period_s, then <name>_zeta_<d> pseudo-accelerations in m/s2 for each
/// damping ratio), target_spectrum.csv and returns the summary (also
/// written to summary.json).
nlohmann::json write_generated(const std::filesystem::path& dir,
                               const GroundMotionConfig& cfg,
                               const ArtificialMotion& motion);

/// Reads the records of cfg (task "spectrum") and writes spectra.csv (and
/// target_spectrum.csv if there is a target) and summary.json; returns the
/// summary.
nlohmann::json write_record_spectra(const std::filesystem::path& dir,
                                    const GroundMotionConfig& cfg);
} // namespace damseis::motion
