// The nonlinear (HTC viscoplastic) concrete of a 2D dam model: material
// state at the quadrature points, its update by the return map for a trial
// displacement, and the internal force and consistent tangent assembled from
// the point values (forms/plasticity_2d.py).
#pragma once

#include "elastic_model.h"
#include <array>
#include <cmath>
#include <damseis/material/concrete.h>
#include <dolfinx/fem/Expression.h>
#include <dolfinx/la/petsc.h>
#include <functional>
#include <map>
#include <memory>
#include <span>
#include <vector>

namespace damseis::fem
{
/// Counts of one material update.
struct MaterialUpdateStats
{
  std::int64_t points = 0;    ///< points updated (owned cells, all ranks)
  std::int64_t inelastic = 0; ///< points with an active return map
  std::int64_t failed = 0;    ///< points whose local Newton did not converge
  /// points that needed the sub-stepping fall-back (each costs up to 55
  /// single-step return maps: the composite tangent by central differences;
  /// 0 unless a material's max_substeps > 1, which ConcreteModel no longer
  /// sets)
  std::int64_t substepped = 0;
  /// single-step return maps (integrate() calls; plane stress: one per
  /// iteration on sigma_zz = 0) and their local Newton iterations, at the
  /// points that left the elastic fast path
  std::int64_t return_maps = 0, local_iterations = 0;
  /// points that left the elastic fast path (owned, all ranks), and the
  /// seconds their updates took (summed over ranks: core-seconds)
  std::int64_t returned_points = 0;
  double return_map_seconds = 0.0;
  int max_iterations = 0; ///< largest local Newton count
};

/// Material state at the quadrature points of a 2D or 3D model.
///
/// Every region gets an HtcConcrete: the regions listed in `concrete` use
/// those parameters (their `mode` selects elastic / plastic / viscoplastic),
/// all others stay linear elastic with the ElasticModel's material (given
/// again in `elastic`). The crack-band width of a cell is h = sqrt(2 A) in
/// 2D (the side of the square that two right triangles of area A make) and
/// h = (6 V)^(1/3) in 3D (the edge of the cube that six tetrahedra of
/// volume V make): exact for a band of such elements across a structured
/// mesh. It is rounded to 1% bins so that cells of similar size share a
/// material object (the energy error of the rounding is below 0.5%).
///
/// The stress and tangent coefficients have the components of the forms:
/// (xx, yy, xy) in 2D, (xx, yy, zz, xy, yz, xz) in 3D (components()).
/// 2D plane strain: eps_zz = 0. Plane stress: eps_zz is solved per point by
/// Newton on sigma_zz = 0 (the tangent is condensed accordingly). In 3D
/// `plane` is ignored.
///
/// Static steps (dt = 0) use the rate-independent version of each material
/// (R = 1, as algorithms.md 6.4 asks for the static stage).
class ConcreteModel
{
public:
  ConcreteModel(ElasticModel& fe,
                const std::map<int, material::ConcreteParameters>& concrete,
                const std::map<int, Material>& elastic, PlaneMode plane);

  ElasticModel& elastic_model() { return _fe; }
  /// Stress components of the coefficients: 3 in 2D (xx, yy, xy), 6 in 3D.
  int components() const { return _nc; }

  /// Updates the trial state for the displacement `u` (a Function on V with
  /// ghosts up to date) reached over the time step `dt` (0: static) from
  /// the committed state; fills the stress and tangent coefficients.
  /// Collective (reduces the counts).
  MaterialUpdateStats update(const dolfinx::fem::Function<double>& u,
                             double dt);
  /// Makes the trial state the committed state (strain rates from dt).
  /// After an extrapolated (IMPL-EX) trial, first runs the implicit return
  /// map at the trial's strains (its counts into `implicit`); false, with
  /// the committed state untouched, if a point fails there.
  bool accept(MaterialUpdateStats* implicit = nullptr);

  /// IMPL-EX integration (Oliver, Huespe & Cante 2008, CMAME 197) of the
  /// dynamic steps: the stress that enters the internal force of a trial is
  /// extrapolated from the committed state with the plastic strain
  /// increment of the last step, sigma~ = sigma_n + D (d_eps - r d_eps_p,n),
  /// r = dt / dt_n, linear in u with the elastic tangent; the implicit
  /// return map updates the state in accept() (and gives the reported
  /// stress). Every dynamic step is then one linear solve with the initial
  /// matrix. Static steps (dt = 0) stay implicit.
  void set_implex(bool on) { _implex = on; }
  /// True if the last trial was extrapolated (its tangent is elastic).
  bool trial_extrapolated() const { return _implex && _trial_dt > 0.0; }

