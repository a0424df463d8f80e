// The modal stage of a seismic analysis: frequencies with and without the
// added mass, the Rayleigh damping fitted to them, the mode shapes.
#pragma once

#include "seismic_settings.h"
#include <damseis/dynamics/newmark.h>
#include <damseis/fem/elastic_model.h>
#include <damseis/linalg/modal.h>
#include <filesystem>
#include <functional>
#include <vector>

namespace damseis::analysis
{
/// Modal analysis (with the added mass in M, and dry if `M_dry`) and the
/// Rayleigh damping of the settings; prints the frequencies (rank 0).
/// `with_K_factors`: see linalg::solve_modes (its time is reported in
/// `with_K_factors_seconds`, not in `seconds`).
struct ModalResult
{
  linalg::Modes modes;
  std::vector<double> dry_hz;
  double f1 = 0.0, f2 = 0.0;
  dynamics::RayleighDamping damping;
  double seconds = 0.0;
  double with_K_factors_seconds = 0.0;
};
ModalResult
modal_and_damping(Mat K, Mat M, Mat M_dry, const SeismicSettings& s,
                  const std::function<void(KSP)>& with_K_factors = {});
/// Writes the mode shapes (P1 vertex displacement, mass-normalised) as one
/// XDMF grid, a vector field per mode named with its number and frequency
/// (mode_01_2.241_Hz).
void write_modes(fem::ElasticModel& fe, const linalg::Modes& modes,
                 const std::function<Vec(Vec)>& full,
                 const std::filesystem::path& file);
} // namespace damseis::analysis
