// Pieces shared by the seismic analysis engines (linear_seismic.cpp,
// nonlinear_seismic.cpp): PETSc vector helpers, stop signals, modal
// analysis and Rayleigh damping, the crest history and the face tables.
#pragma once

#include "seismic_settings.h"
#include <damseis/fem/elastic_model.h>
#include <damseis/fem/modal.h>
#include <damseis/results/stress_envelope.h>
#include <dolfinx/la/petsc.h>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <span>
#include <vector>

namespace damseis::analysis
{
/// A new zero vector with the layout of the columns (rows) of A.
dolfinx::la::petsc::Vector column_vector(Mat A);
dolfinx::la::petsc::Vector row_vector(Mat A);
/// Copies `x` (owned values) into the Function `u` and updates its ghosts.
void to_function(Vec x, dolfinx::fem::Function<double>& u);
std::vector<double> owned_values(Vec x);
void set_owned_values(Vec x, const std::vector<double>& v);

/// {"value" [MPa], "x", "y"(, "z"), "t"} of an extreme stress.
nlohmann::json extreme_json(const results::Extreme& e, int dim);
/// Local cells (owned and ghost) of a region tag.
std::vector<std::int32_t> region_cells(const geometry::Model& m, int region);

/// SIGINT/SIGTERM request a stop while an instance lives (the previous
/// handlers come back on destruction).
class StopSignals
{
public:
  StopSignals();
  ~StopSignals();
  /// True on every rank if any rank got a signal or `forced`; collective.
  bool requested(MPI_Comm comm, bool forced) const;

private:
  void (*_old_int)(int);
  void (*_old_term)(int);
};

/// Modal analysis (with the added mass in M, and dry if `M_dry`) and the
/// Rayleigh damping of the settings.
struct ModalResult
{
  fem::Modes modes;
  std::vector<double> dry_hz;
  double f1 = 0.0, f2 = 0.0;
  dynamics::RayleighDamping damping;
  double seconds = 0.0;
};
ModalResult modal_and_damping(Mat K, Mat M, Mat M_dry,
                              const SeismicSettings& s);
/// Writes the mode shapes (P1 vertex displacement) as an XDMF series.
void write_modes(fem::ElasticModel& fe, const fem::Modes& modes,
                 const std::function<Vec(Vec)>& full,
                 const std::filesystem::path& file);

/// Writes the envelope values of the given owned points of every rank into
/// a CSV file on rank 0.
void write_face_csv(MPI_Comm comm, const results::StressEnvelope& env,
                    std::span<const std::int32_t> points,
                    const std::filesystem::path& file);

/// Post-processes the crest history (per step: crest then base displacement
/// components, already reduced over ranks): writes crest.csv (relative to
/// the base, seismic and total) on rank 0 and returns the summary entries
/// "crest_displacement_max_m", "crest_displacement_max_by_component_m" and
/// "crest_static_m". `crest_static`/`base_static`: static displacements
/// (added to the seismic history for the total columns); with
/// `history_is_total` the history already holds total displacements and
/// the static part is subtracted for the seismic columns.
nlohmann::json write_crest_history(MPI_Comm comm,
                                   const std::vector<double>& hist, int dim,
                                   int steps, double dt,
                                   const std::array<double, 3>& crest_static,
                                   const std::array<double, 3>& base_static,
                                   bool history_is_total,
                                   const std::filesystem::path& file);

/// Per-face envelope tables (face_<name>.csv) and summary entries.
nlohmann::json write_faces(MPI_Comm comm, const SeismicSettings& s,
                           const results::StressEnvelope& env,
                           const std::vector<std::vector<std::int32_t>>& pts,
                           int dim, const std::filesystem::path& out_dir);
} // namespace damseis::analysis
