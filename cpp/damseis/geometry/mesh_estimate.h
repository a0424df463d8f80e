// Cell counts of a mesh estimated before meshing, to refuse absurd mesh
// sizes before gmsh spends minutes and gigabytes on them.
#pragma once

namespace damseis::input
{
class Case;
}

namespace damseis::geometry
{
struct GravityDamSection;
struct ArchDamDefinition;

/// Triangles of size h in an area (equilateral: sqrt(3)/4 h^2 each).
double triangle_count(double area, double h);
/// Tetrahedra of size h in a volume (regular: h^3 / (6 sqrt 2) each;
/// gmsh's Delaunay meshes have about that many).
double tetrahedron_count(double volume, double h);

/// Estimated cells of a gravity-dam section (and its foundation block,
/// whose size grades from mesh_size to foundation_mesh_size: counted with
/// their mean). The section polygon must be valid (section_area).
double estimated_cells(const GravityDamSection& s);
/// Estimated cells of an arch dam and its foundation block (within 10% on
/// the presets; gravity sections with a foundation: up to 1.3 times the
/// real count).
double estimated_cells(const ArchDamDefinition& d);

/// Fails the case (input::InputError on mesh.size, with the estimate) if
/// `estimate` exceeds mesh.max_cells.
void check_cell_estimate(const input::Case& c, double estimate);
} // namespace damseis::geometry
