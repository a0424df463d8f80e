#include "contact_run.h"
#include <sstream>

namespace damseis::joint
{
void save_contact(const CondensedContact& c, engine::Arrays& arrays)
{
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

void restore_contact(const engine::CheckpointData& data, CondensedContact& c)
{
  const std::size_t n = c.pairs().size();
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
  c.set_state(read("contact_g0", n), read("contact_w", 3 * n),
              read("contact_p", 3 * n), s,
              std::vector<char>(broken.begin(), broken.end()));
  const Eigen::VectorXd t = read("contact_totals", 7);
  ContactTotals& totals = c.totals();
  totals.solves = static_cast<long>(t[0]);
  totals.ncp_iterations = static_cast<long>(t[1]);
  totals.line_search_steps = static_cast<long>(t[2]);
  totals.gradient_steps = static_cast<long>(t[3]);
  totals.state_changes = static_cast<long>(t[4]);
  totals.impacts = static_cast<long>(t[5]);
  totals.bonds_broken = static_cast<long>(t[6]);
}

ContactTotals count_difference(const ContactTotals& b, const ContactTotals& a)
{
  return {b.solves - a.solves,
          b.ncp_iterations - a.ncp_iterations,
          b.line_search_steps - a.line_search_steps,
          b.gradient_steps - a.gradient_steps,
          b.state_changes - a.state_changes,
          b.impacts - a.impacts,
          b.bonds_broken - a.bonds_broken};
}

std::string contact_progress_note(const CondensedContact& c,
                                  const ContactTotals& last_step)
{
  std::size_t open = 0, slip = 0;
  for (auto s : c.states())
  {
    open += s == contact::PairState::open;
    slip += s == contact::PairState::slip;
  }
  std::ostringstream note;
  note << "  NCP " << last_step.ncp_iterations << " it, " << open << " open, "
       << slip << " sliding of " << c.states().size() << " pairs";
  return note.str();
}
} // namespace damseis::joint
