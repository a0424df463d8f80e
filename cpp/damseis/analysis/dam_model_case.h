// Case keys of `dam_model`, the analysis of the user's own mesh: the mesh
// file, its physical groups mapped to roles (material regions, supports,
// reservoir-wetted faces, joints, loaded faces, output faces), loads beyond
// ground motion (tractions with a time history, body forces, initial
// velocity), histories at named points, and the shared seismic keys.
#pragma once

#include "concrete_settings.h"
#include "joint_contact_keys.h"
#include "seismic_settings.h"
#include "wave_foundation.h"
#include <array>
#include <damseis/fem/elastic_model.h>
#include <damseis/geometry/mesh_file.h>
#include <damseis/input/case.h>
#include <damseis/joint/static_contact.h>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace damseis::analysis
{
/// A region of cells (a physical group of the mesh's top dimension) and
/// its material.
struct Region
{
  std::string group;
  fem::Material material; ///< rho = 0: massless
  bool dam = false;       ///< part of the dam (envelopes, crest)
};

/// A vector quantity on a physical group (traction [Pa], body force
/// [N/m3], initial velocity [m/s]); components beyond the mesh's dimension
/// are zero.
struct GroupVector
{
  std::string group;
  std::array<double, 3> value = {0, 0, 0};
};

/// joints.model = "contact": the laws of the joints and the static stage.
struct JointContactConfig
{
  bool enabled = false;
  std::vector<double> friction; ///< per joint
  std::vector<bool> keyed;      ///< per joint
  JointConditions joint;        ///< bonds and gaps per joint
  double restitution = 1.0;
  joint::StaticContactSettings statics;
  std::vector<std::array<double, 3>> history_points;
  contact::NcpSettings ncp;
};

struct DamModelConfig
{
  /// The mesh, read and checked (collective; every rank holds its part).
  /// Its facet tags are renumbered for the model (facet_tag()); the
  /// groups' own tags stay in `group_facets`.
  std::shared_ptr<geometry::MeshFile> mesh;
  std::shared_ptr<const dolfinx::mesh::MeshTags<std::int32_t>> group_facets;
  /// Distance of coincident joint nodes [m] (the joint check's).
  double joint_tolerance = 1e-8;
  std::filesystem::path mesh_file;
  int dim = 2;
  int order = 2;
  fem::PlaneMode plane = fem::PlaneMode::plane_strain;
  std::vector<Region> regions;
  std::vector<std::string> fixed; ///< facet groups with every dof fixed
  /// Facet groups of a viscous-spring boundary (instead of `fixed`), and
  /// the foundation it makes (rock with mass, wave input).
  std::vector<std::string> viscous_spring;
  /// Facet groups of a multi-transmitting boundary (instead of `fixed`;
  /// fixed in the static and modal stages).
  std::vector<std::string> transmitting;
  std::optional<WaveFoundation> wave;
  std::vector<std::string> wetted; ///< facet groups the reservoir wets
  std::vector<std::string> floor;  ///< reservoir floor (reservoir.load_floor)
  /// Joints: (side 1, side 2) facet groups of duplicated nodes; tied, or
  /// contact joints.
  std::vector<std::pair<std::string, std::string>> joints;
  JointContactConfig contact;
  std::vector<GroupVector> tractions;   ///< times traction_history
  std::vector<double> traction_history; ///< per step, starting at 0
  std::string traction_history_kind;    ///< "step", "pulse", "static" or a file
  std::vector<GroupVector> body_forces; ///< static, with the dead weight
  std::vector<GroupVector> initial_velocity;
  /// Facet groups whose stress envelopes are tabulated (face_<group>.csv).
  std::vector<std::string> faces;
  /// Named points where displacement, velocity and acceleration are
  /// recorded (histories.csv).
  std::vector<std::pair<std::string, std::array<double, 3>>> history_points;
  SeismicSettings seismic;
  /// material.model and the concrete of the dam regions (linear: the
  /// linear analysis).
  ConcreteSettings concrete;
};

/// Ground-motion components along the mesh axes x, y and z (the last axis
/// of the mesh is vertical).
const std::vector<Direction>& dam_model_directions();

input::Schema dam_model_schema();

/// Reads the keys and the mesh (collective on MPI_COMM_WORLD) and checks
/// them together: every group named exists with the right dimension, every
/// cell has a material, joint sides match node for node, no degenerate
/// cell. Throws input::InputError (one line naming the file and key or
/// group).
DamModelConfig read_dam_model_config(const input::Case& c);

/// The highest and the lowest vertex of the cells with these tags (their
/// last coordinate is the elevation), the same on every rank. Collective.
std::array<std::array<double, 3>, 2>
extreme_vertices(const geometry::Model& model, const std::set<int>& regions);

/// supports.viscous_spring or supports.transmitting: the rock (every
/// region but the dam's, one material with mass), the spring factors or
/// the formula and its band, the scattering centre, the model's bottom and
/// the dam's lowest point as the reference surface
/// (dam_model_foundation.cpp). Throws input::InputError.
void read_wave_foundation(const input::Case& c, DamModelConfig& cfg);

/// The tag a facet group of the configuration carries in its model's facet
/// tags (the wetted faces and the floor take the tags the compiled forms
/// integrate over; the others their own number shifted by 1000).
int facet_tag(const DamModelConfig& cfg, const std::string& group);
} // namespace damseis::analysis
