// What the linear and the concrete seismic analysis assemble alike: the
// system on all dofs or on the tied unknowns of bonded joints (u = P u_r),
// its static loads, the dry mass of the modal stage, and the output folder.
#pragma once

#include "seismic_analysis.h"
#include "seismic_settings.h"
#include <damseis/fem/elastic_model.h>
#include <dolfinx/la/petsc.h>
#include <vector>

namespace damseis::analysis
{
struct SeismicSystem
{
  /// The reservoir whose Westergaard mass is in M, or null.
  const fem::Reservoir* added = nullptr;
  /// Stiffness and mass (with the added mass) on the system's unknowns.
  dolfinx::la::petsc::Matrix K{nullptr, false}, M{nullptr, false};
  /// The dead weight alone and all the static loads (dead weight,
  /// hydrostatic pressure, `static_loads`), on the system's unknowns.
  dolfinx::la::petsc::Vector F_g{nullptr, false}, F_static{nullptr, false};
};

/// Assembles the system of `fe` with the settings' reservoir and gravity;
/// with `tie`, P^T K P, P^T M P and P^T F. Collective.
SeismicSystem assemble_seismic_system(fem::ElasticModel& fe,
                                      const SeismicSettings& s,
                                      const std::vector<Vec>& static_loads,
                                      Mat tie);

/// The mass without the added mass on the system's unknowns (the dry
/// modes), or null when there is no added mass.
dolfinx::la::petsc::Matrix dry_mass(fem::ElasticModel& fe,
                                    const fem::Reservoir* added, Mat tie);

/// Creates the output folder and writes case_used.toml (rank 0): once every
/// input check has passed.
void open_run_folder(MPI_Comm comm, const RunFolder& folder);
} // namespace damseis::analysis
