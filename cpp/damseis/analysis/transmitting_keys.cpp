#include "transmitting_keys.h"
#include <damseis/geometry/tags.h>
#include <sstream>

namespace damseis::analysis
{
void add_formula_keys(input::Schema& s)
{
  s.integer("foundation.mtf_order", "2", "-",
            "order N of the multi-transmitting formula (2 needs mesh.order "
            "= 1)")
      .between(1, 2);
  s.real("foundation.mtf_drift", "0.0001", "-",
         "drift control gamma_d of the multi-transmitting formula (b = 1 / "
         "(1 + gamma_d)): the boundary is fixed at zero frequency and "
         "reflects the frequencies with omega dt of the order of gamma_d")
      .between(0, 0.1);
  s.real("foundation.band_damping", "0.05", "-",
         "stiffness-proportional damping of the explicit band, as its ratio "
         "of critical at the band's highest frequency: it damps the band's "
         "shortest waves, with which the formula is unstable in 3D, and "
         "lowers the stable step by sqrt(1 + r^2) - r; unless set, 0.1 on "
         "P2 elements (a notched box needs more than 0.05 there)")
      .between(0, 0.5);
  s.string("foundation.band_integration", "explicit", "-",
           "the band's time integration: explicit with lumped mass (the "
           "Hughes-Liu partition, stable below the band's own step, stated "
           "in the log), or implicit with the rest (Newmark's average "
           "acceleration, consistent mass: only s = c_p dt / dx <= 1 bounds "
           "the step)",
           {"explicit", "implicit"});
}

void add_transmitting_keys(input::Schema& s, const std::string& where,
                           const std::string& band_size)
{
  add_formula_keys(s);
  s.integer("foundation.band_layers", "4", "-",
            "layers of cells in the structured band along the block's " +
                where +
                " (boundary = mtf): the formula reads 2N node spacings "
                "inward, 2N layers for P1, N for P2")
      .between(1, 20);
  s.real("foundation.band_size", band_size, "m",
         "cell size of the structured band (boundary = mtf); its node "
         "spacing (size / mesh.order) is the formula's dx, bounds c_p dt / "
         "dx <= 1 and sets the explicit band's stable time step")
      .above(0)
      .at_most(1000);
}

Transmitting read_formula_keys(const input::Case& c, int mesh_order,
                               bool active)
{
  Transmitting t;
  t.order = static_cast<int>(c.integer("foundation.mtf_order"));
  t.drift = c.real("foundation.mtf_drift");
  t.band_explicit = c.string("foundation.band_integration") == "explicit";
  t.band_damping = c.real("foundation.band_damping");
  if (mesh_order == 2 && !c.is_set("foundation.band_damping"))
    t.band_damping = 0.1; // tests/fem/test_mtf_box.cpp: 0.05 is not enough
  if (active && mesh_order == 2 && t.order == 2)
    c.fail("foundation.mtf_order",
           "2 drifts away on P2 elements (the band's lumped lattice "
           "alternates vertex and midside masses; tests/fem/"
           "test_mtf_boundary.cpp)",
           "mesh.order = 1, or foundation.mtf_order = 1");
  return t;
}

Transmitting read_transmitting_keys(const input::Case& c, int mesh_order,
                                    bool active, BandKeys& band)
{
  Transmitting t = read_formula_keys(c, mesh_order, active);
  t.band_regions = {geometry::tags::foundation_band};
  band.layers = static_cast<int>(c.integer("foundation.band_layers"));
  band.size = c.real("foundation.band_size");
  t.spacing = band.size / mesh_order;
  if (!active)
    return t;
  // The stencil: nodes k = 0 .. 2N along the normal, mesh_order node
  // spacings per layer.
  const int needed = (2 * t.order + mesh_order - 1) / mesh_order;
  if (band.layers < needed)
    c.fail("foundation.band_layers",
           "is too few for the formula's stencil (2N = " +
               std::to_string(2 * t.order) +
               " node spacings inward of the boundary)",
           "at least " + std::to_string(needed) + " layers");
  return t;
}

void check_transmitting_step(const input::Case& c, double hht_alpha,
                             const Transmitting& t, bool nonlinear_engine,
                             const boundary::Rock& rock, double dt,
                             const std::string& coarser)
{
  if (hht_alpha != 0.0 && t.band_explicit)
    c.fail("time.hht_alpha",
           "must be 0 with a multi-transmitting boundary's explicit band "
           "(the implicit-explicit partition is Newmark's average "
           "acceleration)",
           "time.hht_alpha = 0, or foundation.band_integration = "
           "\"implicit\"");
  if (hht_alpha != 0.0 && !nonlinear_engine)
    c.fail("time.hht_alpha",
           "must be 0 with a multi-transmitting boundary in the linear "
           "engine (its partition is Newmark's average acceleration)",
           "time.hht_alpha = 0, or material.model = \"elastic\" (the same "
           "elastic dam in the nonlinear engine, which takes HHT alpha with "
           "the band implicit)");
  const double spacing = t.spacing;
  const double courant = rock.cp() * dt / spacing;
  if (courant > 1.0)
  {
    std::ostringstream problem, fix;
    problem << "is too large for the multi-transmitting boundary: s = c_p dt "
               "/ dx = "
            << courant << " (c_p " << rock.cp() << " m/s, dx " << spacing
            << " m) must be at most 1";
    fix << "time.dt at most " << spacing / rock.cp()
        << " s (the explicit band's stable step is smaller still: the run "
           "states it), or "
        << coarser;
    c.fail("time.dt", problem.str(), fix.str());
  }
}
} // namespace damseis::analysis
