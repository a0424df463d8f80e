#include "contact_stepper.h"
#include <algorithm>
#include <chrono>
#include <damseis/contact/impact.h>
#include <damseis/linalg/petsc_vectors.h>
#include <sstream>

namespace damseis::joint
{
namespace
{
using dolfinx::la::petsc::Vector;

double sum(Vec x)
{
  PetscScalar s = 0.0;
  VecSum(x, &s);
  return s;
}
} // namespace

ContactStepper::ContactStepper(Mat M, Mat K, dynamics::RayleighDamping damping,
                               dynamics::TimeScheme scheme,
                               std::shared_ptr<CondensedContact> contact,
                               Vec u_static, double restitution,
                               const std::vector<Mat>& extra_damping)
    : engine::LinearStepper(M, K, damping, scheme,
                            linalg::Factorization::automatic, extra_damping,
                            contact, u_static),
      _contact(std::move(contact)), _e(restitution)
{
  // The pair unknowns gathered on rank 0.
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(K));
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const auto& idx = _contact->unknowns();
  const PetscInt n = rank == 0 ? static_cast<PetscInt>(idx.size()) : 0;
  IS is;
  ISCreateGeneral(comm, n, idx.data(), PETSC_COPY_VALUES, &is);
  VecCreateSeq(PETSC_COMM_SELF, n, &_pair_values);
  Vector x(create_vector(), false);
  VecScatterCreate(x.vec(), is, _pair_values, nullptr, &_to_root);
  ISDestroy(&is);

  // Lumped masses at the pair nodes: the diagonal of M scaled to the total
  // mass (HRZ lumping; row sums would be negative at P2 vertices).
  Vector d(create_vector(), false), ones(create_vector(), false),
      row_sums(create_vector(), false);
  MatGetDiagonal(M, d.vec());
  VecSet(ones.vec(), 1.0);
  MatMult(M, ones.vec(), row_sums.vec());
  const double scale = sum(row_sums.vec()) / sum(d.vec());
  _mass = at_pairs(d.vec()) * scale;
  // Pairs whose two nodes have mass (the others get no impact correction:
  // a fixed or massless node has no velocity of its own, only Newmark's
  // by-product of its displacements, and no momentum to exchange).
  const auto& pairs = _contact->pairs();
  _movable.assign(pairs.size(), 0);
  if (rank == 0)
  {
    for (std::size_t i = 0; i < pairs.size(); ++i)
    {
      const Eigen::Vector3d n2 = pairs.frame[i].col(0).cwiseAbs2();
      _movable[i] = n2.dot(_mass.segment<3>(_contact->position1(i))) > 0.0 &&
                    n2.dot(_mass.segment<3>(_contact->position2(i))) > 0.0;
    }
  }
  MPI_Bcast(_movable.data(), static_cast<int>(_movable.size()), MPI_CHAR, 0,
            comm);
}

ContactStepper::~ContactStepper()
{
  VecScatterDestroy(&_to_root);
  VecDestroy(&_pair_values);
}

Eigen::VectorXd ContactStepper::at_pairs(Vec x) const
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

dynamics::StepReport ContactStepper::step(Vec f)
{
  std::vector<double> gap_before(_contact->pairs().size());
  for (std::size_t i = 0; i < gap_before.size(); ++i)
    gap_before[i] = _contact->states()[i] == contact::PairState::open
                        ? _contact->gap(i)
                        : 0.0;
  const ContactTotals before = _contact->totals();
  engine::LinearStepper::step(f);
  const auto t0 = std::chrono::steady_clock::now();
  if (_e >= 0.0)
    impact_correction(gap_before);
  ContactTotals& t = _contact->totals();
  t.seconds_impact +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
          .count();
  _last = {t.solves - before.solves,
           t.ncp_iterations - before.ncp_iterations,
           t.line_search_steps - before.line_search_steps,
           t.gradient_steps - before.gradient_steps,
           t.state_changes - before.state_changes,
           t.impacts - before.impacts,
           t.bonds_broken - before.bonds_broken};
  dynamics::StepReport report;
  report.iterations = static_cast<int>(_last.ncp_iterations);
  return report;
}

