"""Verdicts: the three answers the verifier may give about a property."""
from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum
from typing import Any


class Status(str, Enum):
    """A verdict's status; a str, so it prints and serialises as its value."""
    PROVED = "proved"
    REFUTED = "refuted"
    UNKNOWN = "unknown"

    def __str__(self) -> str:
        return self.value


PROVED, REFUTED, UNKNOWN = Status.PROVED, Status.REFUTED, Status.UNKNOWN

#: the properties of f that the paper's Proposition 1 asks for
PROPERTIES = ("P1", "P2", "P3", "P4", "P5", "P6", "P7", "P8")


@dataclass
class Verdict:
    """The verifier's answer about one claim.

    ``status`` is ``proved`` (a symbolic identity or a rigorous argument over the
    whole domain), ``refuted`` (with a ``witness`` re-checked rigorously) or
    ``unknown`` (``reason`` says what was left undecided)."""

    status: Status
    reason: str
    witness: Any = None
    details: dict = field(default_factory=dict)

    @property
    def proved(self) -> bool:
        return self.status == PROVED

    @property
    def refuted(self) -> bool:
        return self.status == REFUTED


def proved(reason: str, **details) -> Verdict:
    return Verdict(PROVED, reason, None, details)


def refuted(reason: str, witness: Any, **details) -> Verdict:
    return Verdict(REFUTED, reason, witness, details)


def unknown(reason: str, **details) -> Verdict:
    return Verdict(UNKNOWN, reason, None, details)
