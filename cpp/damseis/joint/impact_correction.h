// The impact correction of the joint pairs that close during a step
// (algorithms.md 2.7): their normal velocities keep the normal momentum and
// rebound with the restitution e (e = 1: kinetic energy kept, the paper;
// e = 0: they move together). The masses are the lumped masses at the pair
// nodes (the diagonal of M scaled to the total mass, HRZ lumping). Used
// after the steps of both joint steppers (linear and nonlinear bulk).
#pragma once

#include "condensed_contact.h"
#include <Eigen/Core>
#include <memory>
#include <vector>

namespace damseis::joint
{
/// Pairs closing from a gap narrower than this get no impact correction:
/// the gaps of nodes that carry almost no force (the vertices of P2 faces
/// under even pressure) flicker at the solver's precision, and rebounds
/// there would feed the flicker. 1 micrometre: far below the openings
/// engineers read (millimetres), far above the solver's gap precision.
constexpr double impact_min_gap = 1e-6; // m

class ImpactCorrection
{
public:
  /// M: the mass matrix of the unknowns `contact` acts on (with any added
  /// mass); `restitution` e in [0, 1]. Collective.
  ImpactCorrection(Mat M, const CondensedContact& contact, double restitution);
  ~ImpactCorrection();
  ImpactCorrection(const ImpactCorrection&) = delete;
  ImpactCorrection& operator=(const ImpactCorrection&) = delete;

  /// Per pair the gap before a step (0 for closed pairs).
  std::vector<double> gaps() const;
  /// The velocity change dv of the pairs that closed in the last step from
  /// a gap wider than impact_min_gap (`gap_before`: gaps() before the
  /// step), v the step's velocity; the number of such pairs (0: dv
  /// untouched). Collective.
  std::size_t correction(const std::vector<double>& gap_before, Vec v,
                         Vec dv) const;

private:
  /// The values of x at the pair nodes' unknowns, on rank 0.
  Eigen::VectorXd at_pairs(Vec x) const;

  const CondensedContact& _contact;
  double _e;
  VecScatter _to_root = nullptr; ///< pair unknowns to rank 0
  Vec _pair_values = nullptr;
  Eigen::VectorXd _mass;      ///< lumped mass at the pair unknowns (rank 0)
  std::vector<char> _movable; ///< both nodes of the pair have mass
};

/// What a joint stepper does around each time step: before it, the gaps
/// and the contact totals; after it, the impact correction (none with a
/// negative restitution) and the totals' increments over the step.
class ContactStepWork
{
public:
  /// M: the mass matrix of the unknowns (unused with restitution < 0).
  ContactStepWork(Mat M, CondensedContact& contact, double restitution);
  void before();
  /// The impact correction's velocity change into dv (v: the step's
  /// velocity); false if no pair closed (dv untouched). Collective.
  bool after(Vec v, Vec dv);
  /// The contact totals' increments over the last step.
  const ContactTotals& last() const { return _last; }

private:
  CondensedContact& _contact;
  std::unique_ptr<ImpactCorrection> _impact; ///< null: no correction
  std::vector<double> _gap_before;
  ContactTotals _before, _last;
};
} // namespace damseis::joint
