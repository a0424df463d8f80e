// The compiled UFL kernels (forms/elasticity_{2d,3d}.py) for one spatial
// dimension and displacement degree.
#pragma once

#include <string>
#include <ufcx.h>

namespace damseis::fem
{
/// Pointers to the generated forms of one variant of the elasticity file.
/// Names follow the UFL file: see forms/elasticity_2d.py for their meaning.
struct FormSet
{
  int dim = 0;    ///< spatial dimension (2 or 3)
  int degree = 0; ///< displacement polynomial degree (1 or 2)
  ufcx_form* a_stiffness = nullptr;
  ufcx_form* a_mass = nullptr;
  ufcx_form* a_added_mass = nullptr;
  ufcx_form* L_gravity = nullptr;
  ufcx_form* L_hydrostatic = nullptr;
  ufcx_form* L_internal = nullptr;
  ufcx_form* a_stress = nullptr;
  ufcx_form* L_stress_weight = nullptr;
  ufcx_form* M_output = nullptr;
  /// Function-space factory of a form by coefficient/argument name.
  ufcx_function_space* (*space_of_stiffness)(const char*) = nullptr;
  ufcx_function_space* (*space_of_stress)(const char*) = nullptr;
  ufcx_function_space* (*space_of_output)(const char*) = nullptr;

  /// Number of independent stress components (3 in 2D, 6 in 3D).
  int stress_size() const { return dim == 2 ? 3 : 6; }
};

/// The kernels for `dim` in {2, 3} and `degree` in {1, 2}; throws
/// std::invalid_argument otherwise.
const FormSet& form_set(int dim, int degree);

/// The kernels of a nonlinear material with state at quadrature points
/// (forms/plasticity_{2d,3d}.py): internal force and tangent from the point
/// values, and the strain and position expressions at the same points.
struct PlasticityFormSet
{
  int dim = 0;
  int degree = 0;
  ufcx_form* L_residual = nullptr;
  ufcx_form* a_tangent = nullptr;
  ufcx_expression* strain = nullptr;
  ufcx_expression* position = nullptr;
  ufcx_function_space* (*space_of_residual)(const char*) = nullptr;
  ufcx_function_space* (*space_of_tangent)(const char*) = nullptr;
};

/// The nonlinear-material kernels for `dim` in {2, 3} and `degree` in
/// {1, 2} (forms/plasticity_{2d,3d}.py); throws std::invalid_argument
/// otherwise.
const PlasticityFormSet& plasticity_form_set(int dim, int degree);
} // namespace damseis::fem
