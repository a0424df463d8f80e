#include "joint_surfaces.h"
#include <algorithm>
#include <cmath>
#include <damseis/geometry/coincident_points.h>
#include <dolfinx/mesh/Mesh.h>
#include <stdexcept>

namespace damseis::joint
{
namespace
{
/// The owned facets of `tags` whose value is side 2 of a joint of `pairs`.
std::vector<std::int32_t>
side2_facets(const dolfinx::mesh::Mesh& mesh,
             const dolfinx::mesh::MeshTags<std::int32_t>& tags,
             const PairSet& pairs)
{
  const int fdim = mesh.topology().dim() - 1;
  const std::int32_t owned = mesh.topology().index_map(fdim)->size_local();
  std::vector<std::int32_t> facets;
  for (std::size_t k = 0; k < tags.indices().size(); ++k)
  {
    const std::int32_t f = tags.indices()[k];
    const int value = tags.values()[k];
    const bool side2 =
        std::any_of(pairs.joints.begin(), pairs.joints.end(),
                    [&](const JointSpec& j) { return j.tag_side2 == value; });
    if (side2 && f < owned)
      facets.push_back(f);
  }
  std::sort(facets.begin(), facets.end());
  facets.erase(std::unique(facets.begin(), facets.end()), facets.end());
  return facets;
}

/// The pair at each node of `x` (3 coordinates per node): the pair whose
/// coordinates are within `tol`, -1 if none.
std::vector<std::int32_t> pairs_at(std::span<const double> x,
                                   const PairSet& pairs, double tol)
{
  const geometry::CoincidentPoints pair_points(
      pairs.size(), [&](std::size_t i) { return pairs.x[i]; }, tol);
  std::vector<std::int32_t> out(x.size() / 3);
  for (std::size_t node = 0; node < out.size(); ++node)
    out[node] = static_cast<std::int32_t>(pair_points.find(&x[3 * node]));
  return out;
}
} // namespace

JointSurfaces::JointSurfaces(
    const dolfinx::mesh::Mesh& mesh,
    const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags,
    const ContactRun& stepper, Eigen::VectorXd w_static,
    std::filesystem::path dir, int every)
    : _stepper(stepper), _w_static(std::move(w_static)), _dir(std::move(dir)),
      _every(std::max(every, 1))
{
  const PairSet& pairs = stepper.contact().pairs();
  const std::vector<std::int32_t> facets =
      side2_facets(mesh, facet_tags, pairs);
  auto sub =
      dolfinx::mesh::create_submesh(mesh, mesh.topology().dim() - 1, facets);
  _faces =
      std::make_shared<const dolfinx::mesh::Mesh>(std::move(std::get<0>(sub)));
  // Coincident nodes: the pairs' coordinates are the side-2 nodes' own.
  _pair_of_node = pairs_at(_faces->geometry().x(), pairs, 1e-6);
}

void JointSurfaces::begin(int first_step)
{
  const std::string name =
      first_step == 0
          ? std::string("joints.xdmf")
          : "joints_from_step" + std::to_string(first_step) + ".xdmf";
  _writer.emplace(_faces, _dir / name, true);
}

std::vector<double>
JointSurfaces::at_nodes(const std::function<double(std::size_t)>& value) const
{
  std::vector<double> v(_pair_of_node.size(), 0.0);
  for (std::size_t node = 0; node < v.size(); ++node)
    if (_pair_of_node[node] >= 0)
      v[node] = value(static_cast<std::size_t>(_pair_of_node[node]));
  return v;
}

void JointSurfaces::record(int k, double t)
{
  if (k % _every != 0)
    return;
  const CondensedContact& c = _stepper.contact();
  const Eigen::VectorXd& w = c.relative_displacement();
  _writer->point_field(
      "opening_cm",
      at_nodes([&](std::size_t i) { return 100.0 * std::max(c.gap(i), 0.0); }),
      1);
  _writer->point_field("sliding_cm",
                       at_nodes(
                           [&](std::size_t i)
                           {
                             return 100.0 * (w.segment<2>(3 * i + 1) -
                                             _w_static.segment<2>(3 * i + 1))
                                                .norm();
                           }),
                       1);
  _writer->point_field("state_stick0_slip1_open2",
                       at_nodes(
                           [&](std::size_t i)
                           {
                             switch (c.states()[i])
                             {
                             case contact::PairState::stick:
                               return 0.0;
                             case contact::PairState::slip:
                               return 1.0;
                             default:
                               return 2.0;
                             }
                           }),
                       1);
  _writer->write(t);
}

void JointSurfaces::write_envelope(const std::vector<double>& opening,
                                   const std::vector<double>& sliding) const
{
  results::XdmfWriter envelope(_faces, _dir / "joint_envelope.xdmf", false);
  envelope.point_field(
      "max_opening_cm",
      at_nodes([&](std::size_t i) { return 100.0 * opening[i]; }), 1);
  envelope.point_field(
      "max_sliding_cm",
      at_nodes([&](std::size_t i) { return 100.0 * sliding[i]; }), 1);
  envelope.write();
}
} // namespace damseis::joint
