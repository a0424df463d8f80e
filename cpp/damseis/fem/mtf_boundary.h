// Liao's multi-transmitting formula (boundary::MultiTransmittingFormula) on
// the nodes of a mesh's artificial boundary (algorithms.md 3.3-3.4): each
// boundary node x_0 with outward normal nu reads the field at the points
// x_k = x_0 - k dx nu (k = 0..2N) of the band along the normal (dx the node
// spacing), interpolated in the band's cells (where the band is
// structured along the normal, as the meshes make it for P1, x_k is a node
// and its value is read alone; on P2 tetrahedra of sheared hexahedra the
// points between the layers are not all nodes), and its displacement at
// the next step is
//   u_0^(p+1) = u_in(x_0, t_(p+1)) + MTF[u - u_in],
// and its velocity and acceleration the same formula's on v and a (the
// formula is linear with constant coefficients: it transmits the time
// derivatives of what it transmits; Newmark's relations would derive them
// from the displacements with an undamped alternating mode, see
// dynamics::PrescribedMotion),
// the formula applied to each Cartesian component of the field less the
// known one, with the artificial speed c_p for the part along the normal
// and c_s for the tangential part (waves leaving at normal incidence are P
// in the one, S in the other), and the known field (wave-field
// separation): at the bottom the incident wave alone
// (the down-going reflection must leave through it), on the sides the free
// field. Nodes on the bottom and a side (corners) belong to the bottom; a
// node on two sides (3D vertical edges) marches along the side's normal
// that comes first in lexicographic order. Order 1 or 2 (the history is
// the last two states). A node's boundary facets and band cells may lie
// on other ranks than the node's owner: the set-up sees every rank's; the
// stencils' values are gathered with a PETSc scatter.
#pragma once

#include <algorithm>
#include <array>
#include <damseis/boundary/free_field.h>
#include <damseis/boundary/mtf.h>
#include <damseis/dynamics/partitioned_newmark.h>
#include <dolfinx/fem/FunctionSpace.h>
#include <dolfinx/mesh/MeshTags.h>
#include <functional>
#include <petscvec.h>
#include <string>
#include <vector>

namespace damseis::fem
{
struct MtfSettings
{
  int order = 2;        ///< N, 1 or 2
  double drift = 0.0;   ///< gamma_d (b = 1 / (1 + gamma_d))
  double spacing = 0.0; ///< dx: node spacing along the normals [m]
  /// Artificial speeds c_a [m/s] of the normal and the tangential part.
  double speed_normal = 0.0, speed_tangential = 0.0;
  double dt = 0.0; ///< time step [s]
  /// The larger s = c_a dt / dx, which must lie in (0, 1].
  double courant() const
  {
    return std::max(speed_normal, speed_tangential) * dt / spacing;
  }
};

/// The known field of the wave-field separation at x (the last coordinate
/// vertical) and time t: at the bottom (bottom = true) the incident wave,
/// on the sides the free field (its displacement, velocity and
/// acceleration are read).
using KnownField = std::function<boundary::FreeFieldState(
    const std::array<double, 3>& x, bool bottom, double t)>;

/// Whether the cells `band_cells` hold every stencil point of Liao's
/// formula of `order` with node spacing `spacing` at the nodes of V on the
/// facets tagged `boundary_tags` (as MtfBoundary reads them): empty if so,
/// else one line naming the first point missing (the same on every rank).
/// Collective.
std::string band_gap(const dolfinx::fem::FunctionSpace& V,
                     const dolfinx::mesh::MeshTags<std::int32_t>& facets,
                     const std::vector<int>& boundary_tags,
                     const std::vector<std::int32_t>& band_cells, int order,
                     double spacing);

class MtfBoundary : public dynamics::PrescribedMotion
{
public:
  /// The nodes of V on the facets tagged `boundary_tags`, their stencils
  /// among the nodes of `band_cells` (local cells; the structured band).
  /// Throws std::invalid_argument (one line) if a stencil point lies in no
  /// band cell (the band is too thin) or s is outside (0, 1]. Collective.
  MtfBoundary(const dolfinx::fem::FunctionSpace& V,
              const dolfinx::mesh::MeshTags<std::int32_t>& facets,
              const std::vector<int>& boundary_tags,
              const std::vector<std::int32_t>& band_cells, MtfSettings s,
              KnownField known);
  ~MtfBoundary();
  MtfBoundary(const MtfBoundary&) = delete;
  MtfBoundary& operator=(const MtfBoundary&) = delete;

  const std::vector<PetscInt>& rows() const override { return _rows; }
  void values(int n_next, const dynamics::Kinematics& now,
              const dynamics::Kinematics& prev,
              dynamics::PrescribedValues& out) override;
  /// The number of boundary nodes (all ranks) and of them on the bottom.
  std::array<std::int64_t, 2> node_counts() const { return _counts; }
  const MtfSettings& settings() const { return _s; }

  /// A boundary node: its coordinates, the outward normal its stencil
  /// marches against, whether it is on the bottom.
  struct Node
  {
    std::array<double, 3> x, normal;
    bool bottom;
  };

private:
  /// The formula for the normal and for the tangential part.
  boundary::MultiTransmittingFormula _normal, _tangential;
  MtfSettings _s;
  KnownField _known;
  int _dim;
  std::vector<Node> _nodes; ///< owned boundary nodes
  std::vector<PetscInt> _rows;
  /// The stencil's values: per node and k = 0..2N (CSR by _offsets), the
  /// positions in the gathered buffers (the components following) and the
  /// weights that interpolate u at x_k (one node of weight 1 where x_k is
  /// a node).
  std::vector<std::int32_t> _offsets, _positions;
  std::vector<double> _weights;
  std::array<std::int64_t, 2> _counts{};
  VecScatter _scatter = nullptr;
  /// The stencils' gathered u, v, a at step n and n - 1.
  std::array<Vec, 6> _gathered{};
};
} // namespace damseis::fem
