// A seismic analysis of a dam model in the phases a reader follows in the
// demos' main.cpp: modal stage, static stage, time history, results. The
// modes come first: the Rayleigh damping is fitted to them, a linear model's
// static solution uses the factors of K the modal stage makes (one
// factorisation for both), and the nonlinear static stage relaxes with
// that damping.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace damseis::analysis
{
/// Where a run writes (created if needed) and the case text it ran
/// (case_used.toml; with the model, the checkpoint's fingerprint).
struct RunFolder
{
  std::filesystem::path dir;
  std::string case_text;
};

class SeismicAnalysis
{
public:
  virtual ~SeismicAnalysis() = default;
  /// Natural frequencies and mode shapes with the added water mass (and
  /// without it, for comparison), and the Rayleigh damping fitted to them.
  virtual void modal_stage() = 0;
  /// Dead weight, hydrostatic pressure and the extra static loads (silt,
  /// uplift): the state the earthquake starts from.
  virtual void static_stage() = 0;
  /// The engine's time loop under the ground motion, with its recorders
  /// (creates the output folder; checkpoints and restart).
  virtual void time_history() = 0;
  /// Writes the outputs (crest history, envelopes, face tables) and returns
  /// the summary. Collective.
  virtual nlohmann::json results() = 0;

  /// The four phases in order.
  nlohmann::json run()
  {
    modal_stage();
    static_stage();
    time_history();
    return results();
  }
};
} // namespace damseis::analysis
