// The arch and cantilever stresses of a 3D dam's faces (the normal
// stresses along the face's horizontal and across it,
// results/face_directions.h) at the faces' stress points, their envelopes
// over the time history: face_<name>_arch_cantilever.csv and the largest
// values per face in the summary.
#pragma once

#include "recorders.h"
#include "seismic_settings.h"
#include <damseis/results/direction_envelope.h>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace damseis::analysis
{
class FaceDirectionRecorder : public engine::Observer
{
public:
  /// The faces of `s` (names, tags), their stress points `points` (as
  /// results::face_points gives them, per face); reads the stress of the
  /// step from `stresses` (observe it after that recorder).
  FaceDirectionRecorder(const dolfinx::fem::FunctionSpace& S,
                        const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags,
                        const SeismicSettings& s,
                        const std::vector<std::vector<std::int32_t>>& points,
                        const StressRecorder& stresses);
  void record(int k, double t) override;
  void save(engine::Arrays& arrays) const override;
  void restore(const engine::CheckpointData& data) override;
  /// face_<name>_arch_cantilever.csv per face (rank 0; MPa) and, per face,
  /// the largest arch and cantilever tension and compression over the
  /// points farther than s.singular_radius from the singular points;
  /// `joint_sides` (may be empty): per face and point, a column joint_side
  /// as in write_face_csv. Collective.
  nlohmann::json
  write(MPI_Comm comm, const SeismicSettings& s,
        const std::filesystem::path& dir,
        const std::vector<std::vector<std::int8_t>>& joint_sides = {}) const;

private:
  const StressRecorder& _stresses;
  std::vector<std::string> _names;
  std::vector<results::DirectionEnvelope> _envelopes;
};
} // namespace damseis::analysis
