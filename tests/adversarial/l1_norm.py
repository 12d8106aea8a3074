"""|e1| + |e2|: not radial (f(1, 0) = 1 < f(3/5, 4/5) = 7/5), not differentiable on the axes."""
import sympy as sp
e1, e2 = sp.symbols("e1 e2", real=True)
f = sp.Abs(e1) + sp.Abs(e2)
