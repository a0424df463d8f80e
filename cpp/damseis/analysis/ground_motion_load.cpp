#include "ground_motion_load.h"
#include <damseis/fem/tied_dofs.h>
#include <damseis/linalg/petsc_vectors.h>

namespace damseis::analysis
{
using dolfinx::la::petsc::Vector;

GroundMotionLoad::GroundMotionLoad(const fem::ElasticModel& fe,
                                   const SeismicSettings& s, Mat M, Mat tie,
                                   Vec sustained)
    : _s(s)
{
  if (sustained)
  {
    Vec copy;
    VecDuplicate(sustained, &copy);
    VecCopy(sustained, copy);
    _sustained = Vector(copy, false);
  }
  for (int c = 0; c < fe.dim(); ++c)
  {
    if (!s.motion[c].active)
      continue;
    _active.push_back(c);
    Vector r(fe.influence(c), false);
    if (tie)
      _influence.emplace_back(fem::restrict_to_tied(tie, r.vec()), false);
    else
      _influence.push_back(std::move(r));
    _load.push_back(linalg::column_vector(M));
    MatMult(M, _influence.back().vec(), _load.back().vec());
    VecScale(_load.back().vec(), -1.0);
  }
}

void GroundMotionLoad::assemble(int k, Vec f) const
{
  if (_sustained.vec())
    VecCopy(_sustained.vec(), f);
  else
    VecSet(f, 0.0);
  for (std::size_t i = 0; i < _active.size(); ++i)
    VecAXPY(f, _s.motion[_active[i]].acceleration[k], _load[i].vec());
}

void GroundMotionLoad::initial_acceleration(Vec a) const
{
  VecSet(a, 0.0);
  for (std::size_t i = 0; i < _active.size(); ++i)
  {
    VecAXPY(a, -_s.motion[_active[i]].acceleration[0], _influence[i].vec());
  }
}
} // namespace damseis::analysis
