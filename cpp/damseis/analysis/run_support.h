// Pieces shared by the seismic analysis engines (linear_seismic.cpp,
// nonlinear_seismic.cpp): PETSc vector helpers, stop signals, modal
// analysis and Rayleigh damping, the crest history and the face tables.
#pragma once

#include "checkpoint.h"
#include "seismic_settings.h"
#include <chrono>
#include <damseis/fem/elastic_model.h>
#include <damseis/linalg/modal.h>
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

/// A coordinate [m] rounded to the micrometre (no round-off noise such as
/// -2.9e-17 or 103.00000000000001 in summaries), and a time [s] to the
/// nanosecond.
double coordinate(double x);
double instant(double t);

/// The array `name` of a checkpoint with `size` values (0: any size);
/// std::runtime_error otherwise.
const std::vector<double>& checkpoint_array(const CheckpointData& data,
                                            const std::string& name,
                                            std::size_t size = 0);
/// Runs `restore` (reading a checkpoint into the run) on every rank; a
/// failure on any rank (a missing or mis-sized array) becomes
/// input::InputError on all of them. Collective.
void restore_collectively(MPI_Comm comm, const std::filesystem::path& dir,
                          const std::function<void()>& restore);

/// {"value" [MPa], "x", "y"(, "z"), "t"} of an extreme stress.
nlohmann::json extreme_json(const results::Extreme& e, int dim);
/// Local cells (owned and ghost) of a region tag.
std::vector<std::int32_t> region_cells(const geometry::Model& m, int region);

/// Wall seconds since t0.
double seconds_since(std::chrono::steady_clock::time_point t0);

/// The ground-acceleration load of the relative formulation,
/// f(t_k) = base - M sum_c r_c a_gc(t_k), for the active components of the
/// settings; with `tie` the influence vectors are restricted to the tied
/// unknowns (M is then the reduced mass).
class GroundMotionLoad
{
public:
  GroundMotionLoad(const fem::ElasticModel& fe, const SeismicSettings& s, Mat M,
                   Mat tie = nullptr);
  /// f = base (or 0 if base is null) + the ground-motion load at step k.
  void assemble(int k, Vec base, Vec f) const;
  /// The acceleration at rest under the ground motion at t = 0,
  /// a = -sum_c r_c a_gc(0): it satisfies M a = f(0) also where M is
  /// singular (massless foundation, fixed dofs).
  void initial_acceleration(Vec a) const;

private:
  const SeismicSettings& _s;
  std::vector<int> _active;
  std::vector<dolfinx::la::petsc::Vector> _influence, _load;
};

/// SIGINT/SIGTERM request a stop while an instance lives (the previous
/// handlers come back on destruction).
class StopSignals
{
public:
  StopSignals();
  ~StopSignals();
  /// True on every rank if any rank got a signal or `forced`; collective.
  bool requested(MPI_Comm comm, bool forced) const;
  /// After step k of n: calls checkpoint(k) every s.checkpoint_every steps
  /// (not at the last) and on a stop request (a signal or
  /// s.stop_at_step), then throws Interrupted on a stop. Collective.
  void checkpoint_or_stop(MPI_Comm comm, const SeismicSettings& s, int k, int n,
                          const std::function<void(int)>& checkpoint,
                          const std::filesystem::path& ckpt_dir) const;

private:
  void (*_old_int)(int);
  void (*_old_term)(int);
};

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

/// Prints the model line of a run: "damseis: N cells, M dofs, Pk, R rank(s)"
/// followed by `suffix`.
void print_model_line(fem::ElasticModel& fe, const std::string& suffix);

/// Prints the size of the analysis estimated before meshing (cells, dofs,
/// memory, time per step and for the `steps` of a linear time history),
/// with a warning if the memory exceeds 80% of this machine's.
void print_size_estimate(MPI_Comm comm, double cells, int dim, int order,
                         int steps);

/// Gathers every rank's rows (`columns` values each, flattened) on rank 0
/// and writes them under `header` as CSV (8 digits).
void write_rows_csv(MPI_Comm comm, const std::vector<double>& local,
                    int columns, const std::string& header,
                    const std::filesystem::path& file);

/// Writes the envelope values of the given owned points of every rank into
/// a CSV file on rank 0.
void write_face_csv(MPI_Comm comm, const results::StressEnvelope& env,
                    std::span<const std::int32_t> points,
                    std::span<const std::array<double, 3>> singular,
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

/// Timings of a run [s] and the step it restarted from.
struct RunTimes
{
  double setup_and_static = 0.0, modal = 0.0, factorization = 0.0, loop = 0.0;
  int restarted_from_step = 0;
};

/// summary.json entries common to the seismic engines: model size, modes,
/// damping, ground motion, crest point, stress extremes (from `envelope`),
/// faces, solver and timings. Collective (the stress extremes).
nlohmann::json seismic_summary(MPI_Comm comm, const fem::ElasticModel& fe,
                               const SeismicSettings& s,
                               const ModalResult& modal, bool added_mass,
                               const std::array<double, 3>& crest_node,
                               const results::StressEnvelope& envelope,
                               const nlohmann::json& faces,
                               const std::string& solver, const RunTimes& t);

/// Mesh-objective extremes (results/singular_points.h): the envelope
/// extremes over the points of `subset` (nullptr: the region) farther than
/// s.singular_radius from every singular point, with the radius and (for
/// the region) the method and the points. Collective.
nlohmann::json away_from_singular(MPI_Comm comm, const SeismicSettings& s,
                                  const results::StressEnvelope& env, int dim,
                                  const std::vector<std::int32_t>* subset);

/// The closing line of a run (rank 0): stress extremes and crest peak of a
/// summary, then `extra`.
void print_summary_line(MPI_Comm comm, const nlohmann::json& summary,
                        const std::string& extra = "");

/// Per-face envelope tables (face_<name>.csv) and summary entries.
nlohmann::json write_faces(MPI_Comm comm, const SeismicSettings& s,
                           const results::StressEnvelope& env,
                           const std::vector<std::vector<std::int32_t>>& pts,
                           int dim, const std::filesystem::path& out_dir);
} // namespace damseis::analysis
