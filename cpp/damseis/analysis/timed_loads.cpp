#include "timed_loads.h"
#include <damseis/linalg/petsc_vectors.h>

namespace damseis::analysis
{
LoadWithTimedTerms::LoadWithTimedTerms(const engine::DynamicLoad& base,
                                       const std::vector<TimedLoad>& terms,
                                       Mat tie)
    : _base(base)
{
  for (const TimedLoad& t : terms)
  {
    if (tie)
    {
      // The load on the tied unknowns: P^T F (work-conjugate to u = P u_r).
      dolfinx::la::petsc::Vector y = linalg::column_vector(tie);
      MatMultTranspose(tie, t.load, y.vec());
      _loads.push_back(std::move(y));
    }
    else
    {
      Vec y;
      VecDuplicate(t.load, &y);
      VecCopy(t.load, y);
      _loads.emplace_back(y, false);
    }
    _histories.push_back(t.history);
  }
}

void LoadWithTimedTerms::assemble(int k, Vec f) const
{
  _base.assemble(k, f);
  for (std::size_t i = 0; i < _loads.size(); ++i)
  {
    const double h =
        k < static_cast<int>(_histories[i].size()) ? _histories[i][k] : 0.0;
    if (h != 0.0)
      VecAXPY(f, h, _loads[i].vec());
  }
}
} // namespace damseis::analysis
