// Case keys of the 3D arch-dam analysis (demo `arch_dam`): the geometry
// tables of geometry/arch_case, materials, joints, and the shared seismic
// keys; their reading into a validated configuration (SI units).
#pragma once

#include "concrete_settings.h"

#include "seismic_settings.h"
#include "wave_foundation.h"
#include <damseis/fem/elastic_model.h>
#include <damseis/geometry/arch_dam.h>
#include <damseis/input/case.h>
#include <damseis/joint/static_contact.h>
#include <map>
#include <optional>
#include <string>

namespace damseis::analysis
{
/// How contraction joints act (linear or HTC concrete).
enum class JointModel
{
  bonded,  ///< pairs tied: the monolithic dam
  contact, ///< Coulomb friction, no tension, impact correction
};

struct ArchDamConfig
{
  geometry::ArchDamDefinition geometry;
  int order = 2;
  fem::Material concrete; ///< the static elastic constants of the dam
  /// material.model: the linear engine, or HTC concrete (elastic, plastic,
  /// viscoplastic) with its parameters and dynamic factors.
  ConcreteSettings concrete_model;
  fem::Material rock; ///< massless foundation (rho = 0), or with mass
  /// Rock with mass and a viscous-spring boundary, the ground motion as
  /// vertically incident waves; none: massless, fixed far faces.
  std::optional<WaveFoundation> wave;
  /// foundation.boundary, and the multi-transmitting boundary's settings
  /// (its band is in geometry.mesh).
  FoundationBoundary boundary = FoundationBoundary::fixed;
  Transmitting transmitting;
  /// The rock's density with mass and the viscous-spring factors.
  double rock_rho = 2640.0;
  boundary::SpringFactors spring_factors{4.0 / 3.0, 2.0 / 3.0};
  /// study.foundation: the ratios E_f / E_d (empty: no study).
  std::vector<double> foundation_ratios;
  JointModel joints = JointModel::bonded;
  /// Contact joints: friction and shear keys per joint label, restitution,
  /// static stage.
  std::map<char, double> friction;
  std::string keyed; ///< labels of the keyed joints
  /// Bonds per joint label: tensile strength and cohesion [Pa].
  std::map<char, std::pair<double, double>> bonds;
  std::map<char, double> initial_gap; ///< [m] per joint
  double restitution = 1.0;
  joint::StaticContactSettings statics;
  std::vector<std::array<double, 3>> history_points;
  contact::NcpSettings ncp;
  SeismicSettings seismic;
  /// study.joints: the joint sets of a study, one run each ("none": no
  /// joints; else active labels such as "DGJ"); empty: one run.
  std::vector<std::string> study_joints;
  /// study.table1: elastic, plastic and viscoplastic at each of
  /// table1_levels (reservoir levels [m above the crown's base]).
  bool table1 = false;
  std::vector<double> table1_levels;
};

/// Ground-motion directions in 3D: x across the canyon, y along the river
/// (downstream), z vertical.
const std::vector<Direction>& arch_dam_directions();

input::Schema arch_dam_schema();

/// Throws input::InputError (one line naming the file and key).
ArchDamConfig read_arch_dam_config(const input::Case& c);

/// The configuration with rock of modulus E_f: massless with fixed far
/// faces (`fixed`), or with mass (rock_rho), a viscous-spring or a multi-
/// transmitting boundary and wave input, the dead weight then on the dam
/// only.
ArchDamConfig with_foundation(const ArchDamConfig& cfg, double E_f,
                              FoundationBoundary boundary);

/// The configuration of one run of a joint study: the joints of `set`
/// ("none": the dam without joints, bonded) active, the rest as `a`.
ArchDamConfig joint_study_case(const ArchDamConfig& a, const std::string& set);
/// Its subfolder: joints_0, joints_3_DGJ, ...
std::string joint_study_folder(const std::string& set);
/// The configuration with the reservoir at `level` [m above the crown's
/// base] (the mesh follows the water line).
ArchDamConfig with_reservoir_level(const ArchDamConfig& a, double level);
/// The labels of all candidate joint positions ("ABC...").
std::string candidate_labels(const ArchDamConfig& a);
} // namespace damseis::analysis
