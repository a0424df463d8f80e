// 2D gravity-dam section (with an optional foundation block), built and
// meshed with gmsh and distributed as a DOLFINx mesh.
#pragma once

#include <filesystem>

#include "gmsh_mesh.h"

#include <array>
#include <mpi.h>

namespace damseis::geometry
{
/// @brief Geometry and mesh parameters of a 2D gravity-dam section, in
/// metres. The defaults are the Koyna dam (non-overflow monolith).
///
/// The dam polygon is, counter-clockwise: heel (heel_x, base_y), toe
/// (toe_x, base_y), neck (neck_x, neck_y), downstream crest corner
/// (crest_down_x, crest_y), upstream crest corner (heel_x, crest_y). The
/// upstream face is vertical.
struct GravityDamSection
{
  double heel_x = 0;     ///< x of the heel (and of the vertical upstream face)
  double toe_x = 70;     ///< x of the toe
  double base_y = 0;     ///< elevation of the dam base
  double neck_x = 19.25; ///< x of the downstream slope change
  double neck_y = 66.5;  ///< elevation of the downstream slope change
  double crest_down_x = 14.8; ///< x of the downstream crest corner
  double crest_y = 103;       ///< crest elevation
  /// A mesh node is placed on the upstream face at this elevation (only
  /// if strictly between base_y and crest_y).
  double water_level = 91.75;
  double mesh_size = 2.0;  ///< target element size in the dam [m]
  bool foundation = false; ///< add a foundation block below the dam
  /// Total width of the foundation block [m], centred on the dam base
  /// midpoint; must exceed the base width toe_x - heel_x.
  double foundation_width = 0;
  double foundation_depth = 0; ///< depth of the foundation block [m]
  /// Element size at the far foundation boundaries (0 -> 2.5 x
  /// mesh_size); the size grades from mesh_size at the dam base.
  double foundation_mesh_size = 0;
  /// The block in two rock regions (tags foundation and foundation_2):
  /// none; side_by_side (split at the middle of the dam base: foundation
  /// on the left, foundation_2 on the right); layers (split at
  /// `split_depth` below the base: foundation above, foundation_2 below).
  enum class Split
  {
    none,
    side_by_side,
    layers
  };
  Split foundation_split = Split::none;
  double split_depth = 0; ///< [m] below base_y, for Split::layers
  /// A structured band along the block's sides and bottom (a transmitting
  /// boundary's, fem/mtf_boundary.h): `band_layers` layers of square cells
  /// of size `band_size` [m] (each split into two triangles), tagged
  /// foundation_band; 0: none. Needs Split::none.
  int band_layers = 0;
  double band_size = 0;
};

/// @brief Builds the section with gmsh on rank 0, meshes it with linear
/// triangles (Frontal-Delaunay) and returns the distributed model.
///
/// gmsh is initialised and finalised inside this function on rank 0 (it
/// must not be in use by the caller). Tags (tags.h): regions dam = 1,
/// foundation = 2; facets upstream_face = 1 (x = heel_x, full height),
/// downstream_face = 2 (toe -> neck -> downstream crest corner), crest =
/// 3, dam_base = 4 (heel -> toe; the dam-foundation interface when there
/// is a foundation), foundation_bottom = 5, foundation_sides = 6 (left and
/// right verticals), reservoir_floor = 7 (foundation top upstream of the
/// heel), foundation_top_downstream = 8 (downstream of the toe). The dam
/// and the foundation are conforming (they share the base curve). With a
/// band (band_layers > 0) its cells are the region foundation_band = 4.
///
/// Collective on `comm`.
/// @param[in] comm Communicator over which the mesh is distributed.
/// @param[in] s The section.
/// @param[in] verbose If true, gmsh writes its terminal output.
/// @param[in] mesh_file If not empty, rank 0 also writes the gmsh mesh
/// there (.msh; its physical groups named as in tags.h), for
/// geometry::read_mesh_file and the user's own studies.
/// @return The mesh with cell and facet tags.
/// @throws std::invalid_argument for an impossible section (non-positive
/// or non-finite sizes, crest below the neck, foundation narrower than
/// the base, ...), on all ranks.
Model build_gravity_dam(MPI_Comm comm, const GravityDamSection& s,
                        bool verbose = false,
                        const std::filesystem::path& mesh_file = {});

/// The dam section polygon counterclockwise from the heel: heel, toe, neck,
/// downstream crest corner, upstream crest corner (x, y, 0).
std::array<std::array<double, 3>, 5>
section_outline(const GravityDamSection& s);

/// Distance [m] from the point (x, y) to the model (the dam polygon and,
/// with a foundation, its block); 0 inside or on the boundary. The polygon
/// must be valid (section_area).
double distance_from_model(const GravityDamSection& s, double x, double y);

/// @brief Area of the dam section polygon (closed form, shoelace).
/// @param[in] s The section (the dam polygon is validated).
/// @return The area [m^2].
/// @throws std::invalid_argument for an impossible dam polygon.
double section_area(const GravityDamSection& s);
} // namespace damseis::geometry
