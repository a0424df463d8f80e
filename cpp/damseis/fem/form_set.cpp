#include "form_set.h"
#include <elasticity_2d_p1.h>
#include <elasticity_2d_p2.h>
#include <elasticity_3d_p1.h>
#include <elasticity_3d_p2.h>
#include <plasticity_2d_p1.h>
#include <plasticity_2d_p2.h>
#include <plasticity_3d_p1.h>
#include <plasticity_3d_p2.h>
#include <stdexcept>

namespace damseis::fem
{
namespace
{
#define DAMSEIS_FORM_SET(DIM, DEG, MOD)                                        \
  FormSet                                                                      \
  {                                                                            \
    DIM, DEG, form_##MOD##_a_stiffness, form_##MOD##_a_mass,                   \
        form_##MOD##_a_added_mass, form_##MOD##_L_gravity,                     \
        form_##MOD##_L_hydrostatic, form_##MOD##_L_internal,                   \
        form_##MOD##_a_stress, form_##MOD##_L_stress_weight,                   \
        form_##MOD##_M_output, functionspace_form_##MOD##_a_stiffness,         \
        functionspace_form_##MOD##_a_stress,                                   \
        functionspace_form_##MOD##_M_output                                    \
  }
} // namespace

const FormSet& form_set(int dim, int degree)
{
  static const FormSet sets[4] = {DAMSEIS_FORM_SET(2, 1, elasticity_2d_p1),
                                  DAMSEIS_FORM_SET(2, 2, elasticity_2d_p2),
                                  DAMSEIS_FORM_SET(3, 1, elasticity_3d_p1),
                                  DAMSEIS_FORM_SET(3, 2, elasticity_3d_p2)};
  if ((dim != 2 && dim != 3) || (degree != 1 && degree != 2))
  {
    throw std::invalid_argument("no compiled forms for dimension " +
                                std::to_string(dim) + " and degree " +
                                std::to_string(degree) +
                                "; expected dimension 2 or 3, degree 1 or 2");
  }
  return sets[2 * (dim - 2) + (degree - 1)];
}

#define DAMSEIS_PLASTICITY_SET(DIM, DEG, MOD)                                  \
  PlasticityFormSet                                                            \
  {                                                                            \
    DIM, DEG, form_##MOD##_L_residual, form_##MOD##_a_tangent,                 \
        expression_##MOD##_strain, expression_##MOD##_position,                \
        functionspace_form_##MOD##_L_residual,                                 \
        functionspace_form_##MOD##_a_tangent                                   \
  }

const PlasticityFormSet& plasticity_form_set(int dim, int degree)
{
  static const PlasticityFormSet sets[4] = {
      DAMSEIS_PLASTICITY_SET(2, 1, plasticity_2d_p1),
      DAMSEIS_PLASTICITY_SET(2, 2, plasticity_2d_p2),
      DAMSEIS_PLASTICITY_SET(3, 1, plasticity_3d_p1),
      DAMSEIS_PLASTICITY_SET(3, 2, plasticity_3d_p2)};
  if ((dim != 2 && dim != 3) || (degree != 1 && degree != 2))
  {
    throw std::invalid_argument(
        "no compiled nonlinear-material forms for dimension " +
        std::to_string(dim) + ", degree " + std::to_string(degree) +
        "; expected dimension 2 or 3, degree 1 or 2");
  }
  return sets[2 * (dim - 2) + (degree - 1)];
}
} // namespace damseis::fem
#undef DAMSEIS_FORM_SET
#undef DAMSEIS_PLASTICITY_SET