void ContactStepper::impact_correction(const std::vector<double>& gap_before)
{
  const auto& states = _contact->states();
  std::vector<std::size_t> closing;
  for (std::size_t i = 0; i < states.size(); ++i)
  {
    if (gap_before[i] > impact_min_gap &&
        states[i] != contact::PairState::open && _movable[i])
      closing.push_back(i);
  }
  if (closing.empty()) // the same on every rank (replicated states)
    return;
  _contact->totals().impacts += static_cast<long>(closing.size());
  const Eigen::VectorXd v = at_pairs(engine::LinearStepper::v());
  Vector dv(create_vector(), false);
  if (v.size() > 0) // rank 0
  {
    const auto& pairs = _contact->pairs();
    Eigen::VectorXd dv_s = Eigen::VectorXd::Zero(v.size());
    for (std::size_t i : closing)
    {
      const Eigen::Vector3d n = pairs.frame[i].col(0);
      const int a = _contact->position1(i), b = _contact->position2(i);
      const double ma = n.cwiseAbs2().dot(_mass.segment<3>(a));
      const double mb = n.cwiseAbs2().dot(_mass.segment<3>(b));
      const contact::NormalVelocities before_impact{n.dot(v.segment<3>(a)),
                                                    n.dot(v.segment<3>(b))};
      const contact::NormalVelocities after =
          contact::impact(ma, mb, before_impact, _e);
      dv_s.segment<3>(a) += (after.a - before_impact.a) * n;
      dv_s.segment<3>(b) += (after.b - before_impact.b) * n;
    }
    const auto& idx = _contact->unknowns();
    VecSetValues(dv.vec(), static_cast<PetscInt>(idx.size()), idx.data(),
                 dv_s.data(), ADD_VALUES);
  }
  VecAssemblyBegin(dv.vec());
  VecAssemblyEnd(dv.vec());
  newmark().correct_velocity(dv.vec());
}

void ContactStepper::save(engine::Arrays& arrays) const
{
  engine::LinearStepper::save(arrays);
  const CondensedContact& c = *_contact;
  auto to_vector = [](const Eigen::VectorXd& x)
  { return std::vector<double>(x.data(), x.data() + x.size()); };
  arrays["contact_p"] = to_vector(c.forces());
  arrays["contact_w"] = to_vector(c.relative_displacement());
  arrays["contact_g0"] = to_vector(c.g0());
  std::vector<double> s;
  for (auto state : c.states())
    s.push_back(static_cast<double>(state));
  arrays["contact_state"] = s;
  arrays["contact_broken"] =
      std::vector<double>(c.broken().begin(), c.broken().end());
  const ContactTotals& t = c.totals();
  arrays["contact_totals"] = {static_cast<double>(t.solves),
                              static_cast<double>(t.ncp_iterations),
                              static_cast<double>(t.line_search_steps),
                              static_cast<double>(t.gradient_steps),
                              static_cast<double>(t.state_changes),
                              static_cast<double>(t.impacts),
                              static_cast<double>(t.bonds_broken)};
}

void ContactStepper::restore(const engine::CheckpointData& data)
{
  engine::LinearStepper::restore(data);
  const std::size_t n = _contact->pairs().size();
  auto read = [&](const char* name, std::size_t size)
  {
    const auto& a = engine::checkpoint_array(data, name, size);
    return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(
        a.data(), static_cast<Eigen::Index>(a.size())));
  };
  const Eigen::VectorXd states = read("contact_state", n);
  std::vector<contact::PairState> s(n);
  for (std::size_t i = 0; i < n; ++i)
    s[i] = static_cast<contact::PairState>(static_cast<int>(states[i]));
  const Eigen::VectorXd broken = read("contact_broken", n);
  _contact->set_state(read("contact_g0", n), read("contact_w", 3 * n),
                      read("contact_p", 3 * n), s,
                      std::vector<char>(broken.begin(), broken.end()));
  const Eigen::VectorXd t = read("contact_totals", 7);
  ContactTotals& totals = _contact->totals();
  totals.solves = static_cast<long>(t[0]);
  totals.ncp_iterations = static_cast<long>(t[1]);
  totals.line_search_steps = static_cast<long>(t[2]);
  totals.gradient_steps = static_cast<long>(t[3]);
  totals.state_changes = static_cast<long>(t[4]);
  totals.impacts = static_cast<long>(t[5]);
  totals.bonds_broken = static_cast<long>(t[6]);
}

std::string ContactStepper::progress_note(const dynamics::StepReport&) const
{
  std::size_t open = 0, slip = 0;
  for (auto s : _contact->states())
  {
    open += s == contact::PairState::open;
    slip += s == contact::PairState::slip;
  }
  std::ostringstream note;
  note << "  NCP " << _last.ncp_iterations << " it, " << open << " open, "
       << slip << " sliding of " << _contact->states().size() << " pairs";
  return note.str();
}
} // namespace damseis::joint
