// Parametric double-curvature arch dam in a canyon: the definition (the
// way dam designers give it, level by level), its evaluation and the
// reference integrals (volume, face areas) used to verify the meshes.
//
// Coordinates: x along the dam axis (cross-canyon, the left bank seen
// looking downstream has the smaller x), y in the river direction
// (downstream positive), z vertical up; the base of the crown cantilever is
// at z = 0 and the crest at z = height. Units: m.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace damseis::geometry
{
/// Plan shape of the arch rings (of their centre line).
enum class ArchShape
{
  circular,      ///< one radius (radius_central)
  three_centred, ///< central arc (radius_central, half-angle central_angle)
                 ///< continued tangentially by lateral arcs (radius_lateral)
  parabolic      ///< y = y_c + x^2 / (2 radius_central)
};

/// Interpolation of the level tables between the levels.
enum class LevelInterpolation
{
  linear, ///< piecewise linear (C0)
  cubic   ///< natural cubic spline (C2); linear for two levels
};

/// Canyon cross-section (the valley is prismatic along y).
enum class CanyonShape
{
  v,     ///< straight walls from the floor (bottom_width) to crest_width
  u,     ///< floor, circular fillets of radius u_radius, straight walls
  points ///< piecewise-linear wall coordinates given per elevation
};

/// @brief The dam body, defined per elevation (the "levels").
///
/// Each ring (horizontal section) at elevation z is the band of half-width
/// T/2 on either side of a centre line (plan curve) along its normal. The
/// centre line passes through the crown point (0, y_c) with y_c =
/// crown_upstream_y + crown_thickness / 2 and is symmetric about x = 0.
/// The thickness grows from the crown to the abutments:
/// T = T_c + (T_a - T_c) |xi|^p, xi = x_c / X(z), where x_c is the x of
/// the centre-line point, X(z) the distance from x = 0 to the canyon wall
/// on that side at that elevation and p = thickening_exponent. The tables
/// are interpolated in z (interpolation), linearly extrapolated outside
/// [levels.front(), levels.back()].
struct ArchDamShape
{
  double height = 102;        ///< crest elevation [m] (base at z = 0)
  std::vector<double> levels; ///< elevations of the tables, 0 ... height
  /// y of the upstream face at the crown (crown cantilever profile) [m]
  std::vector<double> crown_upstream_y;
  std::vector<double> crown_thickness;    ///< crown thickness T_c [m]
  std::vector<double> abutment_thickness; ///< thickness at the walls T_a [m]
  ArchShape shape = ArchShape::three_centred;
  /// Centre-line radius at the crown (radius of curvature for parabolic) [m]
  std::vector<double> radius_central;
  std::vector<double> radius_lateral; ///< three-centred: lateral arcs [m]
  /// three-centred: half-angle of the central arc [deg]
  std::vector<double> central_angle_deg;
  double thickening_exponent = 2; ///< p in T_c + (T_a - T_c)|xi|^p
  LevelInterpolation interpolation = LevelInterpolation::cubic;
};

/// Canyon profile. x_left < 0 < x_right are wall x coordinates.
struct CanyonDefinition
{
  CanyonShape shape = CanyonShape::v;
  double bottom_width = 20;    ///< floor width at z = 0 (v, u) [m]
  double crest_width = 300;    ///< valley width at the crest elevation [m]
  double u_radius = 40;        ///< fillet radius (u) [m]
  int u_segments = 12;         ///< straight segments per fillet (u)
  std::vector<double> z;       ///< points: elevations, 0 ... >= height
  std::vector<double> x_left;  ///< points: left wall x (< 0) [m]
  std::vector<double> x_right; ///< points: right wall x (> 0) [m]
};

/// Foundation block extents as multiples of the dam height.
struct FoundationDefinition
{
  double upstream = 1.0;   ///< beyond the most upstream dam point
  double downstream = 1.0; ///< beyond the most downstream dam point
  double below = 1.0;      ///< below the canyon floor (z = 0)
  double beyond = 1.0;     ///< beyond each valley rim (crest-level walls)
};

/// Vertical contraction joints (radial planes at crest points).
struct JointDefinition
{
  /// Number of candidate positions, evenly spaced in arc length along
  /// the crest centre line (used when `positions` is empty).
  int count = 0;
  /// Candidate positions as fractions (0, 1) of the crest centre-line arc
  /// length from the left wall, increasing; labelled A, B, ... in order.
  std::vector<double> positions;
  /// Labels of the candidates that are joints (e.g. "DGJ"); empty: all.
  std::string active;
};

/// Mesh options.
struct ArchMeshOptions
{
  double size = 10.0;  ///< element size in the dam [m]
  double size_far = 0; ///< size at the far foundation (0: 4 x size) [m]
  /// distance (multiple of the height) over which the size grades from
  /// `size` at the dam to `size_far`
  double grading_distance = 0.5;
  /// minimum number of elements through the crown thickness (0: off); the
  /// dam size becomes min(size, T_c(z) / dam_layers)
  int dam_layers = 0;
  int sections = 0;     ///< lofted sections (0: automatic = 12)
  int arch_points = 17; ///< points per face spline of a section
  bool optimize = true; ///< gmsh tetrahedron optimisation (Netgen off)
  /// Duplicate the joint nodes (true) or keep the joint surfaces as
  /// interior, untagged facets of one conforming mesh (false: the jointless
  /// model of the same mesh, to check that bonded joints reproduce it).
  bool split_joints = true;
  /// Reservoir level [m above the dam base]. Strictly between 0 and the
  /// height: the dam is cut at this elevation (the mesh follows the water
  /// line) and the upstream face below it is tagged upstream_wetted.
  double water_level = 0;
  /// A structured band of `band_layers` layers of cells of `band_size` [m]
  /// along the foundation block's bottom, sides and upstream and
  /// downstream faces (a transmitting boundary's band; 0: none), in
  /// pieces, unstructured beside a wall of several segments
  /// (geometry/arch_band).
  int band_layers = 0;
  double band_size = 0;
};

/// Everything that defines an arch-dam model.
struct ArchDamDefinition
{
  ArchDamShape dam;
  CanyonDefinition canyon;
  FoundationDefinition foundation;
  JointDefinition joints;
  ArchMeshOptions mesh;
};

/// A contraction joint: label, plane (point and unit normal = the crest
/// centre-line tangent, pointing from side 1 (left) into side 2 (right)).
struct JointPlane
{
  int label_index = 0; ///< 0 for 'A', 1 for 'B', ...
  char label = 'A';
  double fraction = 0;           ///< position along the crest arc length (0, 1)
  std::array<double, 3> point{}; ///< crest centre-line point (z = height)
  std::array<double, 3> normal{}; ///< horizontal unit normal
};

/// Piecewise interpolation of a table y(z) (linear or natural cubic),
/// linearly extrapolated outside the table.
class LevelTable
{
public:
  LevelTable() = default;
  LevelTable(std::vector<double> z, std::vector<double> y,
             LevelInterpolation kind);
  double operator()(double z) const;

private:
  std::vector<double> _z, _y, _m; // _m: second derivatives (cubic)
  bool _cubic = false;
};

/// @brief Evaluation of an ArchDamDefinition: canyon walls, arch rings,
/// faces, reference integrals and joint planes.
///
/// The constructor validates the definition and throws
/// std::invalid_argument naming the offending field (e.g. "dam.levels:
/// ...") for impossible input.
class ArchDamGeometry
{
public:
  explicit ArchDamGeometry(const ArchDamDefinition& def);

  const ArchDamDefinition& definition() const { return _def; }
  double height() const { return _def.dam.height; }

  /// Canyon polyline (z, x_left, x_right), z increasing from 0.
  const std::vector<std::array<double, 3>>& canyon_profile() const
  {
    return _canyon;
  }
  /// Left / right wall x at elevation z (piecewise linear; constant below
  /// 0, linearly extrapolated above the last point).
  double x_left(double z) const;
  double x_right(double z) const;

  /// Arch-ring parameters at elevation z.
  struct Ring
  {
    double y_c, t_c, t_a, r_c, r_l, phi_c;
  };
  Ring ring(double z) const;

  /// Centre-line point (x, y) at elevation z; theta is the angle of the
  /// tangent (cos theta, sin theta) with the x axis, the curve parameter.
  std::array<double, 2> centre(double z, double theta) const;
  /// Radius of curvature of the centre line.
  double curvature_radius(double z, double theta) const;
  /// Thickness at (z, theta).
  double thickness(double z, double theta) const;
  /// Face point: side -1 upstream, +1 downstream, 0 centre line.
  std::array<double, 3> face_point(double z, double theta, int side) const;
  /// theta of the centre-line point with abscissa x at elevation z.
  double theta_at_x(double z, double x) const;
  /// theta where the face `side` reaches abscissa x at elevation z.
  double face_theta_at_x(double z, double x, int side) const;
  /// Signed offset of (x, y) at elevation z from the centre line along
  /// its downstream normal (negative upstream) and the theta of the foot.
  std::array<double, 2> offset(double z, double x, double y) const;
  /// Range of theta of the over-long ring at z used by the loft: both
  /// faces extend `margin` beyond the walls.
  std::array<double, 2> loft_theta_range(double z, double margin) const;

  /// Area of the ring at z inside the canyon (Green's theorem, Gauss).
  double section_area(double z) const;
  /// Dam volume, upstream (side -1) / downstream (+1) face areas (below
  /// z_top, if given: e.g. the wetted part), crest area: independent
  /// quadrature of the parametric shape.
  double volume() const;
  double face_area(int side, double z_top = -1) const;
  double crest_area() const { return section_area(height()); }
  /// Smallest radius of curvature of the faces (horizontal) over the dam.
  double min_face_radius() const;

  /// Crest centre-line arc length between the walls.
  double crest_length() const;
  /// The joints (active candidates), ordered by label (= by x).
  std::vector<JointPlane> joint_planes() const;

private:
  void validate() const;
  ArchDamDefinition _def;
  std::vector<std::array<double, 3>> _canyon;
  LevelTable _yu, _tc, _ta, _rc, _rl, _phi;
};

/// The box of the foundation and the valley: x over the valley rims and
/// `beyond`, y over the dam and `upstream` / `downstream`, z from `below`
/// the floor to the crest (all multiples of the height, FoundationDefinition).
struct ModelBox
{
  double x0, x1, y0, y1, z0, z1;
};
ModelBox model_box(const ArchDamGeometry& g);

/// Distance [m] from p = (x, y, z) to the model (the dam and the rock of
/// the model box below the valley surface); 0 inside. In the valley (water
/// or air) it is the distance to the dam body, measured along the normal
/// of the centre line, or to the nearer wall or the floor if less.
double distance_from_model(const ArchDamGeometry& g,
                           const std::array<double, 3>& p);

/// Letter of a joint label index (0 -> 'A').
inline char joint_label(int index)
{
  return static_cast<char>('A' + index);
}
} // namespace damseis::geometry
