// Stress points on a tagged boundary (e.g. the upstream face of a dam).
#pragma once

#include <cstdint>
#include <dolfinx/fem/FunctionSpace.h>
#include <dolfinx/mesh/MeshTags.h>
#include <functional>
#include <span>
#include <vector>

namespace damseis::results
{
/// Owned points of the stress-point space S that lie on the facets tagged
/// with any of `tags` (a face may carry several, e.g. the wetted and the dry
/// part of an arch dam's upstream face): for P2 models (points at cell
/// vertices) the vertices of those facets, for P1 models (one point per cell)
/// the centres of the adjacent cells. Sorted, unique. With `vertex_points`
/// false (quadrature points inside the cells): all points of the adjacent
/// cells.
/// Calls `visit(facet, cell, point)` for every facet tagged with any of
/// `tags`, every cell of the facet and every local point of S that
/// face_points() counts for that facet and cell (points may repeat; ghost
/// points included).
void for_each_face_point(
    const dolfinx::fem::FunctionSpace& S,
    const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags,
    const std::vector<int>& tags, bool vertex_points,
    const std::function<void(std::int32_t, std::int32_t, std::int32_t)>& visit);

std::vector<std::int32_t>
face_points(const dolfinx::fem::FunctionSpace& S,
            const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags,
            const std::vector<int>& tags, bool vertex_points = true);

/// Per point of `points` (as face_points gives them for the same S, tags
/// and vertex_points = false): the global index of the cell holding it.
std::vector<std::int64_t>
face_point_cells(const dolfinx::fem::FunctionSpace& S,
                 const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags,
                 const std::vector<int>& tags,
                 std::span<const std::int32_t> points);
} // namespace damseis::results
