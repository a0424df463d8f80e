// The seismic analysis of a 2D gravity-dam section (demos `koyna` and
// `rcc_gravity`), in the pieces their main.cpp composes: the model, the
// analysis (linear, or HTC concrete), the results, and the study that runs
// the three concrete models for a Table 1.
#pragma once

#include "gravity_dam_case.h"
#include "seismic_analysis.h"
#include <damseis/fem/elastic_model.h>
#include <dolfinx/la/petsc.h>
#include <filesystem>
#include <functional>
#include <memory>
#include <mpi.h>
#include <nlohmann/json.hpp>

namespace damseis::analysis
{
/// A gravity-dam section ready to analyse: the mesh with its materials
/// and supports (rigid base, or massless foundation fixed on its far
/// boundaries), and the static loads besides dead weight and water.
struct GravityDamModel
{
  std::unique_ptr<fem::ElasticModel> fe;
  std::vector<dolfinx::la::petsc::Vector> silt_and_uplift;
  std::vector<Vec> static_loads() const;
};

/// Meshes the section (gmsh, rank 0) and builds its model; with
/// output.mesh_file the gmsh model is written to out_dir/model.msh.
GravityDamModel gravity_dam_model(MPI_Comm comm, const GravityDamConfig& cfg,
                                  const std::filesystem::path& out_dir);

/// The linear analysis, or the HTC concrete one (config material.model).
std::unique_ptr<SeismicAnalysis>
gravity_dam_seismic_analysis(GravityDamModel& model,
                             const GravityDamConfig& cfg,
                             const RunFolder& folder);

/// Adds the section's entries to the summary, writes summary.json and the
/// plots; returns the summary.
nlohmann::json gravity_dam_results(MPI_Comm comm, const GravityDamConfig& cfg,
                                   nlohmann::json summary,
                                   const std::filesystem::path& out_dir);

/// One analysis of a configuration into a folder; returns its summary.
using GravityDamRun = std::function<nlohmann::json(
    MPI_Comm, const GravityDamConfig&, const RunFolder&)>;

/// Prints the size estimate, then runs `analyse` once, or with
/// study.table1 once per concrete model (elastic, plastic, viscoplastic)
/// into subfolders and writes table1.csv and table1.md. Returns the
/// (last) summary.
nlohmann::json run_gravity_dam_study(MPI_Comm comm,
                                     const GravityDamConfig& config,
                                     const std::filesystem::path& out_dir,
                                     const std::string& case_text,
                                     const GravityDamRun& analyse);

/// The study with every phase of each analysis in order (what the demos'
/// main.cpp spell out).
nlohmann::json run_gravity_dam_analysis(MPI_Comm comm,
                                        const GravityDamConfig& config,
                                        const std::filesystem::path& out_dir,
                                        const std::string& case_text);
} // namespace damseis::analysis
