# Linear elasticity of a dam section in 2D (plane strain or plane stress).
#
# This file is compiled by FFCx once per displacement degree (the build puts
# "degree = 1" or "degree = 2" in front of it; see forms/CMakeLists.txt).
# The names below are the C++ interface: keep them stable.
#
# Coefficients (all SI):
#   mu, lmbda  Lame constants per cell [Pa] (DG0). Plane stress is obtained by
#              passing lmbda* = 2 lmbda mu / (lmbda + 2 mu) from C++.
#   rho        mass density per cell [kg/m3] (DG0); 0 in a massless foundation.
#   u          displacement [m] (for the internal force vector).
# Constants:
#   gravity    body acceleration vector [m/s2], e.g. (0, -9.81).
#   rho_w      water density [kg/m3]; g_w gravity magnitude [m/s2].
#   H_w        reservoir water level (elevation of the free surface) [m].
#   H_0        reference depth of the Westergaard formula [m].
#   floor_on   1 to load the reservoir floor (foundation top upstream), else 0.
# Facet tags (cpp/damseis/geometry/tags.h): 1 upstream face, 2 downstream
# face, 3 crest, 4 dam base, 5 foundation bottom, 6 foundation sides,
# 7 reservoir floor (foundation top upstream), 8 foundation top downstream.
from ufl import (Coefficient, Constant, FacetNormal, FiniteElement,
                 FunctionSpace, Identity, Mesh, SpatialCoordinate,
                 TensorElement, TestFunction, TrialFunction, VectorElement,
                 as_vector, dot, ds, dx, grad, inner, max_value, sqrt, sym,
                 tr, triangle)

UPSTREAM, RESERVOIR_FLOOR = 1, 7

cell = triangle
mesh = Mesh(VectorElement("Lagrange", cell, 1))
V = FunctionSpace(mesh, VectorElement("Lagrange", cell, degree))
Q = FunctionSpace(mesh, FiniteElement("DG", cell, 0))
# Stress points: DG(degree-1) holds the exact stress of a P(degree) field.
S = FunctionSpace(mesh, VectorElement("DG", cell, degree - 1, dim=3))

du, v = TrialFunction(V), TestFunction(V)
u = Coefficient(V)
mu, lmbda, rho = Coefficient(Q), Coefficient(Q), Coefficient(Q)
gravity = Constant(mesh, shape=(2,))
rho_w, g_w, H_w, H_0, floor_on = (Constant(mesh), Constant(mesh),
                                  Constant(mesh), Constant(mesh),
                                  Constant(mesh))
x = SpatialCoordinate(mesh)
n = FacetNormal(mesh)


def eps(w):
    return sym(grad(w))


def sigma(w):
    return 2.0 * mu * eps(w) + lmbda * tr(eps(w)) * Identity(2)


depth = max_value(H_w - x[1], 0.0)
pressure = rho_w * g_w * depth

# Stiffness, mass, Westergaard added mass (acts normal to the wetted face).
a_stiffness = inner(sigma(du), eps(v)) * dx
a_mass = rho * inner(du, v) * dx
westergaard = 7.0 / 8.0 * rho_w * sqrt(H_0 * depth)
a_added_mass = westergaard * dot(du, n) * dot(v, n) * \
    ds(UPSTREAM, metadata={"quadrature_degree": 8})

# Loads: dead weight and hydrostatic pressure (traction -p n).
L_gravity = rho * inner(gravity, v) * dx
L_hydrostatic = -pressure * dot(n, v) * ds(UPSTREAM) \
    - floor_on * pressure * dot(n, v) * ds(RESERVOIR_FLOOR)

# Internal force of a displacement field (reactions, residuals).
L_internal = inner(sigma(u), eps(v)) * dx

# Stress operator: with quadrature at the stress points and the lumped
# weights below, s = diag(1/w) B u gives (sxx, syy, sxy) exactly there.
tau = TestFunction(S)
if degree == 1:
    dxs = dx(metadata={"quadrature_degree": 0})
else:
    dxs = dx(metadata={"quadrature_rule": "vertex", "quadrature_degree": 1})
sig_du = sigma(du)
a_stress = inner(as_vector([sig_du[0, 0], sig_du[1, 1], sig_du[0, 1]]),
                 tau) * dxs
L_stress_weight = (tau[0] + tau[1] + tau[2]) * dxs

# Output spaces (XDMF): cell tensors and scalars, vertex vectors and scalars.
T0 = FunctionSpace(mesh, TensorElement("DG", cell, 0))
P1 = FunctionSpace(mesh, VectorElement("Lagrange", cell, 1))
P1s = FunctionSpace(mesh, FiniteElement("Lagrange", cell, 1))
sig_cell, s_cell = Coefficient(T0), Coefficient(Q)
u_vertex, s_vertex = Coefficient(P1), Coefficient(P1s)
M_output = (inner(sig_cell, sig_cell) + s_cell * s_cell
            + inner(u_vertex, u_vertex) + s_vertex * s_vertex) * dx

forms = [a_stiffness, a_mass, a_added_mass, L_gravity, L_hydrostatic,
         L_internal, a_stress, L_stress_weight, M_output]
