#include "engine_settings.h"
#include <damseis/checkpoint/checkpoint_file.h>

namespace damseis::analysis
{
engine::TimeHistorySettings
time_history_settings(const SeismicSettings& s, fem::ElasticModel& fe,
                      const std::filesystem::path& out_dir,
                      const std::string& case_text)
{
  engine::TimeHistorySettings t;
  t.steps = s.steps;
  t.dt = s.scheme.dt;
  t.checkpoints = {s.checkpoint_every, s.stop_at_step};
  t.restart = s.restart;
  t.checkpoint_dir = out_dir / "checkpoint";
  // The model (dof coordinates: mesh and partition) and the points whose
  // histories the checkpoint holds (output.* is otherwise left out of the
  // case's fingerprint, so that output.every can change at a restart).
  std::vector<double> coords = fe.V()->tabulate_dof_coordinates(false);
  for (const auto& x : {s.crest_point, s.base_point})
    coords.insert(coords.end(), x.begin(), x.end());
  for (const auto& [name, x] : s.history_points)
    coords.insert(coords.end(), x.begin(), x.end());
  t.fingerprint =
      checkpoint::fingerprint(coords) ^ checkpoint::case_fingerprint(case_text);
  return t;
}
} // namespace damseis::analysis
