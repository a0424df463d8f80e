// What the joints did over a time history: per pair the largest opening
// (gap) and the largest sliding (|w_T - w_T,static|, from the state after
// the static stage) with their times; per step the pairs open and sliding,
// the widest opening and the NCP iterations. Then the tables engineers
// read (the paper's Tables 2-5): per joint and per face (upstream U,
// downstream D) the largest opening and sliding in cm.
#pragma once

#include "contact_run.h"
#include "static_contact.h"
#include <damseis/engine/parts.h>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace damseis::joint
{
/// A face of the dam: its name ("U", "D", ...) and the global blocks
/// (nodes) on it.
struct PairFace
{
  std::string name;
  std::vector<std::int64_t> blocks; ///< sorted
};

/// Writes joint_static.csv into `dir` (rank 0): per pair after the static
/// stage its area [m2], gap [cm], state (open, stick, slip), bond (none,
/// intact, broken) and force on side 2, in
/// the pair's frame (P_n: compression positive; P_a along t_a, P_b) and in
/// x, y, z [kN]. Returns the summary's entries: the totals of the joints'
/// forces in x, y, z and the pairs open.
nlohmann::json write_static_pairs(MPI_Comm comm,
                                  const std::filesystem::path& dir,
                                  const PairSet& pairs,
                                  const StaticContactResult& s);

class JointRecorder : public engine::Observer
{
public:
  /// Sliding is measured from `w_static` (3 per pair). The pairs nearest
  /// to `points` (empty: each joint's top pair) get histories. Replicated
  /// on every rank (the contact state is).
  JointRecorder(const ContactRun& stepper, Eigen::VectorXd w_static,
                const std::vector<std::array<double, 3>>& points = {});
  void record(int k, double t) override;
  void save(engine::Arrays& arrays) const override;
  void restore(const engine::CheckpointData& data) override;

  /// Writes joint_pairs.csv, joint_steps.csv, joint_histories.csv,
  /// joint_table.csv and joint_table.md into `dir` (rank 0) and returns
  /// the summary's entries.
  nlohmann::json write(MPI_Comm comm, const std::filesystem::path& dir,
                       const std::vector<PairFace>& faces) const;

  /// Per pair: the largest opening and sliding so far [m].
  const std::vector<double>& largest_opening() const { return _open; }
  const std::vector<double>& largest_sliding() const { return _slide; }

private:
  /// joint_histories.csv: t, then opening and sliding [cm] of each pair.
  void write_histories(const std::filesystem::path& file) const;

  const ContactRun& _stepper;
  Eigen::VectorXd _w_static;
  /// Per pair: largest opening, its time, largest sliding, its time.
  std::vector<double> _open, _t_open, _slide, _t_slide;
  /// Per step: t, pairs open, pairs sliding, widest opening, NCP iterations.
  std::vector<double> _steps;
  /// The pairs with histories, their names; per step: t, then opening and
  /// sliding of each.
  std::vector<int> _probe;
  std::vector<std::string> _probe_name;
  std::vector<double> _histories;
};
} // namespace damseis::joint
