#include "free_field_load.h"
#include <chrono>
#include <damseis/linalg/duplicate_matrix.h>
#include <damseis/linalg/petsc_vectors.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>
#include <stdexcept>

namespace damseis::analysis
{
using dolfinx::la::petsc::Matrix;
using dolfinx::la::petsc::Vector;

FreeFieldLoad::FreeFieldLoad(const fem::ElasticModel& fe,
                             const fem::ViscousBoundary* b,
                             const geometry::GroundSurface& ground,
                             std::shared_ptr<const boundary::FreeField> field,
                             Mat M, Mat K, dynamics::RayleighDamping damping,
                             double dt, Mat tie, Vec sustained)
    : _field(std::move(field)), _M(M), _K(K), _tie(tie), _damping(damping),
      _dt(dt), _dim(fe.dim())
{
  if (b)
  {
    _Kb = Matrix(b->springs(), true);
    _Cb = Matrix(b->dashpots(), true);
    _T = Matrix(b->traction_operator(), true);
  }
  if (sustained)
  {
    _sustained = linalg::column_vector(K);
    VecCopy(sustained, _sustained.vec());
  }
  // The full layout (all dofs): the boundary's operators', or the rows of
  // the tie.
  for (Vector* v : {&_u_b, &_v_b, &_s_b, &_v_all, &_f_full})
    *v = b ? linalg::column_vector(_Kb.mat())
           : (tie ? linalg::row_vector(tie) : linalg::column_vector(K));
  _work = linalg::column_vector(K);
  if (tie)
  {
    // The restriction of a continuous field onto the reduced unknowns:
    // each takes the mean of the dofs it alone gives (tied copies, or the
    // dof itself), not the dofs a constraint interpolates (P2 midside
    // nodes of contact pairs).
    _pick = Matrix(linalg::duplicate_matrix(tie, MAT_COPY_VALUES), false);
    PetscInt lo = 0, hi = 0;
    MatGetOwnershipRange(_pick.mat(), &lo, &hi);
    std::vector<PetscInt> shared;
    for (PetscInt row = lo; row < hi; ++row)
    {
      PetscInt n = 0;
      const PetscScalar* values = nullptr;
      MatGetRow(_pick.mat(), row, &n, nullptr, &values);
      int nonzero = 0;
      for (PetscInt j = 0; j < n; ++j)
        nonzero += values[j] != 0.0;
      if (nonzero > 1)
        shared.push_back(row);
      MatRestoreRow(_pick.mat(), row, &n, nullptr, &values);
    }
    MatZeroRows(_pick.mat(), static_cast<PetscInt>(shared.size()),
                shared.data(), 0.0, nullptr, nullptr);
    _v_r = linalg::column_vector(K);
    _count = linalg::column_vector(K);
    VecSet(_v_all.vec(), 1.0);
    MatMultTranspose(_pick.mat(), _v_all.vec(), _count.vec());
    PetscReal least = 0.0;
    VecMin(_count.vec(), nullptr, &least);
    if (!(least > 0.0))
      throw std::logic_error("free-field load: a reduced unknown takes its "
                             "value from no dof alone");
  }
  const auto& map = *fe.V()->dofmap()->index_map;
  const std::int32_t n = map.size_local();
  const std::vector<double> x = fe.V()->tabulate_dof_coordinates(false);
  _x.resize(n);
  _z_ground.resize(n);
  for (std::int32_t i = 0; i < n; ++i)
  {
    _x[i] = {x[3 * i], x[3 * i + 1], x[3 * i + 2]};
    _z_ground[i] = ground.height(_x[i]);
  }
  // (With a transmitting boundary its prescribed nodes move with the free
  // field too: their velocity enters the damping force of their
  // neighbours.)
  _fixed.assign(n, 0);
  if (!b)
    return;
  for (std::int32_t dof : fe.fixed_dofs())
    if (dof / _dim < n)
      _fixed[dof / _dim] = 1;
  for (std::int32_t block : b->blocks())
    if (block < n)
      _boundary.push_back(block);
}

void FreeFieldLoad::assemble(int k, Vec f) const
{
  const auto start = std::chrono::steady_clock::now();
  const double t = k * _dt;
  // The free field on the boundary: displacement, velocity, stresses.
  double *u = nullptr, *v = nullptr, *s = nullptr, *va = nullptr;
  VecGetArray(_u_b.vec(), &u);
  VecGetArray(_v_b.vec(), &v);
  VecGetArray(_s_b.vec(), &s);
  for (std::int32_t i : _boundary)
  {
    const boundary::FreeFieldState st = _field->at(_x[i], _z_ground[i], k, t);
    for (int c = 0; c < _dim; ++c)
    {
      u[i * _dim + c] = st.u[c];
      v[i * _dim + c] = st.v[c];
      s[i * _dim + c] = st.s[c];
    }
  }
  VecRestoreArray(_u_b.vec(), &u);
  VecRestoreArray(_v_b.vec(), &v);
  VecRestoreArray(_s_b.vec(), &s);
  // Its velocity at every free node (the damping's reference).
  VecGetArray(_v_all.vec(), &va);
  for (std::size_t i = 0; i < _x.size(); ++i)
  {
    const std::array<double, 3> w =
        _fixed[i] ? std::array<double, 3>{}
                  : _field->velocity(_x[i], _z_ground[i], k, t);
    for (int c = 0; c < _dim; ++c)
      va[i * _dim + c] = w[c];
  }
  VecRestoreArray(_v_all.vec(), &va);

  // The boundary forces (all dofs), onto the system's unknowns.
  if (_Kb.mat())
  {
    MatMult(_Kb.mat(), _u_b.vec(), _f_full.vec());
    MatMultAdd(_Cb.mat(), _v_b.vec(), _f_full.vec(), _f_full.vec());
    MatMultAdd(_T.mat(), _s_b.vec(), _f_full.vec(), _f_full.vec());
  }
  else
    VecSet(_f_full.vec(), 0.0);
  if (_tie)
    MatMultTranspose(_tie, _f_full.vec(), f);
  else
    VecCopy(_f_full.vec(), f);
  if (_sustained.vec())
    VecAXPY(f, 1.0, _sustained.vec());
  // The damping's reference: the free field's velocity on the system's
  // unknowns (tied dofs coincide, so it is the mean of the tied values).
  Vec v_ref = _v_all.vec();
  if (_tie)
  {
    MatMultTranspose(_pick.mat(), _v_all.vec(), _v_r.vec());
    VecPointwiseDivide(_v_r.vec(), _v_r.vec(), _count.vec());
    v_ref = _v_r.vec();
  }
  if (_damping.a_mass != 0.0)
  {
    MatMult(_M, v_ref, _work.vec());
    VecAXPY(f, _damping.a_mass, _work.vec());
  }
  if (_damping.b_stiffness != 0.0)
  {
    MatMult(_K, v_ref, _work.vec());
    VecAXPY(f, _damping.b_stiffness, _work.vec());
  }
  if (_K_extra && _b_extra != 0.0)
  {
    MatMult(_K_extra, v_ref, _work.vec());
    VecAXPY(f, _b_extra, _work.vec());
  }
  _seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
}

void FreeFieldLoad::initial_acceleration(Vec a) const
{
  VecSet(a, 0.0);
}
} // namespace damseis::analysis
