"""Versioned JSON certificates: a list of theorems, each naming its rule,
its premises (earlier entries) and the rule's data.  `check_certificate`
rebuilds every theorem by calling the same rule again (no search) and
compares the claim it gets with the one written down.  (The proposer writes
them, `certify.to_certificate`: what it writes is checked, so the writer is
not trusted.)"""
from __future__ import annotations

import json
from pathlib import Path

from .core import RULES, Claim, Theorem

FORMAT = "uwmr-kernel-certificate"
VERSION = 3         # 3: join_at_zero is join_at_point; 2: every theorem lists sympy-core (1 did not, for some rules)
SCHEMA = Path(__file__).with_name("certificate.schema.json")


class CertificateError(ValueError):
    """The certificate is malformed, of another version, or a step fails."""


def _shape(data):
    if not isinstance(data, dict):
        raise CertificateError("a certificate is a JSON object")
    if data.get("format") != FORMAT:
        raise CertificateError(f"not a {FORMAT} (format = {data.get('format')!r})")
    if data.get("version") != VERSION:
        raise CertificateError(f"certificate format version {data.get('version')!r} is not supported: "
                               f"this kernel reads version {VERSION} only; re-create the certificate")
    for key, typ in (("theorems", list), ("conclusions", list), ("assumptions", list)):
        if not isinstance(data.get(key), typ):
            raise CertificateError(f"'{key}' must be a list")
    for i, node in enumerate(data["theorems"]):
        if not (isinstance(node, dict) and node.get("id") == i and isinstance(node.get("rule"), str)
                and isinstance(node.get("premises"), list) and isinstance(node.get("data"), dict)
                and isinstance(node.get("claim"), dict)):
            raise CertificateError(f"theorem {i}: needs id = {i}, rule, premises, data, claim")


def read_json(data):
    """data itself, or the JSON value of a text; CertificateError if it is no JSON
    (or nested past Python's recursion limit)."""
    try:
        return json.loads(data) if isinstance(data, (str, bytes)) else data
    except (json.JSONDecodeError, RecursionError) as exc:
        raise CertificateError(f"not JSON: {'nested too deeply' if isinstance(exc, RecursionError) else exc}") from None


_CHECKED: dict = {}     # (rule, data, premises' claims and assumptions) -> the theorem it gave


def check_certificate(data) -> list[Theorem]:
    """Re-apply every step; return the conclusions as kernel theorems.
    Raises CertificateError naming the first step that fails."""
    data = read_json(data)
    _shape(data)
    built: list[Theorem] = []
    for node in data["theorems"]:
        i = node["id"]
        fn = RULES.get(node["rule"])
        if fn is None:
            raise CertificateError(f"theorem {i}: unknown rule {node['rule']!r}")
        prem = node["premises"]
        if not all(isinstance(p, int) and not isinstance(p, bool) and 0 <= p < i for p in prem):
            raise CertificateError(f"theorem {i}: premises must be earlier theorems")
        key = (node["rule"], json.dumps(node["data"], sort_keys=True),
               tuple((built[p].claim, built[p].assumptions) for p in prem))
        t = _CHECKED.get(key)
        if t is None:                  # a rule's result depends only on the key: the same step is checked once
            try:
                t = fn.from_json(*[built[p] for p in prem], data=node["data"])
            except Exception as exc:   # noqa: BLE001 -- whatever goes wrong in a step, the step is rejected
                raise CertificateError(f"theorem {i} ({node['rule']}) does not check: {exc}") from None
            if len(_CHECKED) > 4096:
                _CHECKED.clear()
            _CHECKED[key] = t
        try:
            claimed = Claim(**node["claim"])
        except TypeError as exc:
            raise CertificateError(f"theorem {i}: malformed claim: {exc}") from None
        if t.claim != claimed:
            raise CertificateError(f"theorem {i} ({node['rule']}): the rule proves {t.claim}, "
                                   f"the certificate claims {claimed}")
        built.append(t)
    concl = data["conclusions"]
    if not concl or not all(isinstance(c, int) and 0 <= c < len(built) for c in concl):
        raise CertificateError("conclusions must name theorems of the certificate")
    out = [built[c] for c in concl]
    rests = sorted(set().union(*[t.assumptions for t in out]))
    if not all(isinstance(a, str) for a in data["assumptions"]) or rests != sorted(data["assumptions"]):
        raise CertificateError(f"the certificate rests on {rests}, it lists {data['assumptions']}")
    return out
