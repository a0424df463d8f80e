// The joints as surfaces for ParaView: the side-2 faces of the contact
// joints as a triangle mesh whose nodes carry their pair's opening and
// sliding [cm] and state (0 stick, 1 slip, 2 open) - a time series
// joints.xdmf at the output steps of fields.xdmf, and joint_envelope.xdmf
// with the largest opening and sliding over the record. The side-1 faces
// coincide with them, so one face shows the joint. A node of a joint face
// that is no pair (where the joint meets bonded material) holds 0: it
// neither opens nor slides.
#pragma once

#include "contact_run.h"
#include <damseis/engine/parts.h>
#include <damseis/results/xdmf_writer.h>
#include <dolfinx/mesh/MeshTags.h>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace damseis::joint
{
class JointSurfaces : public engine::Observer
{
public:
  /// The faces: the facets of `facet_tags` (the model's) tagged as side 2
  /// of the stepper's joints. Sliding is measured from `w_static` (3 per
  /// pair), as in JointRecorder; output every `every` steps into `dir`.
  /// Collective.
  JointSurfaces(const dolfinx::mesh::Mesh& mesh,
                const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags,
                const ContactRun& stepper, Eigen::VectorXd w_static,
                std::filesystem::path dir, int every);
  /// Opens joints.xdmf (a restart: joints_from_step<k>.xdmf).
  void begin(int first_step) override;
  /// The opening, sliding and state of step k, every `every` steps.
  void record(int k, double t) override;
  /// joint_envelope.xdmf: per node its pair's largest opening and sliding
  /// (`opening`, `sliding`: per pair, in m). Collective.
  void write_envelope(const std::vector<double>& opening,
                      const std::vector<double>& sliding) const;

private:
  /// One value per local node of the faces: value(i) of the node's pair
  /// i, 0 where the node is no pair.
  std::vector<double>
  at_nodes(const std::function<double(std::size_t)>& value) const;

  std::shared_ptr<const dolfinx::mesh::Mesh> _faces;
  std::vector<std::int32_t> _pair_of_node; ///< per local node; -1: no pair
  const ContactRun& _stepper;
  Eigen::VectorXd _w_static;
  std::filesystem::path _dir;
  int _every;
  std::optional<results::XdmfWriter> _writer;
};
} // namespace damseis::joint
