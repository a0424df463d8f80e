// The seismic analysis of a 3D arch dam (demo `arch_dam`), in the pieces
// its main.cpp composes: the model, the analysis (linear with bonded or
// contact joints, or HTC concrete with bonded joints), the results.
#pragma once

#include "arch_dam_case.h"
#include "linear_seismic.h"
#include "seismic_analysis.h"
#include <damseis/fem/elastic_model.h>
#include <damseis/geometry/arch_mesh.h>
#include <dolfinx/la/petsc.h>
#include <filesystem>
#include <functional>
#include <memory>
#include <mpi.h>
#include <nlohmann/json.hpp>
#include <optional>

namespace damseis::analysis
{
/// An arch dam ready to analyse: dam, canyon and foundation meshed, the
/// materials, the foundation fixed on its far boundaries, the joints tied
/// (bonded: u = P u_r), and the seismic settings with the singular lines
/// where the faces meet the rock.
struct ArchDamModel
{
  geometry::ArchModel mesh;
  std::unique_ptr<fem::ElasticModel> fe;
  dolfinx::la::petsc::Matrix tie{nullptr, false};
  /// joints.model = "contact": the contact joints (tie: their modal stage).
  std::optional<ContactJoints> contact;
  /// foundation.boundary = "viscous_spring": rock with mass, wave input.
  std::optional<WaveFoundation> wave;
  SeismicSettings seismic;
  /// The dam's concrete (material.model) and the elastic materials per
  /// region (the dam's E that of its model, with its dynamic factor).
  ConcreteSettings concrete;
  std::map<int, fem::Material> materials;
};

/// Prints the size estimate, meshes (gmsh, rank 0) and builds the model.
ArchDamModel arch_dam_model(MPI_Comm comm, const ArchDamConfig& cfg);

/// The analysis of the model: linear (joints bonded, or in contact), or
/// with HTC concrete in the dam (bonded joints).
std::unique_ptr<SeismicAnalysis>
arch_dam_seismic_analysis(ArchDamModel& model, const RunFolder& folder);

/// Adds the dam's entries to the summary, writes summary.json and the plots
/// (with the model's pictures: model.xdmf, mesh_model.png, mesh_joints.png);
/// returns the summary.
nlohmann::json arch_dam_results(MPI_Comm comm, const ArchDamConfig& cfg,
                                const ArchDamModel& model,
                                nlohmann::json summary,
                                const std::filesystem::path& out_dir);
/// One analysis of a study: the configuration, into its folder.
using ArchDamRun = std::function<nlohmann::json(const ArchDamConfig&,
                                                const std::filesystem::path&)>;

/// study.table1 (the paper's section I): the elastic, plastic and
/// viscoplastic concrete at each reservoir level of the study, into
/// level_<m>/<model> (one level: <model>), then table1.csv and table1.md.
/// Returns the last run's summary.
nlohmann::json run_arch_table1_study(MPI_Comm comm, const ArchDamConfig& cfg,
                                     const std::filesystem::path& out_dir,
                                     const ArchDamRun& analyse);
} // namespace damseis::analysis
