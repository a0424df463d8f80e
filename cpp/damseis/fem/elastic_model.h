// A linear elastic finite element model of a dam (and its foundation):
// function spaces, materials per region, boundary conditions and the
// assembled operators of the compiled forms.
#pragma once

#include "form_set.h"
#include <array>
#include <damseis/geometry/gmsh_mesh.h>
#include <dolfinx/fem/Constant.h>
#include <dolfinx/fem/DirichletBC.h>
#include <dolfinx/fem/Form.h>
#include <dolfinx/fem/Function.h>
#include <dolfinx/fem/FunctionSpace.h>
#include <map>
#include <memory>
#include <petscmat.h>
#include <vector>

namespace damseis::fem
{
/// 2D idealisation of a dam section.
enum class PlaneMode
{
  plane_strain,
  plane_stress
};

/// Isotropic linear elastic material (SI units).
struct Material
{
  double E = 30e9;   ///< Young's modulus [Pa]
  double nu = 0.2;   ///< Poisson's ratio [-]
  double rho = 2500; ///< mass density [kg/m3]; 0 for a massless foundation
};

/// Reservoir water acting on the upstream face.
struct Reservoir
{
  double level = 0.0;      ///< elevation of the water surface [m]
  double bottom = 0.0;     ///< elevation of the reservoir bottom at the dam [m]
  double rho_w = 1000.0;   ///< water density [kg/m3]
  double g = 9.81;         ///< gravity [m/s2]
  bool load_floor = false; ///< also press on the reservoir floor (foundation)
  double depth() const { return level > bottom ? level - bottom : 0.0; }
};

/// The displacement space of the models on `mesh` (vector Lagrange of
/// `degree`), as ElasticModel::V() has it.
std::shared_ptr<dolfinx::fem::FunctionSpace>
displacement_space(std::shared_ptr<dolfinx::mesh::Mesh> mesh, int degree);

/// Owns the spaces, coefficients and forms of one elastic model.
/// Matrices and vectors are returned as new PETSc objects: the caller owns
/// them (wrap them in dolfinx::la::petsc::Matrix / Vector).
class ElasticModel
{
public:
  using Function = dolfinx::fem::Function<double>;
  using FunctionSpace = dolfinx::fem::FunctionSpace;

  /// @param[in] model mesh and tags
  /// @param[in] degree displacement polynomial degree (1 or 2)
  /// @param[in] materials material per region tag; every tagged cell needs
  /// one
  /// @param[in] mode plane strain or plane stress (2D only)
  ElasticModel(geometry::Model model, int degree,
               const std::map<int, Material>& materials,
               PlaneMode mode = PlaneMode::plane_strain);

  const geometry::Model& model() const { return _model; }
  std::shared_ptr<const dolfinx::mesh::Mesh> mesh() const
  {
    return _model.mesh;
  }
  int dim() const { return _forms.dim; }
  int degree() const { return _forms.degree; }
  const FormSet& forms() const { return _forms; }

  /// Displacement space (vector Lagrange of the chosen degree).
  std::shared_ptr<const FunctionSpace> V() const { return _V; }
  /// Stress-point space: DG(degree-1) vector with the stress components.
  std::shared_ptr<const FunctionSpace> S() const { return _S; }
  /// Output spaces: "sig_cell" (DG0 tensor), "s_cell" (DG0 scalar),
  /// "u_vertex" (P1 vector), "s_vertex" (P1 scalar).
  std::shared_ptr<const FunctionSpace> output_space(const std::string& name);

  /// PETSc storage of K and M: "baij" (default; one block per node, the
  /// fastest here for products and factorisations) or "aij".
  void set_matrix_type(const std::string& type) { _matrix_type = type; }

  /// Fixes every displacement component on the facets with these tags.
  void fix(const std::vector<int>& facet_tags);
  const std::vector<std::shared_ptr<const dolfinx::fem::DirichletBC<double>>>&
  bcs() const
  {
    return _bcs;
  }
  /// Local (unrolled) indices of fixed dofs, owned and ghost.
  std::vector<std::int32_t> fixed_dofs() const;

