// The free field of vertically incident plane waves in a homogeneous
// elastic half-space (algorithms.md 3.6): an S wave for each horizontal
// component, a P wave for the vertical one, each reflected at the free
// surface z_s. With the incident displacement u_I(t) at the base z_b,
//   u(z, t)       = u_I(t - tau_up) + u_I(t - tau_dn),
//   sigma_iz(z,t) = rho c [-v_I(t - tau_up) + v_I(t - tau_dn)],
//   tau_up = (z - z_b) / c,  tau_dn = (2 z_s - z - z_b) / c,
// c = c_s for the horizontal components (sigma_xz, sigma_yz) and c_p for
// the vertical one (sigma_zz; sigma_xx = sigma_yy = lambda / (lambda + 2G)
// sigma_zz). The stress vanishes at z_s and the surface moves with twice
// the incident wave.
//
// Input (from_outcrop): the design record is the motion of the free
// surface (the outcrop). Each component's incident wave is half of it,
// delayed so that the three components arrive at the surface together,
// as recorded, one S-wave travel time (z_s - z_b) / c_s after t = 0:
//   u_I(t) = 1/2 u_s(t - (z_s - z_b) (1/c_s - 1/c)),
// and the surface moves as u_s(t - (z_s - z_b) / c_s). The model starts at
// rest. The record's velocity and displacement are integrated exactly for
// the piecewise-linear acceleration; a record that does not end at rest
// (final velocity or displacement above 1e-3 of its peak) is first
// baseline corrected (motion::remove_displacement_trend), so that the wave
// ends at rest.
#pragma once

#include "viscous_spring.h"
#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <vector>

namespace damseis::boundary
{
/// One sampled motion: acceleration linear between samples, velocity and
/// displacement its exact integrals, evaluated at any time (at rest
/// before the start; after the end, the last acceleration's motion is
/// not continued: the velocity stays and the displacement moves with it).
class SampledMotion
{
public:
  SampledMotion() = default;
  /// From rest at t = t_start: a(t_start + k dt) = a[k] for k >= 1 (at
  /// t_start itself the rest before it: a record whose first sample is
  /// not zero jumps just after it).
  SampledMotion(std::vector<double> a, double dt, double t_start = 0.0);
  double displacement(double t) const;
  double velocity(double t) const;
  double acceleration(double t) const;
  bool empty() const { return _a.empty(); }

private:
  /// (t - t_start) / dt, snapped to a sample within 1e-9 of an interval:
  /// the acceleration jumps at a record's first sample (and after its
  /// last), and the same point whose coordinates differ in their last bits
  /// (a mesh partitioned otherwise) must not fall on the jump's other side.
  double samples(double t) const;
  /// The sample interval of s = samples(t) >= 0 and the time into it.
  std::size_t interval(double s, double& tau) const;
  std::vector<double> _a, _v, _d;
  double _dt = 0.0, _t0 = 0.0;
};

/// The state of the free field at a point: displacement, velocity,
/// acceleration and the stresses on horizontal planes, per component (the
/// last component is the vertical one): s[i] = sigma_{i,z} (s[dim-1] =
/// sigma_zz).
struct FreeFieldState
{
  std::array<double, 3> u{}, v{}, a{}, s{};
};

/// A free field as the finite element load reads it at its nodes.
class FreeField
{
public:
  virtual ~FreeField() = default;
  /// The state at x (the last coordinate vertical), in a column whose
  /// ground is at z_ground, at step k, time t = k dt.
  virtual FreeFieldState at(const std::array<double, 3>& x, double z_ground,
                            int k, double t) const = 0;
  /// The velocity alone.
  virtual std::array<double, 3> velocity(const std::array<double, 3>& x,
                                         double z_ground, int k, double t) const
  {
    return at(x, z_ground, k, t).v;
  }
  /// The up-going incident wave alone at x, time t (the known field at
  /// the bottom of a transmitting boundary; its stress that of the wave
  /// alone); throws std::logic_error for a field that does not separate
  /// it.
  virtual FreeFieldState incident(const std::array<double, 3>& x,
                                  double t) const;
  /// How much later the free surface moves than the outcrop record [s].
  virtual double surface_delay() const = 0;
  /// Whether the record of component i was baseline corrected.
  virtual bool baseline_corrected(int i) const = 0;
  /// One line for the summary.
  virtual std::string description() const = 0;
};

/// The incident wave at the base of a column of `rock` and depth
/// z_surface - z_base whose free surface moves with the outcrop record
/// (see the file's comment): half of it, baseline corrected if it does
/// not end at rest, the vertical (P) component delayed so that all
/// arrive at the surface together. `corrected[i]`: whether component i
/// was corrected.
std::array<SampledMotion, 3>
incident_from_outcrop(const Rock& rock, int dim, double depth,
                      const std::array<std::vector<double>, 3>& outcrop,
                      double dt, std::array<bool, 3>& corrected);
/// The same with the travel times from the base to the surface of the S
/// and the P waves given (layers: the sums of h / c over them).
std::array<SampledMotion, 3>
incident_from_outcrop(int dim, double s_time, double p_time,
                      const std::array<std::vector<double>, 3>& outcrop,
                      double dt, std::array<bool, 3>& corrected);

class VerticalFreeField : public FreeField
{
public:
  /// `incident`: the incident wave's acceleration at the base per
  /// component (empty: none), sampled at dt. `z_base` < `z_surface`.
  VerticalFreeField(const Rock& rock, int dim, double z_base, double z_surface,
                    std::array<SampledMotion, 3> incident);

