#include "impact_correction.h"
#include "contact_run.h"
#include <chrono>
#include <damseis/contact/impact.h>

namespace damseis::joint
{
namespace
{
double sum(Vec x)
{
  PetscScalar s = 0.0;
  VecSum(x, &s);
  return s;
}
} // namespace

ImpactCorrection::ImpactCorrection(Mat M, const CondensedContact& contact,
                                   double restitution)
    : _contact(contact), _e(restitution)
{
  // The pair unknowns gathered on rank 0.
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(M));
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const auto& idx = _contact.unknowns();
  const PetscInt n = rank == 0 ? static_cast<PetscInt>(idx.size()) : 0;
  IS is;
  ISCreateGeneral(comm, n, idx.data(), PETSC_COPY_VALUES, &is);
  VecCreateSeq(PETSC_COMM_SELF, n, &_pair_values);
  Vec x;
  MatCreateVecs(M, &x, nullptr);
  VecScatterCreate(x, is, _pair_values, nullptr, &_to_root);
  VecDestroy(&x);
  ISDestroy(&is);

  // Lumped masses at the pair nodes: the diagonal of M scaled to the total
  // mass (HRZ lumping; row sums would be negative at P2 vertices).
  Vec d, ones, row_sums;
  MatCreateVecs(M, &d, nullptr);
  VecDuplicate(d, &ones);
  VecDuplicate(d, &row_sums);
  MatGetDiagonal(M, d);
  VecSet(ones, 1.0);
  MatMult(M, ones, row_sums);
  const double scale = sum(row_sums) / sum(d);
  _mass = at_pairs(d) * scale;
  for (Vec* y : {&d, &ones, &row_sums})
    VecDestroy(y);
  // Pairs whose two nodes have mass (the others get no impact correction:
  // a fixed or massless node has no velocity of its own, only Newmark's
  // by-product of its displacements, and no momentum to exchange).
  const auto& pairs = _contact.pairs();
  _movable.assign(pairs.size(), 0);
  if (rank == 0)
  {
    for (std::size_t i = 0; i < pairs.size(); ++i)
    {
      const Eigen::Vector3d n2 = pairs.frame[i].col(0).cwiseAbs2();
      _movable[i] = n2.dot(_mass.segment<3>(_contact.position1(i))) > 0.0 &&
                    n2.dot(_mass.segment<3>(_contact.position2(i))) > 0.0;
    }
  }
  MPI_Bcast(_movable.data(), static_cast<int>(_movable.size()), MPI_CHAR, 0,
            comm);
}

ImpactCorrection::~ImpactCorrection()
{
  VecScatterDestroy(&_to_root);
  VecDestroy(&_pair_values);
}

Eigen::VectorXd ImpactCorrection::at_pairs(Vec x) const
{
  VecScatterBegin(_to_root, x, _pair_values, INSERT_VALUES, SCATTER_FORWARD);
  VecScatterEnd(_to_root, x, _pair_values, INSERT_VALUES, SCATTER_FORWARD);
  PetscInt n = 0;
  VecGetLocalSize(_pair_values, &n);
  const double* a = nullptr;
  VecGetArrayRead(_pair_values, &a);
  Eigen::VectorXd out = Eigen::Map<const Eigen::VectorXd>(a, n);
  VecRestoreArrayRead(_pair_values, &a);
  return out;
}

std::vector<double> ImpactCorrection::gaps() const
{
  std::vector<double> g(_contact.pairs().size());
  for (std::size_t i = 0; i < g.size(); ++i)
    g[i] = _contact.states()[i] == contact::PairState::open ? _contact.gap(i)
                                                            : 0.0;
  return g;
}

std::size_t ImpactCorrection::correction(const std::vector<double>& gap_before,
                                         Vec v, Vec dv) const
{
  const auto& states = _contact.states();
  std::vector<std::size_t> closing;
  for (std::size_t i = 0; i < states.size(); ++i)
  {
    if (gap_before[i] > impact_min_gap &&
        states[i] != contact::PairState::open && _movable[i])
      closing.push_back(i);
  }
  if (closing.empty()) // the same on every rank (replicated states)
    return 0;
  const Eigen::VectorXd v_pairs = at_pairs(v);
  VecSet(dv, 0.0);
  if (v_pairs.size() > 0) // rank 0
  {
    const auto& pairs = _contact.pairs();
    Eigen::VectorXd dv_s = Eigen::VectorXd::Zero(v_pairs.size());
    for (std::size_t i : closing)
    {
      const Eigen::Vector3d n = pairs.frame[i].col(0);
      const int a = _contact.position1(i), b = _contact.position2(i);
      const double ma = n.cwiseAbs2().dot(_mass.segment<3>(a));
      const double mb = n.cwiseAbs2().dot(_mass.segment<3>(b));
      const contact::NormalVelocities before{n.dot(v_pairs.segment<3>(a)),
                                             n.dot(v_pairs.segment<3>(b))};
      const contact::NormalVelocities after =
          contact::impact(ma, mb, before, _e);
      dv_s.segment<3>(a) += (after.a - before.a) * n;
      dv_s.segment<3>(b) += (after.b - before.b) * n;
    }
    const auto& idx = _contact.unknowns();
    VecSetValues(dv, static_cast<PetscInt>(idx.size()), idx.data(), dv_s.data(),
                 ADD_VALUES);
  }
  VecAssemblyBegin(dv);
  VecAssemblyEnd(dv);
  return closing.size();
}

ContactStepWork::ContactStepWork(Mat M, CondensedContact& contact,
                                 double restitution)
    : _contact(contact)
{
  if (restitution >= 0.0)
    _impact = std::make_unique<ImpactCorrection>(M, _contact, restitution);
}

void ContactStepWork::before()
{
  _before = _contact.totals();
  if (_impact)
    _gap_before = _impact->gaps();
}

bool ContactStepWork::after(Vec v, Vec dv)
{
  const auto t0 = std::chrono::steady_clock::now();
  std::size_t closing = 0;
  if (_impact)
    closing = _impact->correction(_gap_before, v, dv);
  ContactTotals& t = _contact.totals();
  t.impacts += static_cast<long>(closing);
  t.seconds_impact +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
          .count();
  _last = count_difference(t, _before);
  return closing > 0;
}
} // namespace damseis::joint
