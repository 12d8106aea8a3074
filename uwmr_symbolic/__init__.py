"""uwmr-symbolic: machine verification of the saturated controller family (9)
of Moreno-Valenzuela et al. (ISA Transactions, 2020) for unicycle robots."""

import sympy as _sp

__version__ = "0.1.0"

#: The two body-frame position errors (7), as plain real SymPy symbols.
#: Design files may import these or create their own with the same names.
e1, e2 = _sp.symbols("e1 e2", real=True)

__all__ = ["e1", "e2", "__version__"]
