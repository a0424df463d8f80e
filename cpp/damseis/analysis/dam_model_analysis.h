// The seismic (and general dynamic) analysis of the user's own mesh (demo
// `dam_model`), in the pieces its main.cpp composes: the model, the linear
// analysis, the results.
#pragma once

#include "dam_model_case.h"
#include "linear_seismic.h"
#include "seismic_analysis.h"
#include <damseis/fem/elastic_model.h>
#include <dolfinx/la/petsc.h>
#include <filesystem>
#include <memory>
#include <mpi.h>
#include <nlohmann/json.hpp>
#include <optional>

namespace damseis::analysis
{
/// The model of a mesh file ready to analyse: materials per region, the
/// supports fixed, the joints tied, and the loads of the case beyond dead
/// weight, water and ground motion.
struct DamModel
{
  std::unique_ptr<fem::ElasticModel> fe;
  dolfinx::la::petsc::Matrix tie{nullptr, false};
  /// joints.model = "contact": the contact joints (tie: their modal stage).
  std::optional<ContactJoints> contact;
  std::int64_t joint_pairs = 0;
  std::vector<dolfinx::la::petsc::Vector> body_forces, tractions;
  dolfinx::la::petsc::Vector initial_velocity{nullptr, false};
  /// The loads as the analysis takes them (views of the vectors above).
  ModelLoads loads(const DamModelConfig& cfg) const;
};

/// Builds the model of the configuration's mesh. Collective.
DamModel dam_model(MPI_Comm comm, const DamModelConfig& cfg);

/// The linear analysis of the model, or the HTC concrete one in the dam
/// regions (material.model).
std::unique_ptr<SeismicAnalysis>
dam_model_seismic_analysis(DamModel& model, const DamModelConfig& cfg,
                           const RunFolder& folder);

/// Adds the model's entries to the summary, writes summary.json and the
/// plots; returns the summary.
nlohmann::json dam_model_results(MPI_Comm comm, const DamModelConfig& cfg,
                                 const DamModel& model, nlohmann::json summary,
                                 const std::filesystem::path& out_dir);
} // namespace damseis::analysis