  /// Internal force of the trial state into `f` (layout of V, zero at fixed
  /// dofs when `apply_bc`); ghost-consistent.
  void assemble_internal_force(Vec f, bool apply_bc = true) const;
  /// After accept() of an extrapolated (IMPL-EX) trial: the change of the
  /// internal force from the extrapolated to the implicit stresses,
  /// int B^T (sig_implicit - sig_extrapolated), into `f` (layout of V, zero
  /// at fixed dofs; assembled over the cells where the two differ). Zero if
  /// no such trial was accepted yet. Collective.
  void assemble_extrapolation_change(Vec f) const;
  /// Tangent of the trial state, fixed rows and columns identity; the
  /// pattern of ElasticModel::assemble_stiffness.
  Mat assemble_tangent() const;
  /// Assembles the tangent into an existing matrix of that pattern.
  void assemble_tangent(Mat A) const;
  /// Adds scale (K_T - K0) to the assembled matrix A (the pattern of
  /// ElasticModel::assemble_stiffness), K_T the tangent of the trial state
  /// and K0 the elastic stiffness, and finishes the assembly. Only the
  /// cells with a point off the elastic fast path in the last update
  /// contribute (K_T = K0 on all others), so this costs a fraction of
  /// assemble_tangent() while few points are inelastic. Fixed rows and
  /// columns get nothing. Collective.
  void add_tangent_change(Mat A, double scale) const;
  /// The cell matrices of that change (rows and columns: the cells' local
  /// dof blocks of V, values row-major per cell, fixed rows and columns
  /// zeroed) handed to `set`, for a matrix on other unknowns (u = P u_r:
  /// analysis/TiedConcreteSystem); no assembly is finished.
  using BlockSetter = std::function<int(std::span<const std::int32_t>,
                                        std::span<const std::int32_t>,
                                        std::span<const double>)>;
  void add_tangent_change(const BlockSetter& set, double scale) const;

  /// Number of quadrature points per cell.
  int points_per_cell() const { return _nq; }
  /// Quadrature-point stress space (3 components, blocked).
  std::shared_ptr<const dolfinx::fem::FunctionSpace> stress_space() const
  {
    return _Sq;
  }
  /// Committed stress values (sxx, syy, sxy) in the layout of stress_space()
  /// (owned and ghost points).
  std::span<const double> stress() const { return _sig_committed; }
  /// Coordinates of the points in the layout of stress_space() (x, y, z).
  std::span<const double> coordinates() const { return _coords; }

  /// Per point (layout of stress_space(), one value per point), committed:
  /// equivalent viscoplastic strains, their rates, and the largest absolute
  /// principal total strain rate of the last step.
  std::span<const double> kappa_t() const { return _out[0]; }
  std::span<const double> kappa_c() const { return _out[1]; }
  std::span<const double> kappa_t_rate() const { return _out[2]; }
  std::span<const double> kappa_c_rate() const { return _out[3]; }
  std::span<const double> strain_rate() const { return _out[4]; }

  /// The whole committed state as arrays (for checkpoints) and back.
  std::map<std::string, std::vector<double>> save() const;
  void restore(const std::map<std::string, std::vector<double>>& arrays);

  /// Number of distinct material objects (bins of region and h).
  std::size_t material_count() const { return _dynamic.size(); }
  /// Cells whose tensile strength was lowered to avoid snap-back (h larger
  /// than the characteristic length; see material/README.md), all ranks.
  std::int64_t cells_with_reduced_strength() const { return _reduced_cells; }
  /// The smallest and largest lowered tensile strength of those cells [Pa]
  /// (+inf, -inf if there are none).
  std::array<double, 2> reduced_tensile_strength_range() const
  {
    return _reduced_ft;
  }
  /// Cells as large whose tensile strength was kept, their softening
  /// dissipating more than Gf per unit crack area (TensionSoftening::
  /// crack_band_keep_strength), all ranks.
  std::int64_t cells_with_raised_tensile_energy() const
  {
    return _raised_cells;
  }

private:
  /// The in-plane 3x3 tangent (xx, yy, xy) of a 6x6 one into ct (plane
  /// stress: sigma_zz = 0 condensed out).
  void condense(const material::Matrix6& T, double* ct) const;
  /// A ball of stresses around a point's committed stress that the
  /// elastic-trial test (HtcConcrete::admissible) accepts whole
  /// (HtcConcrete::admissible_radius), valid for the material object and
  /// internal variables it was made with: a trial stress inside it skips
  /// the test with the same answer.
  struct ElasticBall
  {
    material::Vector6 centre{};
    double r2 = -1.0; ///< squared radius (< 0: none)
    double kappa_c = 0.0, kappa_t = 0.0;
    const material::HtcConcrete* material = nullptr;
    /// True if the ball was made for this material object and the internal
    /// variables of `s`.
    bool fits(const material::HtcConcrete& m, const material::State& s) const
    {
      return material == &m && kappa_c == s.kappa_c && kappa_t == s.kappa_t;
    }
  };
  /// The material object of local cell c for a step of length dt (> 0:
  /// dynamic; 0: the static stage).
  const material::HtcConcrete& material_of(std::int32_t c, double dt) const
  {
    return dt > 0.0 ? *_dynamic[_cell_material[c]]
                    : *_static[_cell_material[c]];
  }
  /// The common case of integrate_point(): if the elastic trial of the
  /// point (plane stress: with the elastic out-of-plane strain) is
  /// admissible, the elastic update into `out`, eps_new and ct, and true;
  /// else false and nothing written (integrate_point() then does the work).
  bool elastic_point(const material::HtcConcrete& m, std::int32_t material,
                     const ElasticBall& ball, const material::State& old,
                     const std::array<double, 6>& eps_old,
                     const double* eps_new_plane,
                     std::array<double, 6>& eps_new, material::State& out,
                     double* ct) const;
  /// One point: old state and total strain (Voigt 6) -> new state; the
  /// condensed 3x3 tangent into `ct`. Returns the update.
  material::Update integrate_point(const material::HtcConcrete& m,
                                   const material::State& old,
                                   const std::array<double, 6>& eps_old,
                                   const double* eps_new_plane, double dt,
                                   std::array<double, 6>& eps_new, double* ct,
                                   int& return_maps,
                                   std::int64_t& local_iterations) const;

