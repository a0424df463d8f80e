// Case keys of the 2D gravity-dam analysis (demo `koyna`) and their reading
// into a validated configuration (SI units).
#pragma once

#include "concrete_settings.h"
#include "seismic_settings.h"
#include "wave_foundation.h"
#include <damseis/fem/elastic_model.h>
#include <damseis/fem/gravity_dam_loads.h>
#include <damseis/geometry/gravity_dam.h>
#include <damseis/input/case.h>
#include <optional>

namespace damseis::analysis
{
/// Everything the gravity-dam analysis needs, validated.
struct GravityDamConfig
{
  geometry::GravityDamSection section;
  int order = 2;
  fem::PlaneMode plane = fem::PlaneMode::plane_stress;
  /// Static elastic constants of the dam concrete (the model's E is
  /// concrete_model.params.E, with its dynamic factor).
  fem::Material concrete;
  fem::Material rock; ///< foundation (massless: rho = 0)
  /// A foundation with mass and a viscous-spring boundary (the seismic
  /// input as vertically incident waves), or none (massless, fixed at its
  /// far boundary).
  std::optional<WaveFoundation> wave;
  /// foundation.boundary, and the multi-transmitting boundary's settings
  /// (used with boundary = mtf).
  FoundationBoundary boundary = FoundationBoundary::fixed;
  Transmitting transmitting;
  /// The rock's density with mass and the viscous-spring factors (used
  /// with a viscous-spring boundary).
  double rock_rho = 2640.0;
  /// The second rock region's modulus (a split block: the right half or
  /// the lower layer).
  double rock_E2 = 30e9;
  /// study.table6_inhomogeneous: the paper's cases 4 and 5 after the
  /// ratios.
  bool table6_inhomogeneous = false;
  boundary::SpringFactors spring_factors{1.0, 0.5};
  /// study.table6: the foundation models side by side for these ratios
  /// Ef / Ed (empty: no study).
  std::vector<double> table6_ratios;
  SeismicSettings seismic;
  /// Dam concrete model (linear engine or HTC elastic/plastic/viscoplastic)
  /// with the dynamic factors of that model.
  ConcreteSettings concrete_model;
  /// Run elastic, plastic and viscoplastic and write table1.csv/.md.
  bool table1 = false;
  /// Silt on the upstream face (level 0: none) and uplift on the base.
  fem::Silt silt;
  bool uplift_on = false;
  fem::Uplift uplift;
  /// Write the gmsh mesh as model.msh in the output folder.
  bool write_mesh_file = false;
};

/// Ground-motion directions of a 2D section: x horizontal, y vertical.
const std::vector<Direction>& gravity_dam_directions();

/// The case keys with units, defaults (the paper's Koyna study) and bounds.
input::Schema gravity_dam_schema();

/// Reads and cross-checks the case, loads and scales the records. Throws
/// input::InputError (one line naming the file and key) for bad input.
GravityDamConfig read_gravity_dam_config(const input::Case& c);

/// The configuration with a foundation block of modulus E_f: massless and
/// fixed at its far boundary, or with mass (cfg.rock_rho), a viscous-
/// spring or a multi-transmitting boundary (cfg.transmitting; the mesh
/// needs its band: cfg.section.band_layers) and wave input, the dead
/// weight then on the dam only.
GravityDamConfig with_foundation(const GravityDamConfig& cfg, double E_f,
                                 FoundationBoundary boundary);
} // namespace damseis::analysis
