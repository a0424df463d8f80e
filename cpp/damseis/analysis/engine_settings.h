// The engine settings of a seismic run: steps, time step, checkpoints and
// restart from the case, the checkpoint folder in the output folder.
#pragma once

#include "seismic_settings.h"
#include <damseis/engine/time_history.h>
#include <damseis/fem/elastic_model.h>
#include <filesystem>
#include <string>

namespace damseis::analysis
{
/// The checkpoint's fingerprint covers the dof coordinates (mesh and
/// partition) and the case text.
engine::TimeHistorySettings
time_history_settings(const SeismicSettings& s, fem::ElasticModel& fe,
                      const std::filesystem::path& out_dir,
                      const std::string& case_text);
} // namespace damseis::analysis
