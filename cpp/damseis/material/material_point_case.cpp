#include "material_point_case.h"

#include <cmath>
#include <damseis/results/output_folder.h>
#include <sstream>
#include <stdexcept>

namespace damseis::material
{

void add_concrete_keys(input::Schema& s, const std::string& pre)
{
  const std::string p = pre + ".";
  s.string(p + "mode", "viscoplastic", "-",
           "Constitutive law: elastic, plastic (rate-independent, s = 0) or "
           "viscoplastic (consistency model)",
           {"elastic", "plastic", "viscoplastic"});
  s.real(p + "E", "24e9", "Pa", "Young's modulus (static)").above(0);
  s.real(p + "nu", "0.17", "-",
         "Poisson's ratio (concrete: 0.1..0.3; the model needs nu <= 0.45)")
      .between(0.0, 0.45);
  s.real(p + "fc0", "30e6", "Pa", "Static uniaxial compressive strength")
      .above(0);
  s.real(p + "ft0", "2.5e6", "Pa", "Static uniaxial tensile strength").above(0);
  s.string(p + "htc_shape", "calibrated", "-",
           "HTC calibration points: calibrated (fbc_ratio, xi0, rho0) or "
           "classic (those of A=2.0108, B=0.9714, C=9.1412, D=0.2312)",
           {"calibrated", "classic"});
  s.real(p + "fbc_ratio", "1.15", "-", "Equibiaxial / uniaxial compression")
      .above(1);
  s.real(p + "xi0", "1.95", "-", "Triaxial point: -sigma_oct / fc").above(0);
  s.real(p + "rho0", "1.61", "-", "Triaxial point: tau_oct / fc").above(0);
  s.real(p + "Gf", "200", "N/m", "Tensile fracture energy").above(0);
  s.real(p + "Gc", "20e3", "N/m", "Compressive fracture energy").above(0);
  s.real(p + "element_size", "0.1", "m", "Crack-band width h").above(0);
  s.string(p + "rate_law", "ceb_fip", "-",
           "Rate function R(kappa_dot): ceb_fip (power law fitted to the "
           "CEB-FIP DIF), linear (1 + eta kappa_dot) or none",
           {"ceb_fip", "linear", "none"});
  s.real(p + "eta_c", "0", "s", "Linear rate law: compression viscosity")
      .at_least(0);
  s.real(p + "eta_t", "0", "s", "Linear rate law: tension viscosity")
      .at_least(0);
  s.boolean(p + "dynamic_30_percent", "false", "-",
            "Multiply E, fc0, ft0 by dynamic_factor (Chinese specification)");
  s.real(p + "dynamic_factor", "1.3", "-", "Factor of dynamic_30_percent")
      .above(0);
}

ConcreteParameters read_concrete_parameters(const input::Case& c,
                                            const std::string& pre)
{
  const std::string p = pre + ".";
  ConcreteParameters m;
  const std::string mode = c.string(p + "mode");
  m.mode = mode == "elastic"   ? Mode::elastic
           : mode == "plastic" ? Mode::plastic
                               : Mode::viscoplastic;
  m.E = c.real(p + "E");
  m.nu = c.real(p + "nu");
  m.fc0 = c.real(p + "fc0");
  m.ft0 = c.real(p + "ft0");
  m.classic_shape = c.string(p + "htc_shape") == "classic";
  m.fbc_ratio = c.real(p + "fbc_ratio");
  m.xi0 = c.real(p + "xi0");
  m.rho0 = c.real(p + "rho0");
  m.Gf = c.real(p + "Gf");
  m.Gc = c.real(p + "Gc");
  m.element_size = c.real(p + "element_size");
  const std::string law = c.string(p + "rate_law");
  m.rate_law = law == "ceb_fip"  ? RateLaw::ceb_fip
               : law == "linear" ? RateLaw::linear
                                 : RateLaw::none;
  m.eta_c = c.real(p + "eta_c");
  m.eta_t = c.real(p + "eta_t");
  m.dynamic_30_percent = c.boolean(p + "dynamic_30_percent");
  m.dynamic_factor = c.real(p + "dynamic_factor");
  if (m.ft0 >= m.fc0)
    c.fail(p + "ft0", "= " + std::to_string(m.ft0) + " is not below fc0",
           "ft0 < fc0");
  try
  {
    HtcConcrete check(m);
  }
  catch (const std::invalid_argument& e)
  {
    c.fail(pre, e.what(), "a consistent set of material parameters");
  }
  return m;
}

input::Schema material_point_schema()
{
  input::Schema s;
  add_concrete_keys(s, "material");
  s.string("path.kind", "uniaxial", "-",
           "uniaxial (stress), biaxial (plane stress, strain ratio), "
           "triaxial (confinement then axial strain), cyclic (uniaxial "
           "stress through turning points)",
           {"uniaxial", "biaxial", "triaxial", "cyclic"});
  s.real("path.strain_rate", "1e-5", "1/s", "Axial strain rate (magnitude)")
      .between(1e-9, 1e4);
  s.real("path.max_strain", "5e-4", "-",
         "Final axial strain eps11 (tension > 0); not for cyclic")
      .between(-0.1, 0.1);
  s.real("path.ratio", "0.5", "-", "biaxial: eps22 / eps11").between(-1, 1);
  s.real("path.confinement", "10e6", "Pa",
         "triaxial: lateral compressive stress (magnitude)")
      .between(0, 1e9);
  s.real_array("path.turning_points", "[1e-4, -1e-3, 2e-4, -3e-3]", "-",
               "cyclic: successive eps11 targets")
      .between(-0.1, 0.1);
  s.real("path.strain_step", "1e-6", "-", "Axial strain per step")
      .between(1e-9, 1e-2);
  s.string("output.csv", "material_point.csv", "-",
           "CSV file name in the output folder (the plot takes its name "
           "with .png)");
  s.boolean("output.plots", "true", "-",
            "write the PNG plot (needs python3-matplotlib)");
  results::add_overwrite_key(s);
  return s;
}

MaterialPointConfig read_material_point_config(const input::Case& c)
{
  MaterialPointConfig cfg;
  cfg.material = read_concrete_parameters(c, "material");
  cfg.csv_name = c.string("output.csv");
  if (cfg.csv_name.empty() ||
      cfg.csv_name.find_first_of("/\\") != std::string::npos ||
      cfg.csv_name == "." || cfg.csv_name == ".." || cfg.csv_name.size() < 5 ||
      cfg.csv_name.substr(cfg.csv_name.size() - 4) != ".csv")
    c.fail("output.csv", "= \"" + cfg.csv_name + "\" is not a plain file name",
           "a name like material_point.csv (no folder; --out sets it)");
  cfg.plots = c.boolean("output.plots");
  const std::string kind = c.string("path.kind");
  const double rate = c.real("path.strain_rate");
  const double step = c.real("path.strain_step");
  const double emax = c.real("path.max_strain");
  // At most max_steps steps per segment (counted in double: no overflow).
  constexpr double max_steps = 1e6;
  auto steps_for = [&](double de)
  {
    const double n = std::ceil(std::abs(de) / step);
    if (!(n <= max_steps))
      c.fail("path.strain_step",
             "gives " + (std::ostringstream() << n).str() +
                 " steps in a segment of the path",
             "at most 1e6 steps per segment: a larger path.strain_step");
    return std::max(1, static_cast<int>(n));
  };
  if (kind != "cyclic" && emax == 0.0)
    c.fail("path.max_strain", "= 0", "a nonzero final strain");
  Segment s;
  s.control.fill(Control::stress);
  s.control[0] = Control::strain;
  s.duration = std::abs(emax) / rate;
  s.steps = steps_for(emax);
  s.target = {emax, 0, 0, 0, 0, 0};
  if (kind == "uniaxial")
  {
    s.tie[2] = 1;
    cfg.segments = {s};
  }
  else if (kind == "biaxial")
  {
    s.control[1] = Control::strain;
    s.target[1] = c.real("path.ratio") * emax;
    cfg.segments = {s};
  }
  else if (kind == "triaxial")
  {
    const double q = c.real("path.confinement");
    Segment conf;
    conf.control.fill(Control::stress);
    conf.target = {-q, -q, -q, 0, 0, 0};
    const double K = cfg.material.E / (3 * (1 - 2 * cfg.material.nu));
    conf.steps = std::max(10, steps_for(q / (3 * K)));
    conf.duration = q / (3 * K) / rate + 1e-12;
    s.target = {emax, -q, -q, 0, 0, 0};
    s.tie[2] = 1;
    if (q > 0)
      cfg.segments = {conf, s};
    else
      cfg.segments = {s};
  }
  else
  {
    const auto tp = c.reals("path.turning_points");
    if (tp.empty())
      c.fail("path.turning_points", "is empty", "at least one strain");
    double prev = 0;
    for (double e : tp)
    {
      Segment g = s;
      g.tie[2] = 1;
      g.target[0] = e;
      g.duration = std::max(std::abs(e - prev), 1e-12) / rate;
      g.steps = steps_for(e - prev);
      cfg.segments.push_back(g);
      prev = e;
    }
  }
  return cfg;
}

} // namespace damseis::material
