// The case keys of contact joints that every demo with joints shares:
// restitution of the impact correction and the static stage (how the dead
// weight is carried, the increments of the rest of the static load), the
// bonds of grouted joints. The demos add their own keys for which joints
// and their friction.
#pragma once

#include <array>
#include <damseis/contact/ncp.h>
#include <damseis/input/case.h>
#include <damseis/joint/static_contact.h>
#include <string>
#include <vector>

namespace damseis::analysis
{
/// joints.restitution, joints.impact_correction, joints.dead_load (default
/// `dead_load_default`), joints.static_increments, joints.formulation,
/// joints.history_points, joints.tensile_strength, joints.cohesion,
/// joints.initial_gap.
void add_joint_contact_keys(input::Schema& s,
                            const std::string& dead_load_default);

/// The restitution of the impact correction, or -1 without it.
double read_restitution(const input::Case& c);

/// The static stage's settings of the keys above.
joint::StaticContactSettings read_joint_statics(const input::Case& c);

/// joints.formulation: the NCP's form (algorithms.md 2.3, 2.4).
contact::NcpSettings read_ncp_settings(const input::Case& c);

/// joints.history_points: points (3 coordinates each) whose nearest pairs'
/// opening and sliding are recorded per step (empty: each joint's top
/// pair).
std::vector<std::array<double, 3>>
read_joint_history_points(const input::Case& c);

/// Per joint, in the demo's joint order: a grouted joint's bond until it
/// fails, or an ungrouted joint's initial gap.
struct JointConditions
{
  std::vector<double> tensile_strength; ///< [Pa]
  std::vector<double> cohesion;         ///< [Pa]
  std::vector<double> initial_gap;      ///< [m]
};

/// joints.tensile_strength, joints.cohesion and joints.initial_gap for
/// `joints` joints ([]: 0 each); `order` says the demo's joint order in
/// messages. Fails if a list has another length, a bond is given with the
/// paper's formulation, or a joint has both a bond and a gap.
JointConditions read_joint_conditions(const input::Case& c, std::size_t joints,
                                      const std::string& order);

/// Fails (input::InputError) if one of `keys` (the contact keys above and
/// the demo's own) is given while joints.model is not "contact".
void refuse_contact_keys_when_bonded(const input::Case& c,
                                     const std::vector<std::string>& keys);
} // namespace damseis::analysis
