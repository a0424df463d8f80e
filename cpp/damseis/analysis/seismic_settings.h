// Settings of a linear seismic analysis that do not depend on the dam type:
// loads, reservoir, modes, damping, time integration, ground motion, output,
// solver, checkpoints; their case keys and their reading.
#pragma once

#include <array>
#include <damseis/dynamics/newmark.h>
#include <damseis/fem/elastic_model.h>
#include <damseis/input/case.h>
#include <damseis/linalg/direct_solver.h>
#include <string>
#include <utility>
#include <vector>

namespace damseis::analysis
{
/// One component of the ground acceleration on the analysis time grid.
struct GroundMotion
{
  bool active = false;
  std::vector<double> acceleration; ///< m/s2 at t_k = k dt, k = 0..steps
  std::string record;               ///< file it came from
  std::string description;
  double peak_g = 0.0; ///< peak after scaling [g]
};

/// A ground-motion direction: its case-key name and displacement component.
struct Direction
{
  std::string name; ///< e.g. "horizontal", "stream", "vertical"
  int component;    ///< 0 = x, 1 = y, 2 = z
  std::string default_record;
  double default_peak_g;
};

struct SeismicSettings
{
  fem::Reservoir reservoir;
  bool westergaard = true;
  double gravity = 9.81; ///< acts along -e_{dim}
  int modes = 6;
  double damping_ratio = 0.05;
  std::vector<std::int64_t> damping_modes = {1, 3};
  std::vector<double> damping_frequencies_hz; ///< overrides damping_modes
  dynamics::TimeScheme scheme;
  int steps = 0;
  /// Ground motion per displacement component (inactive ones are zero).
  std::array<GroundMotion, 3> motion;
  int output_every = 10;
  bool stress_total = true; ///< envelopes of static + seismic stress
  std::array<double, 3> crest_point = {0, 0, 0};
  std::array<double, 3> base_point = {0, 0, 0};
  /// The cell tags of the dam (stress envelopes): geometry::tags::dam in
  /// the built models, the user's groups in dam_model.
  std::vector<int> dam_regions = {1};
  /// The cells the dead weight acts on (empty: all). A foundation with
  /// mass carries its own weight before the dam is built: only the dam's
  /// loads it (the dam_regions).
  std::vector<int> gravity_regions;
  /// Named groups (cells or facets, tagged `tag` in `tags`) whose mean
  /// displacement, velocity and acceleration are recorded
  /// (group_histories.csv).
  struct HistoryGroup
  {
    std::string name;
    std::shared_ptr<const dolfinx::mesh::MeshTags<std::int32_t>> tags;
    int tag = 0;
  };
  std::vector<HistoryGroup> history_groups;
  /// Named points whose displacement, velocity and acceleration are
  /// recorded (histories.csv).
  std::vector<std::pair<std::string, std::array<double, 3>>> history_points;
  /// Faces whose envelope extremes are reported: (name, facet tags), the
  /// tags of `face_tags` (null: the model's facet tags).
  std::shared_ptr<const dolfinx::mesh::MeshTags<std::int32_t>> face_tags;
  std::vector<std::pair<std::string, std::vector<int>>> faces;
  /// Points where the elastic stress is unbounded (results/
  /// singular_points.h), what they are, and the radius around them that
  /// the mesh-objective extremes leave out [m].
  std::vector<std::array<double, 3>> singular_points;
  std::string singular_where;
  double singular_radius = 0.0;
  int checkpoint_every = 0; ///< steps between checkpoints; 0: none
  bool restart = false;     ///< resume from the output folder's checkpoint
  int stop_at_step = 0;     ///< checkpoint and stop there (0: run to the end)
  bool plots = true;
  linalg::Factorization factorization = linalg::Factorization::automatic;
};

/// Adds the shared keys. `directions` are the ground-motion components the
/// demo offers; the crest and base points default to the given coordinates.
void add_seismic_keys(input::Schema& schema,
                      const std::vector<Direction>& directions,
                      const std::string& crest_point,
                      const std::string& base_point);

/// Reads and checks the shared keys, loads and scales the records. `dim` is
/// the spatial dimension; `crest_elevation` bounds the reservoir level;
/// `crest` and `base` are used when output.crest_point / output.base_point
/// are empty. With `motion_optional` every record may be empty (other
/// loads drive the model): the run then lasts time.duration (which must be
/// given). Throws input::InputError naming the file and key.
SeismicSettings read_seismic_settings(const input::Case& c,
                                      const std::vector<Direction>& directions,
                                      int dim, double crest_elevation,
                                      const std::array<double, 3>& crest,
                                      const std::array<double, 3>& base,
                                      bool motion_optional = false);
/// Refuses an output point (key `key`, e.g. "output.crest_point") that is
/// `distance` m from the model, more than `tolerance` (the mesh size: the
/// history would be that of some node far from the point asked for).
/// `model` says what the point should be in, e.g. "the dam section or its
/// foundation block".
void check_output_point(const input::Case& c, const std::string& key,
                        const std::array<double, 3>& x, int dim,
                        double distance, double tolerance,
                        const std::string& model);
} // namespace damseis::analysis
