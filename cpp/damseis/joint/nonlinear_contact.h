// Joint contact on a nonlinear bulk (HTC concrete): the contact as a
// constraint of the Newton iteration of dynamics::NonlinearNewmark and
// dynamics::solve_static (dynamics/newton_constraint.h; instead of
// algorithms.md 2.6's monolithic Newton),
// condensed on the initial effective matrix J0 of the step length
// (CondensedContact: the pairs' flexibility W0 = G^T J0^-1 G computed once
// per factorisation of J0). Each Newton iterate z of the bulk is corrected
// by one condensed solve,
//   J0 u_k+1 = J0 z - G p_k + G p_k+1,   NCP(p_k+1, G^T u_k+1),
// the slip measured from the committed (last accepted) state. After each
// accepted step, the impact correction of the pairs that closed
// (impact_correction.h).
#pragma once

#include "condensed_contact.h"
#include "contact_run.h"
#include "impact_correction.h"
#include <damseis/dynamics/newton_constraint.h>
#include <memory>

namespace damseis::joint
{
class NonlinearContact : public dynamics::NewtonConstraint, public ContactRun
{
public:
  /// `contact`: the pairs and the state the run starts from; `M`: the mass
  /// matrix of the unknowns (impact correction) with `restitution` e in
  /// [0, 1], or negative for no impact correction (then M may be null).
  NonlinearContact(std::shared_ptr<CondensedContact> contact, Mat M,
                   double restitution);
  ~NonlinearContact() override;
  NonlinearContact(const NonlinearContact&) = delete;
  NonlinearContact& operator=(const NonlinearContact&) = delete;

  /// The pairs disconnected (no pair forces; a block's own support must
  /// carry it): the cantilevers' dead weight of the static stage.
  void set_disconnected(bool disconnected) { _disconnected = disconnected; }

  // dynamics::NewtonConstraint
  void factorize(Mat J0) override;
  void begin() override;
  Vec force() const override { return _force; }
  void start_iteration() override;
  void correct(Mat J0, Vec z) override;
  void blend(double eta) override;
  bool consistent() const override { return _consistent; }
  void accept() override;
  void reject() override;

  /// Around a time step: the gaps before it, and after it the velocity
  /// change of the impact correction into dv (false: none, dv untouched).
  void before_step();
  bool after_step(Vec v, Vec dv);

  // ContactRun
  const CondensedContact& contact() const override { return *_contact; }
  const ContactTotals& last_step() const override { return _work.last(); }
  CondensedContact& contact() { return *_contact; }

private:
  std::shared_ptr<CondensedContact> _contact;
  ContactStepWork _work; ///< impact correction and the step's totals
  bool _disconnected = false;
  /// The trial force, the base of the iteration and the corrected one.
  Vec _force = nullptr, _force_base = nullptr, _force_new = nullptr;
  Vec _rhs = nullptr;
  Eigen::VectorXd _p_base, _w_base, _p_new, _w_new;
  bool _corrected = false, _consistent = false;
};
} // namespace damseis::joint
