// The crack-band check shared by the 2D and 3D concrete tests: a bar
// [0, L] x [0, H]^(dim-1), clamped at x = 0 and pulled at x = L under
// displacement control, whose middle slab of cells is 2% weaker so that the
// crack forms there. The work done, less the elastic energy left, divided
// by Gf times the section, must be 1 whatever the mesh (crack-band theory,
// Bazant & Oh 1983).
#pragma once

#include "fem_test_support.h"
#include <damseis/fem/concrete_model.h>
#include <damseis/linalg/direct_solver.h>
#include <damseis/linalg/petsc_vectors.h>

namespace damseis::test
{
/// W / (Gf A) of the bar with nx cells along (dim 2: triangles, plane
/// stress; dim 3: tetrahedra) and P`degree` elements.
inline double tension_bar_energy_ratio(int dim, int nx, int degree)
{
  using fem::ConcreteModel;
  using fem::ElasticModel;
  using fem::Material;
  using fem::PlaneMode;
  namespace tags = damseis::tags;
  const double L = 0.5, H = 0.05, Gf = 300.0, ft = 3e6, E = 30e9;
  const double area = dim == 2 ? H : H * H;
  const std::size_t ny = std::max(1, nx / 10);
  auto ends = [&](const Point& x)
  {
    if (x[0] < 1e-12)
      return 5;
    if (x[0] > L - 1e-12)
      return 6;
    return -1;
  };
  Model m = dim == 2 ? rectangle_model(MPI_COMM_WORLD, {0, 0}, {L, H},
                                       {std::size_t(nx), ny}, ends)
                     : box_model(MPI_COMM_WORLD, {0, 0, 0}, {L, H, H},
                                 {std::size_t(nx), ny, ny}, ends);
  // The weak slab: the cells whose centroid is in the middle column.
  {
    auto& t = *m.cell_tags;
    const auto& x = m.mesh->geometry().x();
    const auto& g = m.mesh->geometry().dofmap();
    std::vector<std::int32_t> idx(t.indices().begin(), t.indices().end());
    std::vector<std::int32_t> val(t.values().begin(), t.values().end());
    const double a = L / nx;
    for (std::size_t i = 0; i < idx.size(); ++i)
    {
      auto v = g.links(idx[i]);
      double xc = 0;
      for (std::size_t k = 0; k < v.size(); ++k)
        xc += x[3 * v[k]] / double(v.size());
      if (std::abs(xc - (std::floor(nx / 2) + 0.5) * a) < 0.5 * a)
        val[i] = 3;
    }
    m.cell_tags = std::make_shared<dolfinx::mesh::MeshTags<std::int32_t>>(
        m.mesh, dim, std::move(idx), std::move(val));
  }
  const Material mat{E, 0.0, 2500};
  ElasticModel fe(m, degree, {{tags::dam, mat}, {3, mat}},
                  PlaneMode::plane_stress);
  fe.fix({5, 6});
  material::ConcreteParameters p;
  p.E = E;
  p.nu = 0.0;
  p.fc0 = 10 * ft;
  p.ft0 = ft;
  p.Gf = Gf;
  p.mode = material::Mode::plastic;
  material::ConcreteParameters weak = p;
  weak.ft0 = 0.98 * ft;
  ConcreteModel cm(fe, {{tags::dam, p}, {3, weak}},
                   {{tags::dam, mat}, {3, mat}}, PlaneMode::plane_stress);
  EXPECT_EQ(cm.cells_with_reduced_strength(), 0);

  // Right-end x dofs (owned), for the imposed displacement and reaction.
  auto V = fe.V();
  const std::vector<double> X = V->tabulate_dof_coordinates(false);
  const std::int32_t nown = V->dofmap()->index_map->size_local();
  std::vector<PetscInt> right;
  for (std::int32_t i = 0; i < nown; ++i)
    if (X[3 * i] > L - 1e-12)
      right.push_back(dim * i);
  PMat J = own(cm.assemble_tangent());
  auto zero = [&] { return own(fe.assemble_gravity({0, 0, 0})); };
  PVec u = zero(), R = zero(), du = zero(), f_free = zero(), u_old = zero(),
       step = zero();
  dolfinx::fem::Function<double> uf(V);
  auto reaction = [&]()
  {
    cm.assemble_internal_force(f_free.vec(), false);
    const double* a = nullptr;
    VecGetArrayRead(f_free.vec(), &a);
    double s = 0;
    for (PetscInt i : right)
      s += a[i];
    VecRestoreArrayRead(f_free.vec(), &a);
    return global_sum(s);
  };
  // Displacement steps: fine around the peak (ft L / E = 5e-5 m) and in the
  // softening branch, up to a crack opening of 8 Gf/ft.
  const double peak = ft / E * L, w_end = 8.0 * Gf / ft;
  std::vector<double> steps;
  for (double d = 0; d < w_end + peak;)
  {
    d += d < 0.9 * peak ? 0.1 * peak : 0.02 * peak + 0.004 * d;
    steps.push_back(d);
  }
  double work = 0, F_prev = 0, d_prev = 0, d_pp = 0, F_max = 0;
  for (double d : steps)
  {
    // Predictor: the last converged increment, scaled to the new one (an
    // imposed end displacement alone would strain only the end cells).
    VecWAXPY(step.vec(), -1.0, u_old.vec(), u.vec());
    VecCopy(u.vec(), u_old.vec());
    double* a = nullptr;
    VecGetArray(u.vec(), &a);
    if (d_prev > d_pp)
    {
      VecRestoreArray(u.vec(), &a);
      VecAXPY(u.vec(), (d - d_prev) / (d_prev - d_pp), step.vec());
      VecGetArray(u.vec(), &a);
    }
    else
    {
      // First step: the uniform elastic stretch u_x = d x / L.
      for (std::int32_t i = 0; i < nown; ++i)
        a[dim * i] = d * X[3 * i] / L;
    }
    for (PetscInt i : right)
      a[i] = d;
    VecRestoreArray(u.vec(), &a);
    bool ok = false;
    for (int it = 0; it < 40 && !ok; ++it)
    {
      linalg::to_function(u.vec(), uf);
      const auto st = cm.update(uf, 0.0);
      EXPECT_EQ(st.failed, 0) << "d / peak = " << d / peak << ", iteration "
                              << it << ", inelastic " << st.inelastic;
      cm.assemble_internal_force(R.vec());
      if (norm2(R.vec()) <= 1e-9 * ft * area)
      {
        ok = true;
        break;
      }
      cm.assemble_tangent(J.mat());
      linalg::DirectSolver lu(MPI_COMM_WORLD, linalg::Factorization::mumps);
      lu.factorize_lu(J.mat());
      lu.solve(R.vec(), du.vec());
      VecAXPY(u.vec(), -1.0, du.vec());
    }
    EXPECT_TRUE(ok) << "displacement step " << d;
    cm.accept();
    const double F = reaction();
    F_max = std::max(F_max, F);
    work += 0.5 * (F + F_prev) * (d - d_prev);
    F_prev = F;
    d_pp = d_prev;
    d_prev = d;
  }
  // Elastic energy left in the bar at the end (F_end^2 L / (2 E A)).
  work -= F_prev * F_prev * L / (2 * E * area);
  print_metric(fmt(dim, "D bar nx = ", nx, " P", degree,
                   ": peak force / (ft A) = ", F_max / (ft * area),
                   ", final force / peak = ", F_prev / F_max,
                   ", work / (Gf A) = ", work / (Gf * area)));
  return work / (Gf * area);
}
} // namespace damseis::test
