// Seismic input as a wave (the absolute formulation of a foundation with
// mass and a viscous-spring boundary): the free field of vertically
// incident waves (boundary::VerticalFreeField) enters through the loads
// that make it an exact solution of the truncated model without the dam
// (algorithms.md 3.6),
//   f(t) = F + K_b u_ff + C_b v_ff + T sigma_ff        (boundary)
//            + (a_M M + b_K K) v_ff                     (all nodes),
// (with a transmitting boundary's band, + b_E K_E v_ff as well),
// the last term so that the Rayleigh damping acts on the motion relative to
// the free field (the scattered field), not on the incident wave, which
// would otherwise be damped on its way up: C (v - v_ff). On a rigid
// foundation (v_ff uniform, K v_ff = 0) this is the relative formulation's
// damping of the massless-foundation model. Each node's column has its
// own free surface, the ground above it (geometry::GroundSurface: the
// valley floor, the rock under the dam, the plateau beyond a canyon); above
// it (the dam) the free field is the surface's motion.
#pragma once

#include <damseis/boundary/free_field.h>
#include <damseis/dynamics/newmark.h>
#include <damseis/engine/parts.h>
#include <damseis/fem/elastic_model.h>
#include <damseis/fem/viscous_boundary.h>
#include <damseis/geometry/ground_surface.h>
#include <dolfinx/la/petsc.h>
#include <vector>

namespace damseis::analysis
{
class FreeFieldLoad : public engine::DynamicLoad
{
public:
  /// `b`: the viscous-spring boundary, or null (a transmitting boundary
  /// prescribes its nodes: then only the damping's term, at every node).
  /// M and K: the system's (K with the boundary's springs), on the
  /// system's unknowns: all dofs, or with `tie` (bonded joints) the tied
  /// unknowns u = P u_r; `damping`: the Rayleigh damping of C = a_M M +
  /// b_K K (+ the dashpots). `sustained`: a load held through the run
  /// (copied, system layout), or null. The matrices must outlive the load.
  FreeFieldLoad(const fem::ElasticModel& fe, const fem::ViscousBoundary* b,
                const geometry::GroundSurface& ground,
                std::shared_ptr<const boundary::FreeField> field, Mat M, Mat K,
                dynamics::RayleighDamping damping, double dt, Mat tie = nullptr,
                Vec sustained = nullptr);
  /// A further stiffness-proportional damping b K_extra in C (the
  /// explicit band's own, dynamics::PartitionedNewmark): its force on
  /// the free field's velocity joins the load. K_extra must outlive the
  /// load.
  void add_stiffness_damping(Mat K_extra, double b)
  {
    _K_extra = K_extra;
    _b_extra = b;
  }
  void assemble(int k, Vec f) const override;
  /// Zero: the free field starts at rest.
  void initial_acceleration(Vec a) const override;
  const boundary::FreeField& field() const { return *_field; }
  /// Wall time spent assembling the load so far [s].
  double seconds() const { return _seconds; }

private:
  std::shared_ptr<const boundary::FreeField> _field;
  Mat _M, _K, _tie, _K_extra = nullptr;
  dynamics::RayleighDamping _damping;
  double _b_extra = 0.0;
  double _dt;
  int _dim;
  mutable double _seconds = 0.0;
  dolfinx::la::petsc::Matrix _Kb{nullptr, false}, _Cb{nullptr, false},
      _T{nullptr, false};
  dolfinx::la::petsc::Vector _sustained{nullptr, false};
  /// Owned nodes: the vertical coordinate of each, its ground, whether it
  /// is fixed, and the owned nodes on the boundary.
  std::vector<std::array<double, 3>> _x;
  std::vector<double> _z_ground;
  std::vector<std::int8_t> _fixed;
  std::vector<std::int32_t> _boundary;
  /// Work vectors: the free field's u, v, stresses on the boundary and v
  /// at every node.
  dolfinx::la::petsc::Vector _u_b{nullptr, false}, _v_b{nullptr, false},
      _s_b{nullptr, false}, _v_all{nullptr, false}, _f_full{nullptr, false};
  /// With ties: P with the rows of constrained dofs (more than one entry)
  /// zeroed, the velocity on the tied unknowns, the number of dofs each
  /// takes its value from, a work vector of the system's layout.
  dolfinx::la::petsc::Matrix _pick{nullptr, false};
  dolfinx::la::petsc::Vector _v_r{nullptr, false}, _count{nullptr, false},
      _work{nullptr, false};
};
} // namespace damseis::analysis
