// The linear seismic analysis of a dam model, whatever its geometry (2D
// section or 3D dam): static stage (dead weight, hydrostatic), modal
// analysis with and without added mass, HHT/Newmark time history under base
// acceleration, and the outputs (XDMF fields and envelopes, face extremes,
// crest history, summary, checkpoints).
#pragma once

#include "seismic_analysis.h"
#include "seismic_settings.h"
#include "timed_loads.h"
#include "wave_foundation.h"
#include <damseis/fem/elastic_model.h>
#include <damseis/joint/pairs.h>
#include <damseis/joint/static_contact.h>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

namespace damseis::analysis
{
/// Loads of a model besides dead weight, water and the ground motion
/// (full-space vectors, zero at fixed dofs; they must outlive the
/// analysis).
struct ModelLoads
{
  std::vector<Vec> static_loads;  ///< silt, uplift, body forces
  std::vector<TimedLoad> timed;   ///< tractions with a time history
  Vec initial_velocity = nullptr; ///< full space; null: at rest
};

/// Contraction joints with Coulomb friction (joint/): the time history
/// runs on all dofs with the pairs' contact condensed onto them, from the
/// static stage with contact; the state is total (contact is not additive).
struct ContactJoints
{
  std::vector<joint::JointSpec> joints;
  /// The facet tags the joints' tags refer to.
  const dolfinx::mesh::MeshTags<std::int32_t>* facet_tags = nullptr;
  double restitution = 1.0; ///< impact correction: e in [0, 1]; < 0: none
  joint::StaticContactSettings statics;
  /// Points whose nearest pairs are recorded per step (empty: each
  /// joint's top pair).
  std::vector<std::array<double, 3>> history_points;
  contact::NcpSettings ncp; ///< the pair problem's formulation, tolerance
  double tolerance = 1e-8;  ///< coincidence of the pair nodes [m]
};

/// The analysis on `fe` (materials and fixed boundaries already set)
/// that writes into `folder.dir` (created): summary.json, crest.csv,
/// fields.xdmf, envelopes.xdmf, modes.xdmf, face_<name>.csv, case_used.toml.
/// Its phases are collective; `fe` and the vectors must outlive it.
///
/// With settings.checkpoint_every > 0 the state is saved every so many steps
/// in out_dir/checkpoint; with settings.restart the run resumes from there
/// (fields written after a restart go to fields_from_step<k>.xdmf). On
/// SIGINT/SIGTERM, or at settings.stop_at_step, the run writes a checkpoint
/// at the end of the current step and throws engine::Interrupted.
///
/// `tie` (optional, from fem::tie_prolongation) ties coincident dofs
/// (bonded joints): the system is solved for u_r with u = P u_r. With
/// `contact`, the joints it lists are contact joints instead and `tie` (the
/// same joints bonded) serves the modal stage only: the natural
/// frequencies and the Rayleigh damping are those of the closed joints.
/// `loads`: the static loads are added to the static stage, the timed ones
/// to the ground motion's in the time history; with an initial velocity
/// the initial acceleration satisfies M a = f - C v (at the dofs with
/// mass).
///
/// With `wave`, the foundation has mass and a viscous-spring boundary on
/// the facets it names (`fe` has no fixed dofs there), and the ground
/// motion is the outcrop motion of vertically incident waves: the state is
/// absolute (the displacements include the ground's) and the load is the
/// free field's (analysis/free_field_load); the Rayleigh damping acts on
/// the motion relative to the free field; bonded and contact joints run on
/// it.
std::unique_ptr<SeismicAnalysis>
linear_seismic_analysis(fem::ElasticModel& fe, const SeismicSettings& settings,
                        const ModelLoads& loads, const RunFolder& folder,
                        Mat tie = nullptr,
                        const ContactJoints* contact = nullptr,
                        const WaveFoundation* wave = nullptr);

/// All phases of that analysis; returns the summary.
inline nlohmann::json run_linear_seismic(fem::ElasticModel& fe,
                                         const SeismicSettings& settings,
                                         const ModelLoads& loads,
                                         const RunFolder& folder,
                                         Mat tie = nullptr)
{
  return linear_seismic_analysis(fe, settings, loads, folder, tie)->run();
}

/// The summary's description of a wave foundation (boundary, rock, input;
/// `boundary_measure` and the spring factors for a viscous-spring one).
nlohmann::json wave_foundation_summary(const WaveFoundation& wave,
                                       const boundary::FreeField& f,
                                       double boundary_measure);
} // namespace damseis::analysis

namespace damseis::analysis
{
/// Writes summary.json on rank 0 and, if `plots`, runs the plotting script
/// `scripts/<plot_script>` of the source tree on the output folder (a
/// failure to plot is a warning, not an error).
void write_summary_and_plots(MPI_Comm comm, const nlohmann::json& summary,
                             const std::filesystem::path& out_dir, bool plots,
                             const std::string& plot_script);

/// Runs `scripts/<script> <dir>` of the source tree with the build's Python
/// (a failure is a warning; call on one rank).
void run_plot_script(const std::string& script,
                     const std::filesystem::path& dir);
} // namespace damseis::analysis