  /// The free field whose free surface moves with the outcrop motion
  /// `outcrop` (accelerations per component, empty: none; m/s2 at k dt),
  /// delayed by surface_delay(): see the file's comment.
  static VerticalFreeField
  from_outcrop(const Rock& rock, int dim, double z_base, double z_surface,
               const std::array<std::vector<double>, 3>& outcrop, double dt);
  /// Whether from_outcrop corrected the baseline of component i.
  bool baseline_corrected(int i) const override { return _corrected[i]; }
  FreeFieldState at(const std::array<double, 3>& x, double z_ground, int,
                    double t) const override
  {
    return at(x[_dim - 1], z_ground, t);
  }
  std::array<double, 3> velocity(const std::array<double, 3>& x,
                                 double z_ground, int, double t) const override
  {
    return velocity(x[_dim - 1], z_ground, t);
  }
  FreeFieldState incident(const std::array<double, 3>& x,
                          double t) const override;
  std::string description() const override;

  /// The state at height z (<= z_surface; above it, the surface's) and
  /// time t.
  FreeFieldState at(double z, double t) const { return at(z, _zs, t); }
  /// The same in a column whose free surface is at z_s (>= z_base: the
  /// local ground of a canyon, with the base's incident wave).
  FreeFieldState at(double z, double z_s, double t) const;
  /// The velocity alone (cheaper).
  std::array<double, 3> velocity(double z, double z_s, double t) const;

  /// The wave speed of component i (c_s horizontal, c_p vertical).
  double speed(int i) const { return i == _dim - 1 ? _rock.cp() : _rock.cs(); }
  /// How much later the surface (at z_surface) moves than the outcrop
  /// record. A column whose ground is lower sees the same incident wave
  /// earlier reflected.
  double surface_delay() const override { return (_zs - _zb) / _rock.cs(); }
  const Rock& rock() const { return _rock; }
  double z_base() const { return _zb; }
  double z_surface() const { return _zs; }

private:
  /// The times the up-going and the down-going wave of component i seen
  /// at height z (in a column with its surface at z_s) at time t left the
  /// base: t - tau_up, t - tau_dn.
  struct Arrivals
  {
    double up, down;
  };
  Arrivals arrivals(double z, double z_s, double t, int i) const;

  Rock _rock;
  int _dim;
  double _zb, _zs;
  std::array<SampledMotion, 3> _incident;
  std::array<bool, 3> _corrected{};
};

/// Two free fields side by side: `left` where x[0] < x_split, `right`
/// elsewhere (rock regions side by side, each column its own).
class SideBySideFreeField : public FreeField
{
public:
  SideBySideFreeField(double x_split, std::shared_ptr<const FreeField> left,
                      std::shared_ptr<const FreeField> right)
      : _x(x_split), _left(std::move(left)), _right(std::move(right))
  {
  }
  FreeFieldState at(const std::array<double, 3>& x, double z_ground, int k,
                    double t) const override
  {
    return (x[0] < _x ? *_left : *_right).at(x, z_ground, k, t);
  }
  std::array<double, 3> velocity(const std::array<double, 3>& x,
                                 double z_ground, int k,
                                 double t) const override
  {
    return (x[0] < _x ? *_left : *_right).velocity(x, z_ground, k, t);
  }
  FreeFieldState incident(const std::array<double, 3>& x,
                          double t) const override
  {
    return (x[0] < _x ? *_left : *_right).incident(x, t);
  }
  double surface_delay() const override
  {
    return std::max(_left->surface_delay(), _right->surface_delay());
  }
  bool baseline_corrected(int i) const override
  {
    return _left->baseline_corrected(i);
  }
  std::string description() const override;

private:
  double _x;
  std::shared_ptr<const FreeField> _left, _right;
};
} // namespace damseis::boundary
