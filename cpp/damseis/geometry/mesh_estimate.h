// Cell counts of a mesh estimated before meshing, to refuse absurd mesh
// sizes before gmsh spends minutes and gigabytes on them.
#pragma once

#include <string>

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

/// The size of an analysis, estimated before meshing from its cell count.
struct SizeEstimate
{
  double cells = 0;
  double dofs = 0;
  double memory_gb = 0;   ///< peak resident memory, all ranks together
  double ms_per_step = 0; ///< a linear time step (factors reused)
};

/// Dofs from the cells (Lagrange P1/P2 vectors: nodes per cell of the
/// measured meshes), memory and time per linear step from fits to the
/// benchmarks of bench/results (2-core machine: 2D serial with PETSc's LU,
/// 3D on 2 ranks with MUMPS); see bench/results/size-estimate-*.md for the
/// estimates against measured runs.
SizeEstimate estimate_size(double cells, int dim, int order);

/// "about 2,160 cells, 8,950 dofs, 0.12 GB, 0.43 ms per linear step".
std::string describe(const SizeEstimate& e);

/// Physical memory of this machine in GB (0 if unknown).
double machine_memory_gb();
} // namespace damseis::geometry
