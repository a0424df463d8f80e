// Case keys of the 2D gravity-dam analysis (demo `koyna`) and their reading
// into a validated configuration (SI units).
#pragma once

#include <array>
#include <damseis/case/case.h>
#include <damseis/dynamics/newmark.h>
#include <damseis/fem/direct_solver.h>
#include <damseis/fem/elastic_model.h>
#include <damseis/geometry/gravity_dam.h>
#include <string>
#include <vector>

namespace damseis::analysis
{
/// One component of the ground acceleration on the analysis time grid.
struct GroundMotion
{
  bool active = false;
  std::vector<double> acceleration; ///< m/s2 at t_k = k dt, k = 0..steps
  std::string record;               ///< file it came from
  std::string description;
  double peak_g = 0.0; ///< target peak after scaling [g]
};

/// Everything the gravity-dam analysis needs, validated.
struct GravityDamConfig
{
  geometry::GravityDamSection section;
  int order = 2;
  fem::PlaneMode plane = fem::PlaneMode::plane_stress;
  fem::Material concrete;
  fem::Material rock; ///< foundation (massless: rho = 0)
  fem::Reservoir reservoir;
  bool westergaard = true;
  double gravity = 9.81;
  int modes = 6;
  double damping_ratio = 0.05;
  std::vector<std::int64_t> damping_modes = {1, 3};
  std::vector<double> damping_frequencies_hz; ///< overrides damping_modes
  dynamics::TimeScheme scheme;
  int steps = 0;
  GroundMotion horizontal, vertical;
  int output_every = 10;
  bool stress_total = true; ///< envelopes of total (static + seismic) stress
  std::array<double, 3> crest_point = {0, 103, 0};
  std::array<double, 3> base_point = {0, 0, 0};
  bool plots = true;
  fem::Factorization factorization = fem::Factorization::automatic;
};

/// The case keys with units, defaults (the paper's Koyna study) and bounds.
input::Schema gravity_dam_schema();

/// Reads and cross-checks the case, loads and scales the records. Throws
/// input::InputError (one line naming the file and key) for bad input.
GravityDamConfig read_gravity_dam_config(const input::Case& c);
} // namespace damseis::analysis
