#include "contact_joints.h"
#include <algorithm>
#include <damseis/fem/facet_dofs.h>
#include <damseis/fem/prolongation.h>
#include <damseis/fem/tied_dofs.h>
#include <damseis/linalg/all_gather.h>
#include <damseis/linalg/petsc_vectors.h>
#include <damseis/results/progress.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>

namespace damseis::analysis
{
using dolfinx::la::petsc::Matrix;
using dolfinx::la::petsc::Vector;

JointPairs set_up_joint_pairs(const fem::ElasticModel& fe,
                              const SeismicSettings& s, const ContactJoints& c,
                              SeismicSystem& sys)
{
  MPI_Comm comm = fe.mesh()->comm();
  if (s.scheme.alpha == 0.0)
    results::warn(comm,
                  "time.hht_alpha = 0 with contact joints: with the "
                  "trapezoidal rule pairs that close and open do work "
                  "(energy.csv, joint_work_kj: two bars meeting gained 3.4 "
                  "times their energy); -0.1 damps it "
                  "(tests/demo/joint_patch_impact_checks.sh)");
  joint::PairSet all =
      joint::joint_pairs(*fe.V(), *c.facet_tags, c.joints, c.tolerance);
  // P2: the midside pairs follow their edges' vertex pairs (u = P u_r, P
  // in the role of a tie), contact acts at the vertex pairs.
  std::vector<std::size_t> vertex;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (!all.midside[i])
      vertex.push_back(i);
  JointPairs jp{joint::subset(all, vertex)};
  if (vertex.size() < all.size())
  {
    jp.mpc = Matrix(joint::midside_prolongation(*fe.V(), all), false);
    Mat P = jp.mpc.mat();
    sys.K = Matrix(fem::reduce_to_tied(sys.K.mat(), P), false);
    sys.M = Matrix(fem::reduce_to_tied(sys.M.mat(), P), false);
    for (Vector* f : {&sys.F_static, &sys.F_g})
    {
      Vector reduced = linalg::column_vector(sys.K.mat());
      MatMultTranspose(P, f->vec(), reduced.vec());
      *f = std::move(reduced);
    }
    // The pairs' nodes in the reduced numbering.
    for (auto* blocks : {&jp.pairs.block1, &jp.pairs.block2})
    {
      *blocks = fem::reduced_blocks(P, 3, *blocks);
      if (std::any_of(blocks->begin(), blocks->end(),
                      [](std::int64_t b) { return b < 0; }))
        throw std::logic_error("a vertex pair node is constrained");
    }
  }
  results::print(
      comm,
      "contact joints: " + std::to_string(c.joints.size()) + " joints, " +
          std::to_string(jp.pairs.size()) + " node pairs in contact" +
          (jp.mpc.mat() ? ", " + std::to_string(all.size() - jp.pairs.size()) +
                              " midside pairs following them"
                        : std::string()));
  return jp;
}

std::vector<joint::PairFace> joint_pair_faces(const fem::ElasticModel& fe,
                                              const SeismicSettings& s, Mat mpc)
{
  MPI_Comm comm = fe.mesh()->comm();
  std::vector<joint::PairFace> faces;
  const auto& tags = s.face_tags ? *s.face_tags : *fe.model().facet_tags;
  const auto& map = *fe.V()->dofmap()->index_map;
  for (const auto& [name, face_tags] : s.faces)
  {
    std::vector<std::int64_t> mine;
    for (int tag : face_tags)
      for (std::int32_t b : fem::owned_blocks_on(*fe.V(), tags, tag))
        mine.push_back(map.local_range()[0] + b);
    joint::PairFace f{name, linalg::all_gather(comm, mine)};
    if (mpc) // the pairs' blocks are in the reduced numbering
    {
      f.blocks = fem::reduced_blocks(mpc, 3, f.blocks);
      std::erase(f.blocks, -1); // midside nodes: not contact pairs
    }
    std::sort(f.blocks.begin(), f.blocks.end());
    faces.push_back(std::move(f));
  }
  return faces;
}

void JointObservers::observe(engine::TimeHistory& history,
                             const fem::ElasticModel& fe,
                             const ContactJoints& c,
                             const joint::ContactRun& run,
                             const Eigen::VectorXd& w_static,
                             const std::filesystem::path& dir, int output_every)
{
  table =
      std::make_unique<joint::JointRecorder>(run, w_static, c.history_points);
  history.observe(*table);
  surfaces = std::make_unique<joint::JointSurfaces>(
      *fe.V()->mesh(), *c.facet_tags, run, w_static, dir, output_every);
  history.observe(*surfaces);
}

nlohmann::json JointObservers::write(MPI_Comm comm,
                                     const std::filesystem::path& dir,
                                     const std::vector<joint::PairFace>& faces,
                                     const ContactJoints& c,
                                     const joint::PairSet& pairs,
                                     const joint::StaticContactResult& st,
                                     nlohmann::json static_work) const
{
  nlohmann::json j = table->write(comm, dir, faces);
  surfaces->write_envelope(table->largest_opening(), table->largest_sliding());
  j["static_stage"] = {{"dead_load", c.statics.cantilever_dead_load
                                         ? "cantilevers (joints disconnected)"
                                         : "joints active"},
                       {"increments", c.statics.increments}};
  j["static_stage"].update(static_work);
  j["static_stage"].update(joint::write_static_pairs(comm, dir, pairs, st));
  j["restitution"] = c.restitution;
  nlohmann::json gaps = nlohmann::json::object();
  for (const joint::JointSpec& spec : pairs.joints)
    if (spec.initial_gap > 0.0)
      gaps[spec.label] = spec.initial_gap;
  j["initial_gap_m"] = gaps;
  return j;
}
} // namespace damseis::analysis
