// What a seismic run reports: the model line and size estimate, the crest
// history, the face and point tables, stress extremes and summary.json.
#pragma once

#include "modal_stage.h"
#include "seismic_settings.h"
#include <array>
#include <chrono>
#include <damseis/fem/elastic_model.h>
#include <damseis/results/stress_envelope.h>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

namespace damseis::analysis
{
/// A coordinate [m] rounded to the micrometre (no round-off noise such as
/// -2.9e-17 or 103.00000000000001 in summaries), and a time [s] to the
/// nanosecond.
double coordinate(double x);
double instant(double t);

/// {"value" [MPa], "x", "y"(, "z"), "t"} of an extreme stress.
nlohmann::json extreme_json(const results::Extreme& e, int dim);
/// Local cells (owned and ghost) of a region tag.
std::vector<std::int32_t> region_cells(const geometry::Model& m, int region);
/// Local cells (owned and ghost) of any of these region tags.
std::vector<std::int32_t> region_cells(const geometry::Model& m,
                                       const std::vector<int>& regions);

/// Wall seconds since t0.
double seconds_since(std::chrono::steady_clock::time_point t0);

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
/// a CSV file on rank 0; with `joint_sides` (one per point: -1 on the side
/// 1 of a contact joint, 1 on side 2, 0 elsewhere) a column joint_side, so
/// that plots can draw each block apart (contours break across joints);
/// with `cells` (one per point: the global index of the cell holding it,
/// for quadrature points) a column cell, so that plots can draw a cell's
/// points as one value.
void write_face_csv(MPI_Comm comm, const results::StressEnvelope& env,
                    std::span<const std::int32_t> points,
                    std::span<const std::array<double, 3>> singular,
                    const std::filesystem::path& file,
                    std::span<const std::int8_t> joint_sides = {},
                    std::span<const std::int64_t> cells = {});

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

/// Per-face envelope tables (face_<name>.csv) and summary entries;
/// `joint_sides` and `cells` (may be empty): per face, per point, as
/// write_face_csv.
nlohmann::json
write_faces(MPI_Comm comm, const SeismicSettings& s,
            const results::StressEnvelope& env,
            const std::vector<std::vector<std::int32_t>>& pts, int dim,
            const std::filesystem::path& out_dir,
            const std::vector<std::vector<std::int8_t>>& joint_sides = {},
            const std::vector<std::vector<std::int64_t>>& cells = {});
} // namespace damseis::analysis
