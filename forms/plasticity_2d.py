# Nonlinear (concrete) material in 2D: internal force and consistent tangent
# from stress and tangent values held at the quadrature points.
#
# Compiled by FFCx once per displacement degree, like elasticity_2d.py (the
# build puts "degree = 1" or "degree = 2" in front of this file). The names
# below are the C++ interface (cpp/damseis/fem/concrete_model.h).
#
# Quadrature: degree 2 (3 points) for P2, degree 1 (1 point) for P1: exact for
# the elastic stiffness (the strain of a P2 field is linear), so the elastic
# material reproduces the linear solver.
# Voigt order in the plane: (xx, yy, xy), engineering shear gamma = 2 eps_xy.
#
# Coefficients:
#   sig   stress (sxx, syy, sxy) at the points [Pa]
#   Ct    algorithmic tangent d(sig)/d(exx, eyy, gxy), 3x3 row-major [Pa]
#   u     displacement [m] (for the strain expression)
# Expressions (evaluated at the same points):
#   strain    (exx, eyy, gxy) of u
#   position  coordinates of the points
import basix
from ufl import (Coefficient, FunctionSpace, Mesh, SpatialCoordinate,
                 TensorElement, TestFunction, TrialFunction, VectorElement,
                 as_vector, dot, dx, grad, inner, sym, triangle)

cell = triangle
qdeg = max(1, 2 * (degree - 1))
mesh = Mesh(VectorElement("Lagrange", cell, 1))
V = FunctionSpace(mesh, VectorElement("Lagrange", cell, degree))
Sq = FunctionSpace(mesh, VectorElement("Quadrature", cell, degree=qdeg, dim=3,
                                       quad_scheme="default"))
Cq = FunctionSpace(mesh, TensorElement("Quadrature", cell, degree=qdeg,
                                       shape=(3, 3), quad_scheme="default"))

du, v = TrialFunction(V), TestFunction(V)
u = Coefficient(V)
sig, Ct = Coefficient(Sq), Coefficient(Cq)


def eps_v(w):
    e = sym(grad(w))
    return as_vector([e[0, 0], e[1, 1], 2.0 * e[0, 1]])


dxq = dx(metadata={"quadrature_degree": qdeg, "quadrature_scheme": "default"})
L_residual = inner(sig, eps_v(v)) * dxq
a_tangent = inner(dot(Ct, eps_v(du)), eps_v(v)) * dxq

points, weights = basix.make_quadrature(basix.CellType.triangle, qdeg)
strain = eps_v(u)
position = SpatialCoordinate(mesh)

forms = [L_residual, a_tangent]
expressions = [(strain, points), (position, points)]
