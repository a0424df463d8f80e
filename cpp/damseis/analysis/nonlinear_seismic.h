// The nonlinear seismic analysis of a 2D dam section with HTC concrete
// (elastic, rate-independent plastic or viscoplastic): nonlinear static
// stage in load increments, modal analysis of the initial elastic system,
// HHT/Newmark with Newton per step, and the outputs of the linear engine
// plus the viscoplastic strains and strain rates.
#pragma once

#include "concrete_settings.h"
#include "linear_seismic.h"
#include "seismic_settings.h"
#include <damseis/fem/elastic_model.h>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <vector>

namespace damseis::analysis
{
/// The concrete of a nonlinear run: the HTC model of the dam region, the
/// elastic materials of the other regions (they stay linear), and the 2D
/// plane mode.
struct ConcreteBulk
{
  ConcreteSettings concrete;
  std::map<int, fem::Material> elastic;
  fem::PlaneMode plane = fem::PlaneMode::plane_strain;
  /// The cell tags made of this concrete (the dam).
  std::vector<int> regions = {1};
};

/// The analysis on `fe` (fixed boundaries set; its materials are the
/// initial elastic ones and must match `bulk.concrete.params` in the dam
/// region) that writes into `folder.dir` what run_linear_seismic writes,
/// plus dam_points.csv (per dam quadrature point: envelopes, equivalent
/// viscoplastic strains, maximum strain rates). `loads` as in
/// run_linear_seismic: the static ones are applied with the reservoir in
/// the static stage (silt, uplift, body forces), the timed ones with the
/// ground motion, and an initial velocity starts the time history. `tie`
/// (optional) ties bonded joints, u = P u_r, as in run_linear_seismic: the
/// Newton iteration runs on the tied unknowns (TiedConcreteSystem). `wave`
/// (optional): a foundation with mass on a viscous-spring boundary (its
/// springs linear supports of the concrete system and in K0, its dashpots
/// extra damping, the free field's load on top of the static loads).
/// `contact` (optional, with `tie` the same joints bonded for the modal
/// stage): contact joints, a constraint of every Newton iteration of the
/// static stage and the time history (joint::NonlinearContact), with the
/// joint outputs of run_linear_seismic. Checkpoints and signals as in
/// run_linear_seismic. Collective.
///
/// Throws dynamics::StepFailure if a step cannot be solved (the outputs
/// written so far stay; no unconverged step is accepted).
std::unique_ptr<SeismicAnalysis> concrete_seismic_analysis(
    fem::ElasticModel& fe, const SeismicSettings& settings,
    const ConcreteBulk& bulk, const ModelLoads& loads, const RunFolder& folder,
    Mat tie = nullptr, const WaveFoundation* wave = nullptr,
    const ContactJoints* contact = nullptr);

/// All phases of that analysis; returns the summary.
inline nlohmann::json
run_nonlinear_seismic(fem::ElasticModel& fe, const SeismicSettings& settings,
                      const ConcreteBulk& bulk, const ModelLoads& loads,
                      const RunFolder& folder, Mat tie = nullptr)
{
  return concrete_seismic_analysis(fe, settings, bulk, loads, folder, tie)
      ->run();
}
} // namespace damseis::analysis
