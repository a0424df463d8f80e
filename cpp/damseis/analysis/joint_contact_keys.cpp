#include "joint_contact_keys.h"
#include <algorithm>
#include <utility>

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
  s.string("joints.formulation", "alart_curnier", "-",
           "contact: the NCP's unknowns, Cartesian (Alart-Curnier) or the "
           "paper's polar form (P_n, P_tau, theta); bench/results/"
           "ncp-formulations-*.md compares them",
           {"alart_curnier", "paper"});
  s.real_array("joints.tensile_strength", "[]", "Pa",
               "contact: tensile strength of each joint's bond (grouted "
               "joints; lost for good where the joint opens or slides), in "
               "the order of the joints' friction ([]: 0 each, the paper's)")
      .between(0, 1e8);
  s.real_array("joints.cohesion", "[]", "Pa",
               "contact: cohesion of each joint's bond (shear strength "
               "cohesion + friction x compression until the bond fails), in "
               "the order of the joints' friction ([]: 0 each)")
      .between(0, 1e8);
  s.real_array("joints.initial_gap", "[]", "m",
               "contact: each joint's opening at the start (ungrouted "
               "joints: the shrinkage gap the faces close before they touch), "
               "in the order of the joints' friction ([]: 0 each, closed)")
      .between(0, 1);
  s.real_array("joints.history_points", "[]", "m",
               "contact: points (x, y, z each) whose nearest pairs' opening "
               "and sliding are recorded per step (joint_histories.csv); "
               "[]: the top pair of each joint");
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

contact::NcpSettings read_ncp_settings(const input::Case& c)
{
  contact::NcpSettings s;
  s.formulation = c.string("joints.formulation") == "paper"
                      ? contact::Formulation::paper
                      : contact::Formulation::alart_curnier;
  return s;
}

std::vector<std::array<double, 3>>
read_joint_history_points(const input::Case& c)
{
  const auto x = c.reals("joints.history_points");
  if (x.size() % 3 != 0)
    c.fail("joints.history_points",
           "has " + std::to_string(x.size()) +
               " values, not 3 coordinates per point",
           "x, y, z of each point, one after the other");
  std::vector<std::array<double, 3>> points;
  for (std::size_t i = 0; i < x.size(); i += 3)
    points.push_back({x[i], x[i + 1], x[i + 2]});
  return points;
}

JointConditions read_joint_conditions(const input::Case& c, std::size_t joints,
                                      const std::string& order)
{
  JointConditions b;
  for (auto [key, out] :
       {std::pair{"joints.tensile_strength", &b.tensile_strength},
        std::pair{"joints.cohesion", &b.cohesion},
        std::pair{"joints.initial_gap", &b.initial_gap}})
  {
    std::vector<double> v = c.reals(key);
    if (!v.empty() && v.size() != joints)
      c.fail(key,
             "has " + std::to_string(v.size()) + " values for " +
                 std::to_string(joints) + " joints",
             "one value per joint (" + order + "), or [] for none");
    if (v.empty())
      v.assign(joints, 0.0);
    const bool bonded =
        std::any_of(v.begin(), v.end(), [](double x) { return x > 0.0; });
    if (bonded && out != &b.initial_gap &&
        c.string("joints.formulation") == "paper")
      c.fail(key, "is given with joints.formulation = \"paper\"",
             "joints.formulation = \"alart_curnier\" for bonded joints");
    *out = std::move(v);
  }
  for (std::size_t j = 0; j < joints; ++j)
  {
    if (b.initial_gap[j] > 0.0 &&
        (b.tensile_strength[j] > 0.0 || b.cohesion[j] > 0.0))
      c.fail("joints.initial_gap",
             "opens joint " + std::to_string(j + 1) + " (" + order +
                 "), which has a bond (joints.tensile_strength or "
                 "joints.cohesion)",
             "a gap of 0 for a grouted joint, or no bond for an open one");
  }
  return b;
}

void refuse_contact_keys_when_bonded(const input::Case& c,
                                     const std::vector<std::string>& keys)
{
  if (c.string("joints.model") == "contact")
    return;
  std::vector<std::string> all = {
      "joints.restitution",      "joints.impact_correction",
      "joints.dead_load",        "joints.static_increments",
      "joints.history_points",   "joints.formulation",
      "joints.tensile_strength", "joints.cohesion",
      "joints.initial_gap"};
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
