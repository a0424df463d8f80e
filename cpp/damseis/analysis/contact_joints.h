// What the linear and the concrete seismic analyses do alike with contact
// joints: the node pairs on the system's unknowns (P2: the vertex pairs,
// the midside nodes following their edges through u = P u_r), the closed
// (bonded) system of the modal stage, the joint recorders, and the joint
// outputs with the summary's "joints" entry.
#pragma once

#include "linear_seismic.h"
#include "seismic_system.h"
#include <damseis/engine/time_history.h>
#include <damseis/joint/contact_run.h>
#include <damseis/joint/joint_recorder.h>
#include <damseis/joint/joint_surfaces.h>
#include <dolfinx/la/petsc.h>
#include <memory>

namespace damseis::analysis
{
struct JointPairs
{
  /// The pairs contact acts at, their blocks in the system's numbering.
  joint::PairSet pairs;
  /// P2: the midside prolongation u = P u_r (null: P1, none).
  dolfinx::la::petsc::Matrix mpc{nullptr, false};
};

/// The pairs of `c` on fe's dofs; with P2, `sys` (assembled on all dofs)
/// is reduced to u = P u_r.
/// Prints the line "contact joints: ..." (and a warning with HHT alpha =
/// 0). Collective.
JointPairs set_up_joint_pairs(const fem::ElasticModel& fe,
                              const SeismicSettings& s, const ContactJoints& c,
                              SeismicSystem& sys);

/// The faces of the output settings as pair faces (the joint tables), the
/// blocks in the numbering of the pairs (`mpc`: P2's reduction, or null).
std::vector<joint::PairFace> joint_pair_faces(const fem::ElasticModel& fe,
                                              const SeismicSettings& s,
                                              Mat mpc);

/// The joint recorders of a time history with contact.
struct JointObservers
{
  std::unique_ptr<joint::JointRecorder> table;
  std::unique_ptr<joint::JointSurfaces> surfaces;
  /// Creates both (`w_static`: the pairs' w after the static stage) and
  /// adds them to `history`.
  void observe(engine::TimeHistory& history, const fem::ElasticModel& fe,
               const ContactJoints& c, const joint::ContactRun& run,
               const Eigen::VectorXd& w_static,
               const std::filesystem::path& dir, int output_every);
  /// The joint tables, the surfaces' envelopes and joint_static.csv; the
  /// summary's "joints" entry (`static_work`: the static stage's entries).
  nlohmann::json write(MPI_Comm comm, const std::filesystem::path& dir,
                       const std::vector<joint::PairFace>& faces,
                       const ContactJoints& c, const joint::PairSet& pairs,
                       const joint::StaticContactResult& st,
                       nlohmann::json static_work) const;
};
} // namespace damseis::analysis