  /// Stiffness K: fixed rows and columns zero, 1 on their diagonal.
  Mat assemble_stiffness() const;
  /// Mass M, plus the Westergaard added mass of `reservoir` if given; fixed
  /// rows and columns zero (including the diagonal).
  Mat assemble_mass(const Reservoir* reservoir) const;
  /// Dead-weight load for the body acceleration `g` [m/s2]; zero at fixed
  /// dofs. With `regions` (cell tags), on those cells only (the dam's,
  /// where the foundation's own weight is not a load on the dam).
  Vec assemble_gravity(const std::array<double, 3>& g,
                       const std::vector<int>& regions = {}) const;
  /// Hydrostatic load of the reservoir; zero at fixed dofs.
  Vec assemble_hydrostatic(const Reservoir& reservoir) const;
  /// A load of another compiled linear form on V (e.g.
  /// forms/gravity_loads_2d.py) with scalar constants by name, integrated
  /// over the tagged exterior and interior facets; zero at fixed dofs.
  /// `coefficients`: name -> Function (e.g. a region indicator).
  Vec assemble_load_form(
      const ufcx_form& form, const std::map<std::string, double>& constants,
      const std::map<std::string, std::shared_ptr<const Function>>&
          coefficients = {}) const;
  /// A load of a compiled linear form whose integrals run over subdomain 1
  /// (cells, or exterior facets, or with `interior` interior facets, by the
  /// dimension of `group`), the entities `group` gives value 1 (e.g.
  /// forms/group_loads_2d.py); zero at fixed dofs if `apply_bc`.
  Vec assemble_group_load(const ufcx_form& form,
                          const std::map<std::string, double>& constants,
                          const dolfinx::mesh::MeshTags<std::int32_t>& group,
                          bool interior = false, bool apply_bc = true) const;
  /// Internal force f_int(u) = K u without boundary conditions (used for
  /// reactions and residual checks).
  Vec assemble_internal_force(const Function& u) const;
  /// Loads without boundary conditions (for reaction checks).
  Vec assemble_gravity_free(const std::array<double, 3>& g) const;
  Vec assemble_hydrostatic_free(const Reservoir& reservoir) const;
  /// The stress operator B: stress components at the stress points (rows in
  /// S, blocked by the number of components) = B u, exact for the
  /// element's polynomial field.
  Mat assemble_stress_operator() const;
  /// Influence vector: 1 at the free dofs of displacement `component`, 0
  /// elsewhere.
  Vec influence(int component) const;

  /// The bilinear form `form` on V x V with the material coefficients and
  /// the scalar or vector constants by name, its exterior-facet integrals
  /// over subdomain 1 of `facets`, assembled with the fixed dofs' rows and
  /// columns zero (their diagonal too). Collective.
  Mat assemble_facet_matrix(
      const ufcx_form& form,
      const std::map<std::string, std::vector<double>>& constants,
      const dolfinx::mesh::MeshTags<std::int32_t>& facets) const;

  /// The operators of an implicit-explicit partition
  /// (dynamics::PartitionedNewmark) whose explicit group is the cells of
  /// `explicit_regions`, on all dofs and without boundary conditions: K of
  /// all cells, K_implicit of the other cells alone, and M consistent on
  /// the other cells (with the added mass of `reservoir`), lumped on the
  /// explicit ones by HRZ (each element's diagonal scaled to its mass: for
  /// straight-sided simplices of one kind a single factor, sum(M_E 1) /
  /// trace(M_E), P1 giving the row sums and P2 triangles positive vertex
  /// and midside masses in the ratio 6 : 32). The caller owns the PETSc
  /// objects. Collective.
  struct Partitioned
  {
    Mat K = nullptr, K_implicit = nullptr, M = nullptr;
    Vec M_explicit = nullptr; ///< the explicit cells' lumped mass alone
  };
  Partitioned assemble_partitioned(const std::vector<int>& explicit_regions,
                                   const Reservoir* reservoir) const;

  /// Sum over all ranks of the volume (area in 2D) of cells of `region`.
  double region_measure(int region) const;

private:
  std::map<std::string, std::shared_ptr<const dolfinx::fem::Constant<double>>>
  constants(const Reservoir* reservoir, const std::array<double, 3>& g) const;
  std::shared_ptr<dolfinx::fem::Form<double>>
  make_form(ufcx_form* form,
            std::vector<std::shared_ptr<const FunctionSpace>> spaces,
            const Reservoir* reservoir = nullptr,
            const std::array<double, 3>& g = {0, 0, 0},
            std::shared_ptr<const Function> u = nullptr,
            std::shared_ptr<const Function> rho = nullptr,
            std::shared_ptr<const Function> mu = nullptr,
            std::shared_ptr<const Function> lmbda = nullptr) const;
  /// A copy of the cellwise coefficient f, zero on the cells of `regions`
  /// (or, with `keep`, zero elsewhere).
  std::shared_ptr<Function> zeroed_on(const Function& f,
                                      const std::vector<int>& regions,
                                      bool keep) const;
  Vec assemble_load(const dolfinx::fem::Form<double>& L, bool apply_bc) const;

  geometry::Model _model;
  const FormSet& _forms;
  std::shared_ptr<FunctionSpace> _V, _S;
  std::string _matrix_type = "baij";
  std::map<std::string, std::shared_ptr<const FunctionSpace>> _outputs;
  std::shared_ptr<Function> _mu, _lmbda, _rho;
  std::vector<std::shared_ptr<const dolfinx::fem::DirichletBC<double>>> _bcs;
};
} // namespace damseis::fem
