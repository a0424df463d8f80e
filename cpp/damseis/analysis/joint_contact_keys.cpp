#include "joint_contact_keys.h"

namespace damseis::analysis
{
void add_joint_contact_keys(input::Schema& s,
                            const std::string& dead_load_default)
{
  s.real("joints.restitution", "1", "-",
         "contact: restitution of the impact correction (1: kinetic energy "
         "kept, the paper; 0: the nodes move together)")
      .between(0, 1);
  s.boolean("joints.impact_correction", "true", "-",
            "contact: correct the velocities of pairs that close (the "
            "paper's momentum and energy balance)");
  s.string("joints.dead_load", dead_load_default, "-",
           "contact: the dead weight with the joints active, or carried by "
           "the blocks alone (cantilever: joints grouted afterwards)",
           {"joints_active", "cantilever"});
  s.integer("joints.static_increments", "5", "-",
            "contact: increments of the static load beyond the dead weight")
      .between(1, 1000);
}

double read_restitution(const input::Case& c)
{
  return c.boolean("joints.impact_correction") ? c.real("joints.restitution")
                                               : -1.0;
}

joint::StaticContactSettings read_joint_statics(const input::Case& c)
{
  joint::StaticContactSettings s;
  s.cantilever_dead_load = c.string("joints.dead_load") == "cantilever";
  s.increments = static_cast<int>(c.integer("joints.static_increments"));
  return s;
}

void refuse_contact_keys_when_bonded(const input::Case& c,
                                     const std::vector<std::string>& keys)
{
  if (c.string("joints.model") == "contact")
    return;
  std::vector<std::string> all = {
      "joints.restitution", "joints.impact_correction", "joints.dead_load",
      "joints.static_increments"};
  all.insert(all.end(), keys.begin(), keys.end());
  for (const auto& key : all)
  {
    if (c.is_set(key))
      c.fail(key,
             "is given while joints.model = \"" + c.string("joints.model") +
                 "\"",
             "joints.model = \"contact\" for frictional joints");
  }
}
} // namespace damseis::analysis
