#include "nonlinear_contact.h"

namespace damseis::joint
{
NonlinearContact::NonlinearContact(std::shared_ptr<CondensedContact> contact,
                                   Mat M, double restitution)
    : _contact(std::move(contact)), _work(M, *_contact, restitution)
{
}

NonlinearContact::~NonlinearContact()
{
  for (Vec* x : {&_force, &_force_base, &_force_new, &_rhs})
    VecDestroy(x);
}

void NonlinearContact::factorize(Mat J0)
{
  _contact->factorize(J0);
  if (!_force)
  {
    for (Vec* x : {&_force, &_force_base, &_force_new, &_rhs})
      MatCreateVecs(J0, x, nullptr);
  }
}

void NonlinearContact::begin()
{
  _contact->rollback(); // the trial starts from the committed state
  if (_disconnected)
    VecSet(_force, 0.0);
  else
    _contact->force_vector(_force);
  _corrected = _consistent = false;
}

void NonlinearContact::start_iteration()
{
  VecCopy(_force, _force_base);
  _p_base = _contact->forces();
  _w_base = _contact->relative_displacement();
}

void NonlinearContact::correct(Mat J0, Vec z)
{
  // J0 u = J0 z - r_base + G p: the bulk's iterate plus the change of the
  // pair forces, with the pairs' NCP at u.
  if (_disconnected)
  {
    // No pair forces: the bulk's iterate stands.
    VecSet(_force_new, 0.0);
    _p_new = _contact->forces();
    _w_new = _contact->relative_displacement();
    _corrected = true;
    return;
  }
  MatMult(J0, z, _rhs);
  VecAXPY(_rhs, -1.0, _force_base);
  // The bonds an earlier iterate broke are judged again at this one.
  _contact->reset_bonds();
  _contact->solve_trial(_rhs, z, _force_new);
  _p_new = _contact->forces();
  _w_new = _contact->relative_displacement();
  _corrected = true;
}

void NonlinearContact::blend(double eta)
{
  VecAXPBYPCZ(_force, 1.0 - eta, eta, 0.0, _force_base, _force_new);
  if (eta == 1.0)
    _contact->set_trial(_p_new, _w_new);
  else
    _contact->set_trial(_p_base + eta * (_p_new - _p_base),
                        _w_base + eta * (_w_new - _w_base));
  _consistent = _corrected && eta == 1.0;
}

void NonlinearContact::accept()
{
  if (!_disconnected)
    _contact->commit();
}

void NonlinearContact::reject()
{
  _contact->rollback();
}

void NonlinearContact::before_step()
{
  _work.before();
}

bool NonlinearContact::after_step(Vec v, Vec dv)
{
  return _work.after(v, dv);
}
} // namespace damseis::joint
