// What the joint recorders read from a time history with contact joints:
// the contact state after each step and the contact work of the step.
// Implemented by the steppers of the linear bulk (ContactStepper) and of
// the nonlinear bulk (NonlinearContact, through the concrete stepper).
#pragma once

#include "condensed_contact.h"
#include <damseis/engine/parts.h>

namespace damseis::joint
{
class ContactRun
{
public:
  virtual ~ContactRun() = default;
  virtual const CondensedContact& contact() const = 0;
  /// The contact totals' increments over the last step (the same on every
  /// rank).
  virtual const ContactTotals& last_step() const = 0;
};

/// The contact state (forces, relative displacements, gap references, pair
/// states, bonds, totals) into a checkpoint's arrays, and back.
void save_contact(const CondensedContact& c, engine::Arrays& arrays);
void restore_contact(const engine::CheckpointData& data, CondensedContact& c);

/// b - a of the counts (the seconds are not differences: zero).
ContactTotals count_difference(const ContactTotals& b, const ContactTotals& a);

/// "  NCP <it> it, <open> open, <slip> sliding of <n> pairs".
std::string contact_progress_note(const CondensedContact& c,
                                  const ContactTotals& last_step);
} // namespace damseis::joint
