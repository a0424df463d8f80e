#include "design_spectrum.h"
#include "message.h"
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>
#include <stdexcept>

namespace damseis::motion
{
namespace
{
[[noreturn]] void bad(const std::string& what)
{
  throw std::invalid_argument(what);
}

void check_vertical_ratio(double ratio)
{
  if (!(ratio > 0 && ratio <= 1.5))
    bad("vertical ratio " + number_text(ratio) + "; expected 0 < ratio <= 1.5");
}

// beta_max by structure type: DL 5073-2000 Table 4.3.4 and NB 35047-2015
// (the same values). Gravity 2.0 and arch 2.5 are confirmed by worked
// solutions quoting DL 5073 Table 4.3.4; 2.25 and 1.6 by an independent
// NB 35047 implementation only (../shared/docs/algorithms.md §8.1).
double beta_max_of(DamType t)
{
  switch (t)
  {
  case DamType::gravity:
    return 2.00;
  case DamType::arch:
    return 2.50;
  case DamType::other_concrete:
    return 2.25;
  case DamType::earth_rock:
  default:
    return 1.60;
  }
}

// DL 5073-2000 Table 4.3.6: Tg by site class (class II confirmed by worked
// solutions quoting the code; I, III, IV as recorded in
// ../shared/docs/algorithms.md §8.1, unconfirmed: override with tg).
// §4.3.6 also lengthens Tg by 0.05 s for a structure whose fundamental
// period exceeds 1 s where the design intensity is at most 8; that depends
// on the structure, so it is left to the tg key (documented in --help).
double tg_dl5073(const std::string& site)
{
  static const std::map<std::string, double> tg = {
      {"I", 0.20}, {"II", 0.30}, {"III", 0.40}, {"IV", 0.65}};
  const auto it = tg.find(site);
  if (it == tg.end())
    bad("site class \"" + site +
        "\" is not one of DL 5073-2000's; expected I, II, III or IV");
  return it->second;
}

// NB 35047-2015 takes Tg from the zoning map (GB 18306-2015): the class II
// value 0.35, 0.40 or 0.45 s adjusted by site class, GB 18306-2015 Table 1
// (0.40 -> I1 0.30 and III 0.55 confirmed by worked solutions quoting
// NB 35047 Table 5.3.5; the rest as recorded in ../shared/docs/algorithms.md
// §8.1).
double tg_nb35047(const std::string& site, double tg_map)
{
  static const std::map<double, std::map<std::string, double>> table = {
      {0.35,
       {{"I0", 0.20}, {"I1", 0.25}, {"II", 0.35}, {"III", 0.45}, {"IV", 0.65}}},
      {0.40,
       {{"I0", 0.25}, {"I1", 0.30}, {"II", 0.40}, {"III", 0.55}, {"IV", 0.75}}},
      {0.45,
       {{"I0", 0.30},
        {"I1", 0.35},
        {"II", 0.45},
        {"III", 0.65},
        {"IV", 0.90}}}};
  const auto row = std::find_if(table.begin(), table.end(),
                                [&](const auto& r)
                                { return std::abs(r.first - tg_map) < 1e-9; });
  if (row == table.end())
    bad("zoning-map characteristic period " + number_text(tg_map) +
        " s is not in GB 18306-2015; expected 0.35, 0.40 or 0.45");
  const auto it = row->second.find(site);
  if (it == row->second.end())
    bad("site class \"" + site +
        "\" is not one of NB 35047-2015's; expected I0, I1, II, III or IV");
  return it->second;
}

// EN 1998-1:2004 Tables 3.2 (type 1) and 3.3 (type 2): S, TB, TC, TD
// (every value confirmed against two independent implementations).
struct Ec8Row
{
  double s, tb, tc, td;
};
Ec8Row ec8_row(bool type1, const std::string& ground)
{
  static const std::map<std::string, Ec8Row> t1 = {
      {"A", {1.00, 0.15, 0.4, 2.0}},
      {"B", {1.20, 0.15, 0.5, 2.0}},
      {"C", {1.15, 0.20, 0.6, 2.0}},
      {"D", {1.35, 0.20, 0.8, 2.0}},
      {"E", {1.40, 0.15, 0.5, 2.0}}};
  static const std::map<std::string, Ec8Row> t2 = {
      {"A", {1.00, 0.05, 0.25, 1.2}},
      {"B", {1.35, 0.05, 0.25, 1.2}},
      {"C", {1.50, 0.10, 0.25, 1.2}},
      {"D", {1.80, 0.10, 0.30, 1.2}},
      {"E", {1.60, 0.05, 0.25, 1.2}}};
  const auto& t = type1 ? t1 : t2;
  const auto it = t.find(ground);
  if (it == t.end())
    bad("ground type \"" + ground +
        "\" is not one of Eurocode 8's; expected A, B, C, D or E");
  return it->second;
}
} // namespace

DesignSpectrum::DesignSpectrum(const DesignSpectrumSettings& s) : _s(s)
{
  const bool table = s.code == SpectrumCode::table;
  if (!table && (!(s.pga > 0) || !std::isfinite(s.pga)))
    bad("design acceleration " + number_text(s.pga) + " m/s2; expected > 0");
  if (table && (!(s.pga >= 0) || !std::isfinite(s.pga)))
    bad("peak ground acceleration " + number_text(s.pga) +
        " m/s2 of a spectrum table; expected >= 0 (0: Sa at T = 0)");
  switch (s.code)
  {
  case SpectrumCode::dl5073_2000:
  case SpectrumCode::nb35047_2015:
  {
    const bool dl = s.code == SpectrumCode::dl5073_2000;
    _tg = s.tg ? *s.tg
               : (dl ? tg_dl5073(s.site_class)
                     : tg_nb35047(s.site_class, s.tg_map));
    _beta_max = s.beta_max ? *s.beta_max : beta_max_of(s.dam);
    if (!(_tg > 0.1 && _tg <= 3.0))
      bad("Tg = " + number_text(_tg) + " s; expected 0.1 < Tg <= 3");
    if (!(_beta_max >= 1.0 && _beta_max <= 5.0))
      bad("beta_max = " + number_text(_beta_max) +
          "; expected 1 <= beta_max <= 5");
    _gamma = dl ? 0.9 : 0.6;
    // Vertical design acceleration: 2/3 of the horizontal (DL 5073-2000
    // §4.3.3, NB 35047-2015 the same), or the given ratio.
    check_vertical_ratio(s.vertical_ratio);
    _a = s.vertical ? s.vertical_ratio * s.pga : s.pga;
    break;
  }
  case SpectrumCode::ec8_type1:
  case SpectrumCode::ec8_type2:
  {
    const bool type1 = s.code == SpectrumCode::ec8_type1;
    if (!(s.damping > 0 && s.damping < 1))
      bad("damping ratio " + number_text(s.damping) +
          "; expected 0 < damping < 1");
    // eta = sqrt(10 / (5 + xi)) >= 0.55, xi in percent (§3.2.2.2(3)).
    _eta = std::max(0.55, std::sqrt(10.0 / (5.0 + 100.0 * s.damping)));
    if (s.vertical)
    {
      // Table 3.4: avg / ag 0.90 (type 1) or 0.45 (type 2); TB 0.05,
      // TC 0.15, TD 1.0 s; plateau 3.0 (§3.2.2.3); no soil factor.
      _a = (type1 ? 0.90 : 0.45) * s.pga;
      _soil = 1.0;
      _tb = 0.05;
      _tg = 0.15;
      _td = 1.0;
      _plateau = 3.0;
    }
    else
    {
      const Ec8Row r = ec8_row(type1, s.site_class);
      _a = s.pga;
      _soil = r.s;
      _tb = r.tb;
      _tg = r.tc;
      _td = r.td;
      _plateau = 2.5;
    }
    break;
  }
  case SpectrumCode::table:
  {
    check_vertical_ratio(s.vertical_ratio);
    const auto& t = s.table_period;
    const auto& sa = s.table_sa;
    if (t.size() < 2 || t.size() != sa.size())
      bad("a spectrum table needs at least two (period, Sa) pairs of equal "
          "length; got " +
          std::to_string(t.size()) + " periods and " +
          std::to_string(sa.size()) + " values");
    if (s.pga == 0 && t.front() != 0)
      bad("a spectrum table starting at " + number_text(t.front()) +
          " s and no peak ground acceleration; expected a table from T = 0 "
          "or the PGA");
    for (std::size_t i = 0; i < t.size(); ++i)
    {
      if (!(t[i] >= 0) || (i > 0 && !(t[i] > t[i - 1])))
        bad("spectrum table periods must be >= 0 and increasing (period " +
            std::to_string(i + 1) + " = " + number_text(t[i]) + " s)");
      if (!(sa[i] > 0) || !std::isfinite(sa[i]))
        bad("spectrum table value " + std::to_string(i + 1) + " = " +
            number_text(sa[i]) + " m/s2; expected > 0");
    }
    // A vertical target is the table scaled by the ratio, once.
    if (s.vertical)
    {
      for (double& v : _s.table_sa)
        v *= s.vertical_ratio;
      _s.pga *= s.vertical_ratio;
    }
    break;
  }
  }
}

double DesignSpectrum::operator()(double period) const
{
  if (!(period >= 0))
    throw std::invalid_argument("period " + number_text(period) +
                                " s; expected >= 0");
  const double t = period;
  switch (_s.code)
  {
  case SpectrumCode::dl5073_2000:
  case SpectrumCode::nb35047_2015:
  {
    // beta: 1 at T = 0, linear to beta_max at 0.1 s, flat to Tg, then
    // beta_max (Tg / T)^gamma, not below 0.2 beta_max (DL 5073-2000
    // §4.3.5 with Tables 4.3.4 and 4.3.6; NB 35047-2015 §5.3 the same
    // shape with gamma = 0.6).
    double beta = 0;
    if (t <= 0.1)
      beta = 1.0 + (_beta_max - 1.0) * t / 0.1;
    else if (t <= _tg)
      beta = _beta_max;
    else
      beta = std::max(_beta_max * std::pow(_tg / t, _gamma), 0.2 * _beta_max);
    return _a * beta;
  }
  case SpectrumCode::ec8_type1:
  case SpectrumCode::ec8_type2:
  {
    // EN 1998-1 eq. (3.2)-(3.5) and (3.8)-(3.11).
    const double top = _a * _soil * _eta * _plateau;
    if (t <= _tb)
      return _a * _soil * (1.0 + t / _tb * (_eta * _plateau - 1.0));
    if (t <= _tg)
      return top;
    if (t <= _td)
      return top * _tg / t;
    return top * _tg * _td / (t * t);
  }
  case SpectrumCode::table:
  default:
  {
    const auto& p = _s.table_period;
    const auto& sa = _s.table_sa;
    if (t < p.front() - 1e-12 || t > p.back() + 1e-12)
      throw std::out_of_range(
          "period " + number_text(t) + " s is outside the spectrum table (" +
          number_text(p.front()) + " to " + number_text(p.back()) + " s)");
    const auto it = std::upper_bound(p.begin(), p.end(), t);
    const std::size_t i = std::clamp<std::size_t>(
        static_cast<std::size_t>(it - p.begin()), 1, p.size() - 1);
    const double w = (t - p[i - 1]) / (p[i] - p[i - 1]);
    return (1 - w) * sa[i - 1] + w * sa[i];
  }
  }
}

double DesignSpectrum::min_period() const
{
  return _s.code == SpectrumCode::table ? _s.table_period.front() : 0.0;
}

double DesignSpectrum::max_period() const
{
  return _s.code == SpectrumCode::table ? _s.table_period.back() : HUGE_VAL;
}

double DesignSpectrum::pga() const
{
  return _s.code == SpectrumCode::table && _s.pga > 0 ? _s.pga : (*this)(0.0);
}

std::string DesignSpectrum::describe() const
{
  std::ostringstream out;
  out << std::fixed << std::setprecision(2) << to_string(_s.code);
  switch (_s.code)
  {
  case SpectrumCode::dl5073_2000:
  case SpectrumCode::nb35047_2015:
    out << ", " << to_string(_s.dam) << " dam, site " << _s.site_class
        << " (Tg " << _tg << " s, beta_max " << _beta_max << ")";
    break;
  case SpectrumCode::ec8_type1:
  case SpectrumCode::ec8_type2:
    out << ", ground " << _s.site_class << ", " << 100 * _s.damping
        << "% damping";
    break;
  case SpectrumCode::table:
    out << " of " << _s.table_period.size() << " points";
    break;
  }
  out << ", a = " << pga() << " m/s2";
  out << (_s.vertical ? ", vertical" : ", horizontal");
  return out.str();
}

SpectrumCode parse_spectrum_code(const std::string& name)
{
  static const std::map<std::string, SpectrumCode> codes = {
      {"DL5073-2000", SpectrumCode::dl5073_2000},
      {"NB35047-2015", SpectrumCode::nb35047_2015},
      {"EC8-type1", SpectrumCode::ec8_type1},
      {"EC8-type2", SpectrumCode::ec8_type2},
      {"table", SpectrumCode::table}};
  const auto it = codes.find(name);
  if (it == codes.end())
    bad("unknown design spectrum \"" + name +
        "\"; expected \"DL5073-2000\", \"NB35047-2015\", \"EC8-type1\", "
        "\"EC8-type2\" or \"table\"");
  return it->second;
}

DamType parse_dam_type(const std::string& name)
{
  static const std::map<std::string, DamType> types = {
      {"gravity", DamType::gravity},
      {"arch", DamType::arch},
      {"other_concrete", DamType::other_concrete},
      {"earth_rock", DamType::earth_rock}};
  const auto it = types.find(name);
  if (it == types.end())
    bad("unknown dam type \"" + name +
        "\"; expected gravity, arch, other_concrete or earth_rock");
  return it->second;
}

std::string to_string(SpectrumCode code)
{
  switch (code)
  {
  case SpectrumCode::dl5073_2000:
    return "DL5073-2000";
  case SpectrumCode::nb35047_2015:
    return "NB35047-2015";
  case SpectrumCode::ec8_type1:
    return "EC8-type1";
  case SpectrumCode::ec8_type2:
    return "EC8-type2";
  case SpectrumCode::table:
  default:
    return "table";
  }
}

std::string to_string(DamType type)
{
  switch (type)
  {
  case DamType::gravity:
    return "gravity";
  case DamType::arch:
    return "arch";
  case DamType::other_concrete:
    return "other_concrete";
  case DamType::earth_rock:
  default:
    return "earth_rock";
  }
}
} // namespace damseis::motion
