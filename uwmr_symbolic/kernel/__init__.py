"""The trusted kernel: the only code that makes theorems (see docs/kernel.md).

    from uwmr_symbolic.kernel import rules, check_certificate
"""
from . import core as rules
from .arb import Undefined, evaluate
from .certificate import VERSION, CertificateError, check_certificate
from .core import RULES, Claim, KernelError, Theorem

__all__ = ["rules", "RULES", "Claim", "Theorem", "KernelError", "Undefined", "evaluate",
           "check_certificate", "CertificateError", "VERSION"]
