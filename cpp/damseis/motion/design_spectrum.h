/// @file design_spectrum.h
/// Design (target) acceleration spectra: the Chinese hydraulic-structure
/// codes DL 5073-2000 and NB 35047-2015, the Eurocode 8 elastic spectra
/// (types 1 and 2, horizontal and vertical) and a user table.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace damseis::motion
{
enum class SpectrumCode
{
  dl5073_2000,  ///< DL 5073-2000 (and SL 203-97): descending exponent 0.9
  nb35047_2015, ///< NB 35047-2015 (and GB 51247-2018): exponent 0.6
  ec8_type1,    ///< EN 1998-1 §3.2.2.2, type 1 (Ms > 5.5)
  ec8_type2,    ///< EN 1998-1 §3.2.2.2, type 2 (Ms <= 5.5)
  table         ///< user (period, Sa) pairs, linear in between
};

/// Structure type of the Chinese codes (sets beta_max).
enum class DamType
{
  gravity,        ///< beta_max 2.00
  arch,           ///< beta_max 2.50
  other_concrete, ///< sluice, intake tower, other concrete: 2.25
  earth_rock      ///< earth and rockfill dams: 1.60
};

struct DesignSpectrumSettings
{
  SpectrumCode code = SpectrumCode::nb35047_2015;
  DamType dam = DamType::arch;
  /// Site class: DL 5073 "I".."IV"; NB 35047 "I0", "I1", "II", "III",
  /// "IV"; Eurocode 8 "A".."E".
  std::string site_class = "II";
  /// NB 35047: characteristic period of the zoning map for class II sites
  /// (0.35, 0.40 or 0.45 s; GB 18306-2015), adjusted by site class.
  double tg_map = 0.40;
  /// Design peak ground acceleration of the component [m/s2]: a_h for the
  /// Chinese codes, a_g for Eurocode 8 (ground type A); for a table the
  /// PGA of the motion (0: the table's Sa at T = 0, which it must give).
  double pga = 0.0;
  /// Vertical component: the Chinese codes and tables take vertical_ratio
  /// (2/3) of the horizontal spectrum; Eurocode 8 its vertical spectrum
  /// (Table 3.4).
  bool vertical = false;
  double vertical_ratio = 2.0 / 3.0;
  /// Overrides of the code tables (Chinese codes), if given.
  std::optional<double> tg, beta_max;
  /// Viscous damping ratio (Eurocode 8's eta; the Chinese spectra are
  /// for 5%).
  double damping = 0.05;
  /// SpectrumCode::table: periods (increasing, s) and Sa (m/s2) of the
  /// horizontal motion; `vertical` scales them by vertical_ratio.
  std::vector<double> table_period, table_sa;
};

/// Sa(T) of a design spectrum, m/s2. Construction checks the settings and
/// throws std::invalid_argument naming the value and what is expected.
class DesignSpectrum
{
public:
  explicit DesignSpectrum(const DesignSpectrumSettings& s);
  /// Pseudo-acceleration at period T >= 0 [m/s2]. Chinese codes: defined to
  /// 3 s, continued by the same law beyond (with its floor). A table:
  /// throws std::out_of_range outside its periods.
  double operator()(double period) const;
  /// Peak ground acceleration of the motion, m/s2: Sa at T = 0, or for a
  /// table the settings' pga if given.
  double pga() const;
  /// The characteristic period Tg (Chinese codes) or TC (Eurocode 8), s;
  /// 0 for a table.
  double corner_period() const { return _tg; }
  /// beta_max of the Chinese codes (0 otherwise).
  double beta_max() const { return _beta_max; }
  /// Periods where the spectrum is defined: [0, inf) for the codes, the
  /// table's range for a table.
  double min_period() const;
  double max_period() const;
  /// One line, e.g. "NB 35047-2015, arch dam, site I1 (Tg 0.30 s, beta_max
  /// 2.50), a = 3.15 m/s2, horizontal".
  std::string describe() const;

private:
  DesignSpectrumSettings _s;
  double _tg = 0, _beta_max = 0, _gamma = 0, _a = 0;
  // Eurocode 8: soil factor, corner periods, plateau factor, eta.
  double _soil = 1, _tb = 0, _td = 0, _plateau = 2.5, _eta = 1;
};

/// Names used in case files and messages.
SpectrumCode parse_spectrum_code(const std::string& name);
DamType parse_dam_type(const std::string& name);
std::string to_string(SpectrumCode code);
std::string to_string(DamType type);
} // namespace damseis::motion
