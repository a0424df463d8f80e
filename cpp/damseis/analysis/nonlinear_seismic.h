// The nonlinear seismic analysis of a 2D dam section with HTC concrete
// (elastic, rate-independent plastic or viscoplastic): nonlinear static
// stage in load increments, modal analysis of the initial elastic system,
// HHT/Newmark with Newton per step, and the outputs of the linear engine
// plus the viscoplastic strains and strain rates.
#pragma once

#include "concrete_settings.h"
#include "seismic_settings.h"
#include <damseis/fem/elastic_model.h>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <vector>

namespace damseis::analysis
{
/// Runs the analysis on `fe` (fixed boundaries set; its materials are the
/// initial elastic ones and must match `concrete.params` in the dam region)
/// and writes into `out_dir` what run_linear_seismic writes, plus
/// dam_points.csv (per dam quadrature point: envelopes, equivalent
/// viscoplastic strains, maximum strain rates). `elastic` gives the
/// materials of the other regions (they stay linear elastic);
/// `extra_static_loads` (full-space vectors, zero at fixed dofs) are applied
/// with the reservoir in the static stage (silt, uplift). Checkpoints and
/// signals as in run_linear_seismic. Collective.
///
/// Throws dynamics::StepFailure if a step cannot be solved (the outputs
/// written so far stay; no unconverged step is accepted).
nlohmann::json run_nonlinear_seismic(
    fem::ElasticModel& fe, const SeismicSettings& settings,
    const ConcreteSettings& concrete,
    const std::map<int, fem::Material>& elastic, fem::PlaneMode plane,
    const std::vector<Vec>& extra_static_loads,
    const std::filesystem::path& out_dir, const std::string& case_text);
} // namespace damseis::analysis