  ElasticModel& _fe;
  PlaneMode _plane;
  const PlasticityFormSet& _forms;
  int _nq = 0;
  std::int32_t _num_cells = 0, _num_owned_cells = 0;
  std::shared_ptr<dolfinx::fem::FunctionSpace> _Sq, _Cq;
  std::shared_ptr<dolfinx::fem::Function<double>> _sig, _Ct, _u;
  std::vector<std::int32_t> _cells; ///< all local cells (owned, ghost)
  /// Ghosted work vector of the internal force assembly.
  dolfinx::la::petsc::Vector _f_work{nullptr, false};
  /// Adds the ghost contributions of _f_work to their owners, zeroes the
  /// fixed dofs if apply_bc, and copies the owned values into f.
  void finish_work_vector(Vec f, bool apply_bc) const;
  std::shared_ptr<dolfinx::fem::Form<double>> _L, _a;
  std::unique_ptr<dolfinx::fem::Expression<double>> _strain;
  std::vector<std::unique_ptr<material::HtcConcrete>> _dynamic, _static;
  /// Stress components of the forms (3 in 2D, 6 in 3D) and their Voigt
  /// indices in the material's 6.
  int _nc = 3;
  std::array<int, 6> _voigt = {0, 1, 3, 0, 0, 0};
  /// The material's strain increment (6 Voigt components) of a point whose
  /// strain (form components) is e and whose committed strain is eps_old;
  /// plane stress: eps_zz from the elastic sigma_zz = 0 with `nu` (nu < 0:
  /// eps_zz = 0).
  material::Vector6 strain_increment(const double* e,
                                     const std::array<double, 6>& eps_old,
                                     double nu) const;
  /// Per material: the elastic 6x6 and condensed tangents (the same for
  /// the dynamic and the static object), for the elastic-trial fast path.
  std::vector<material::Matrix6> _De;
  std::vector<std::array<double, 36>> _ct_elastic;
  std::vector<std::int32_t> _cell_material; ///< per local cell
  std::vector<std::int32_t> _dof;           ///< point p -> Sq dof (block)
  std::vector<std::int32_t> _dof_c;         ///< point p -> Cq dof (block)
  // Committed and trial states, per point p = cell * nq + q.
  std::vector<material::State> _state, _trial;
  std::vector<ElasticBall> _ball; ///< per point p, around _state[p]
  std::vector<std::array<double, 6>> _eps, _eps_trial;
  std::vector<double> _sig_committed, _coords, _strain_values;
  std::array<std::vector<double>, 5> _out;
  double _trial_dt = 0.0;
  std::int64_t _reduced_cells = 0, _raised_cells = 0;
  std::array<double, 2> _reduced_ft = {HUGE_VAL, -HUGE_VAL};
  // IMPL-EX: the plastic strain increment of the last accepted dynamic step
  // per point, and that step's length (0: none yet, no extrapolation).
  bool _implex = false;
  /// The stress coefficient of the last extrapolated trial, kept by accept()
  /// before the implicit return map replaces it.
  std::vector<double> _sig_extrapolated;
  std::vector<std::array<double, 6>> _dep;
  double _dt_last = 0.0;
  /// Overwrites the stress coefficient with the extrapolated stress of every
  /// point for the strains of the last update (IMPL-EX).
  void extrapolate_stress(double dt);
  /// The return map at every point for the strains of the last update
  /// (stops at the first failed owned point); fills the stress and tangent
  /// coefficients. Collective.
  MaterialUpdateStats update_points(double dt);
  std::int64_t _num_owned_points = 0; ///< all ranks
  /// Owned cells whose trial tangent may differ from the elastic one (a
  /// point left the elastic fast path in the last update).
  std::vector<std::int32_t> _tangent_cells;
  /// Dirichlet markers of V's dofs (blocked layout), made on first use.
  mutable std::vector<std::int8_t> _bc_marker;
  mutable std::vector<double> _coeff_work;
};
} // namespace damseis::fem
