// The free field of vertically incident waves in horizontally layered rock,
// computed on a 1D column (Lokke & Chopra's free-field column; algorithms.md
// 3.6 for the homogeneous closed form it reproduces): per component the 1D
// wave equation rho u_tt = (E_c u_z)_z (E_c = G for the horizontal
// components, the P modulus for the vertical one), linear elements with
// consistent mass, Newmark's average acceleration sub-stepped so that a
// step is at most the time a wave takes to cross the smallest element; at
// the bottom the half-space below the column (the lowest layer's rock):
// a dashpot rho c and the force 2 rho c v_I of the incident wave; the top
// free. The whole record is solved once; the field is then read at the
// record's steps.
#pragma once

#include "free_field.h"
#include <vector>

namespace damseis::boundary
{
/// A layer of rock, from the layer below (or the column's bottom) up to
/// `top` [m].
struct Layer
{
  double top = 0.0;
  Rock rock;
};

class LayeredColumn : public FreeField
{
public:
  /// Layers from the bottom z_base up (tops increasing; the last top is
  /// the free surface), at most `h_max` per element; the incident wave per
  /// component (empty: none), read at the steps k dt, k = 0..steps; `dim`
  /// 2 or 3 (the last component vertical).
  LayeredColumn(double z_base, const std::vector<Layer>& layers, int dim,
                const std::array<SampledMotion, 3>& incident, double dt,
                int steps, double h_max);

  /// The column whose incident wave is half the outcrop record
  /// (incident_from_outcrop with the layers' S and P travel times: every
  /// component reaches the surface the layers' S travel time late),
  /// elements of at most 1/20 of the shortest S wavelength at 25 Hz.
  static LayeredColumn
  from_outcrop(double z_base, const std::vector<Layer>& layers, int dim,
               const std::array<std::vector<double>, 3>& outcrop, double dt,
               int steps);

  /// The state at height z (clamped to the column) at step k.
  FreeFieldState at(double z, int k) const;
  FreeFieldState at(const std::array<double, 3>& x, double, int k,
                    double) const override
  {
    return at(x[_dim - 1], k);
  }
  double surface_delay() const override { return _delay; }
  bool baseline_corrected(int i) const override { return _corrected[i]; }
  std::string description() const override;
  double z_surface() const { return _z.back(); }
  int nodes() const { return static_cast<int>(_z.size()); }
  int substeps() const { return _m; }

private:
  std::vector<double> _z; ///< node heights
  int _dim, _steps, _m = 1;
  /// Per component, per step, per node: u, v, a and the stress
  /// sigma_{i,z} (nodal: the mean of the adjacent elements; 0 at the free
  /// surface).
  std::array<std::vector<double>, 3> _u, _v, _a, _s;
  std::array<bool, 3> _active{}, _corrected{};
  double _delay = 0.0; ///< the layers' S travel time
  std::size_t _layers = 0;
  void solve(int c, const std::vector<double>& modulus,
             const std::vector<double>& density, const SampledMotion& wave,
             double rho_c_bottom, double dt);
};
} // namespace damseis::boundary
