# The viscous-spring artificial boundary of a truncated foundation and its
# free-field load operator in 3D: as forms/viscous_boundary_2d.py, with z
# the vertical axis. a_traction maps w = (sigma_xz, sigma_yz, sigma_zz) of
# a vertically propagating free field to its traction sigma n, with
# sigma_xx = sigma_yy = lmbda / (lmbda + 2 mu) sigma_zz and sigma_xy = 0.
from ufl import (Coefficient, Constant, FacetNormal, FiniteElement,
                 FunctionSpace, Mesh, SpatialCoordinate, TestFunction,
                 TrialFunction, VectorElement, as_matrix, dot, ds, inner,
                 sqrt, tetrahedron)

BOUNDARY = 1

cell = tetrahedron
mesh = Mesh(VectorElement("Lagrange", cell, 1))
V = FunctionSpace(mesh, VectorElement("Lagrange", cell, degree))
Q = FunctionSpace(mesh, FiniteElement("DG", cell, 0))
du, v = TrialFunction(V), TestFunction(V)
mu, lmbda, rho = Coefficient(Q), Coefficient(Q), Coefficient(Q)
centre = Constant(mesh, shape=(3,))
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
sigma_w = as_matrix([[k * du[2], 0, du[0]],
                     [0, k * du[2], du[1]],
                     [du[0], du[1], du[2]]])
a_traction = inner(dot(sigma_w, n), v) * ds(BOUNDARY)

forms = [a_spring, a_dashpot, a_traction]
