// Silt and uplift loads (fem/gravity_dam_loads, forms/gravity_loads_2d.py)
// against closed-form resultants, on the Koyna section with a foundation
// block (the dam base is then an interior interface of free nodes):
//  - silt: the horizontal resultant is K_a gamma_s' h_s^2 / 2 with
//    K_a = tan^2(45 - phi/2) (Rankine); the silt surface is put at the
//    section's water-level node, so the pressure is linear on every loaded
//    facet and the P2 load is exact (tolerance 1e-12 relative);
//  - uplift: the vertical resultant is the area of the pressure diagram
//    (two trapezoids); the kink at the drainage line lies inside a facet, so
//    the quadrature error of that facet is allowed (1e-3 relative).
#include "fem_test_support.h"

#include <damseis/fem/gravity_dam_loads.h>
#include <damseis/geometry/gravity_dam.h>

namespace
{
using namespace damseis::test;
using damseis::fem::ElasticModel;
using damseis::fem::Material;
namespace tags = damseis::tags;

double component_sum(Vec b, int comp)
{
  const double* a = nullptr;
  PetscInt n = 0;
  VecGetLocalSize(b, &n);
  VecGetArrayRead(b, &a);
  double s = 0;
  for (PetscInt i = comp; i < n; i += 2)
    s += a[i];
  VecRestoreArrayRead(b, &a);
  return global_sum(s);
}

TEST(GravityDamLoads, SiltAndUpliftResultants)
{
  damseis::geometry::GravityDamSection s;
  s.mesh_size = 4.0;
  s.water_level = 30.0; // a node at the silt surface
  s.foundation = true;
  s.foundation_width = 200;
  s.foundation_depth = 60;
  const Material m{30e9, 0.2, 2500};
  ElasticModel fe(damseis::geometry::build_gravity_dam(MPI_COMM_WORLD, s), 2,
                  {{tags::dam, m}, {tags::foundation, {30e9, 0.2, 0}}});
  fe.fix({tags::foundation_bottom});

  damseis::fem::Silt silt;
  silt.level = 30.0;
  silt.unit_weight = 9000;
  silt.friction_angle_deg = 20;
  PVec fs = own(damseis::fem::assemble_silt(fe, silt));
  const double ka = std::pow(std::tan((45.0 - 10.0) * M_PI / 180.0), 2);
  const double silt_ref = ka * 9000 * 30.0 * 30.0 / 2;
  const double sx = component_sum(fs.vec(), 0);
  print_metric(fmt("silt resultant ", sx, " N/m, closed form ", silt_ref));
  EXPECT_NEAR(sx, silt_ref, 1e-12 * silt_ref);
  EXPECT_NEAR(component_sum(fs.vec(), 1), 0.0, 1e-12 * silt_ref);

  damseis::fem::Uplift up;
  up.head_upstream = 91.75;
  up.head_downstream = 10.0;
  up.alpha = 0.25;
  up.x_heel = 0.0;
  up.x_drain = 7.3;
  up.x_toe = 70.0;
  PVec fu = own(damseis::fem::assemble_uplift(fe, up));
  const double g = up.gamma_w, h1 = 91.75, h2 = 10.0;
  const double pd = g * (h2 + 0.25 * (h1 - h2));
  const double uplift_ref =
      0.5 * (g * h1 + pd) * 7.3 + 0.5 * (pd + g * h2) * (70.0 - 7.3);
  const double uy = component_sum(fu.vec(), 1);
  print_metric(fmt("uplift resultant ", uy, " N/m, closed form ", uplift_ref,
                   ", relative error ",
                   std::abs(uy - uplift_ref) / uplift_ref));
  EXPECT_NEAR(uy, uplift_ref, 1e-3 * uplift_ref);
  EXPECT_NEAR(component_sum(fu.vec(), 0), 0.0, 1e-9 * uplift_ref);
}
} // namespace
