# The viscous-spring artificial boundary of a truncated foundation and its
# free-field load operator (algorithms.md 3.6), on the facets the assembly
# marks BOUNDARY = 1. Compiled per displacement degree like
# elasticity_2d.py; y is the vertical axis.
#
# Coefficients (DG0, the adjacent cell's): mu, lmbda (lambda* in plane
# stress), rho. Constants: centre (the scattering centre [m]), alpha_n,
# alpha_t (spring factors). Per unit area:
#   springs  k_n = alpha_n mu / R, k_t = alpha_t mu / R, R = |x - centre|,
#   dashpots c_n = rho c_p = sqrt(rho (lmbda + 2 mu)), c_t = sqrt(rho mu).
# a_traction maps a nodal field w = (sigma_xy, sigma_yy) of a vertically
# propagating free field to its traction sigma n on the boundary, with
# sigma_xx = lmbda / (lmbda + 2 mu) sigma_yy.
from ufl import (Coefficient, Constant, FacetNormal, FiniteElement,
                 FunctionSpace, Mesh, SpatialCoordinate, TestFunction,
                 TrialFunction, VectorElement, as_matrix, dot, ds, inner,
                 sqrt, triangle)

BOUNDARY = 1

cell = triangle
mesh = Mesh(VectorElement("Lagrange", cell, 1))
V = FunctionSpace(mesh, VectorElement("Lagrange", cell, degree))
Q = FunctionSpace(mesh, FiniteElement("DG", cell, 0))
du, v = TrialFunction(V), TestFunction(V)
mu, lmbda, rho = Coefficient(Q), Coefficient(Q), Coefficient(Q)
centre = Constant(mesh, shape=(2,))
alpha_n, alpha_t = Constant(mesh), Constant(mesh)
x = SpatialCoordinate(mesh)
n = FacetNormal(mesh)

R = sqrt(dot(x - centre, x - centre))
un, vn = dot(du, n), dot(v, n)
ut, vt = du - un * n, v - vn * n

a_spring = (alpha_n * mu / R * un * vn
            + alpha_t * mu / R * inner(ut, vt)) * ds(BOUNDARY)
a_dashpot = (sqrt(rho * (lmbda + 2 * mu)) * un * vn
             + sqrt(rho * mu) * inner(ut, vt)) * ds(BOUNDARY)
k = lmbda / (lmbda + 2 * mu)
sigma_w = as_matrix([[k * du[1], du[0]],
                     [du[0], du[1]]])
a_traction = inner(dot(sigma_w, n), v) * ds(BOUNDARY)

forms = [a_spring, a_dashpot, a_traction]
