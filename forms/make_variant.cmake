# Writes ${OUT}: the UFL file ${SRC} with "degree = ${DEG}" put in front, so
# one form file serves every polynomial degree. Run with cmake -P.
file(READ ${SRC} body)
file(WRITE ${OUT} "# Generated from ${SRC}: do not edit.\ndegree = ${DEG}\n${body}")
