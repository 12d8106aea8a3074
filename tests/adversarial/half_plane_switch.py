"""A switch across the line e1 = 0: log(1 + rho) for e1 > 0, twice that otherwise.  Each branch
is radial, so e1 df/de2 - e2 df/de1 = 0 branch by branch, but f jumps on e1 = 0 and is not radial."""
import sympy as sp
e1, e2 = sp.symbols("e1 e2", real=True)
r = e1**2 + e2**2
f = sp.Piecewise((sp.log(1+r), e1 > 0), (sp.log(1+r)*2, True))
