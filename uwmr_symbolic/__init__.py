"""uwmr-symbolic: machine verification of the saturated controller family (9)
of Moreno-Valenzuela et al. (ISA Transactions, 2020) for unicycle robots."""

import os as _os

# SymPy keeps 1000 results per cached function by default; one proof asks for
# the same derivatives, substitutions and assumption queries far more often
# (the chain of 16 joins in benchmarks/bench_scaling.py: 35 s with 1000, 26 s
# with 20000, for 40 MB more).  SymPy reads this once, at its first import; a
# value the user has set is kept.
_os.environ.setdefault("SYMPY_CACHE_SIZE", "20000")

import sympy as _sp  # noqa: E402

__version__ = "0.1.0"

#: The two body-frame position errors (7), as plain real SymPy symbols.
#: Design files may import these or create their own with the same names.
e1, e2 = _sp.symbols("e1 e2", real=True)

# The Python API (`api`): verify, verify_file, generate, simulate.
# `uwmr_symbolic.verify` stays the verifier's module (`import uwmr_symbolic.verify
# as v`, `from uwmr_symbolic.verify import verify_design` and patches of its
# names keep working) and calling it calls `api.verify`.
import inspect as _inspect  # noqa: E402
import types as _types  # noqa: E402

from . import api as _api, verify as _verify_module  # noqa: E402
from .api import generate, simulate, verify_file  # noqa: E402
from .design import DesignError  # noqa: E402


class _CallableModule(_types.ModuleType):
    def __call__(self, *args, **kwargs):
        return _api.verify(*args, **kwargs)

    __call__.__doc__ = _api.verify.__doc__      # what help() and IPython's `verify?` show for a call


_verify_module.__class__ = _CallableModule
_verify_module.__signature__ = _inspect.signature(_api.verify)
verify = _verify_module

__all__ = ["e1", "e2", "__version__", "verify", "verify_file", "generate", "simulate", "DesignError"]
