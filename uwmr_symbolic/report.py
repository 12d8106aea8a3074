"""Rendering verification results.

`to_dict` turns a `Report` into a JSON-able dict; every format (text, JSON,
JUnit XML, GitHub workflow annotations, the summary table) is rendered from
that dict alone, so a result read back from the cache prints exactly as the
run that computed it."""
from __future__ import annotations

import ast
import json
import math
import re
from decimal import Decimal
from pathlib import Path
from xml.etree import ElementTree as ET

import sympy as sp

from .interval import Interval
from .kf import exact_text, show_interval
from .verify import Report, kf_checked

MARK = {"proved": "proved ", "refuted": "REFUTED", "unknown": "unknown"}
LETTER = {"proved": "P", "refuted": "R", "unknown": "?"}
STATUS_TEXT = {0: "all properties proved, gains within the limits", 1: "REFUTED or a gain check fails",
               2: "unusable input", 3: "inconclusive"}
PROPS = ("P1", "P2", "P3", "P4", "P5", "P6", "P7", "P8")


def _num(x):
    """A float for JSON (None for infinite/undecided, and where SymPy cannot
    tell x from 0: its digits would be noise)."""
    if x is None:
        return None
    try:
        v = float(sp.N(x, 30, strict=True)) if isinstance(x, sp.Basic) else float(x)
    except sp.core.evalf.PrecisionExhausted:
        return None
    return v if math.isfinite(v) else None


def _jsonable(obj):
    if isinstance(obj, dict):
        return {str(k): _jsonable(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_jsonable(v) for v in obj]
    if isinstance(obj, (str, int, float, bool)) or obj is None:
        return obj
    return str(obj)


def assignment_line(source: str, name: str) -> int | None:
    """Line of the last module-level assignment to `name` in Python `source`."""
    line = None
    try:
        body = ast.parse(source).body
    except (SyntaxError, ValueError):
        return None
    for node in body:
        targets = node.targets if isinstance(node, ast.Assign) else \
            [node.target] if isinstance(node, (ast.AnnAssign, ast.AugAssign)) else []
        if any(isinstance(t, ast.Name) and t.id == name for t in targets):
            line = node.lineno
    return line


def design_fields(design) -> dict:
    """What a result says about the file rather than about f: filled in afresh
    when a result comes from the cache (another file may define the same f)."""
    try:
        gains_line = assignment_line(Path(design.path).read_text(), "gains")
    except (OSError, UnicodeDecodeError):
        gains_line = None
    return {"design": str(design.path), "name": design.name, "f": exact_text(design.f),
            "f_line": design.f_line, "gains_line": gains_line or design.f_line}


def to_dict(r: Report) -> dict:
    if r.error is not None:
        return {"design": str(r.path), "error": r.error, "exit_status": r.exit_status}
    kf = r.kf
    d = {
        "design": str(r.path),
        "name": r.design.name if r.design else None,
        "f": exact_text(r.design.f) if r.design else None,
        "properties": {p: {"verdict": v.status, "reason": v.reason,
                           "witness": _jsonable(v.witness),
                           **_jsonable({k: x for k, x in v.details.items() if k != "kernel"})}
                       for p, v in r.properties.items()},
        "kf": {**(kf_numbers(None, None, None, False) if kf is None else
                  kf_numbers(kf.exact, kf.lower, kf.upper, kf.upper is None and bool(kf.unbounded_witness))),
               "attained": None if kf is None else kf.attained,
               # the kernel checked this kf (its value, enclosure or infinity), not the search alone
               "kernel_checked": kf is not None and r.kernel is not None and kf_checked(r.certificate, r.kernel),
               "reason": "undecided (f not radial or P1 not analysed)" if kf is None else kf.reason},
        "gains": gains_dict(r.gains),
        "proof_replay": r.proof_replay,
        "kernel": r.kernel,
        "seconds": round(r.seconds, 3),
        "exit_status": r.exit_status,
    }
    if r.design is not None:
        d.update(design_fields(r.design))
    else:
        d["f_line"] = d["gains_line"] = 1
    return d


def kf_numbers(exact, lower, upper, unbounded: bool) -> dict:
    """kf's numbers as the reports give them (`to_dict`; a cache hit derives
    them again from the kf the kernel checked): the exact value and its first
    20 digits (none for an integer written out), the enclosure's ends as
    doubles rounded outward and as 12 digits rounded outward (for the text),
    and whether kf is infinite."""
    return {"exact": None if exact is None else exact_text(exact),
            "exact_digits": None if exact is None or exact.is_Integer and exact_text(exact) == str(exact)
            else str(sp.N(exact, 20)),
            "lower": None if lower is None else Interval.point(lower).lower_float(),
            "upper": None if upper is None else Interval.point(upper).upper_float(),
            "enclosure": None if lower is None or upper is None else show_interval(lower, upper, 12),
            "unbounded": unbounded}


def number_text(x, spec: str) -> str | None:
    """x (an exact number, None: none) in the format spec ('.8g', '+.3e'),
    through a float where a normal double holds it, else SymPy's digits (a
    gain of 10^-400 is not 0, nor 10^400 inf); "?" when SymPy cannot tell
    x from 0 (pi/4 - atan(1/2) - atan(1/3))."""
    if x is None:
        return None
    try:
        value = sp.N(x, 30, strict=True)
    except sp.core.evalf.PrecisionExhausted:
        return "?"
    v = float(value) if abs(value) < sp.Float("1e300") else math.inf
    if value == 0 or 1e-300 <= abs(v) < math.inf:
        return format(v, spec)
    text = str(sp.N(value, int(re.search(r"\d+", spec).group()) + ("e" in spec)))
    return ("+" if "+" in spec and not text.startswith("-") else "") + text


def gains_dict(gains: dict) -> dict:
    """Bound (10) per gain scenario (`gains.GainCheck`) as JSON-able data;
    "text": the numbers as the reports print them."""
    return {name: {"V_bound": _num(g.V_bound), "W_bound": _num(g.W_bound),
                   "V_margin": str(g.V_margin), "W_margin": None if g.W_margin is None else str(g.W_margin),
                   "V_margin_float": _num(g.V_margin), "W_margin_float": _num(g.W_margin),
                   "V_ok": g.V_ok, "W_ok": g.W_ok, "lam_max": _num(g.lam_max),
                   "lam_max_exact": None if g.lam_max is None else str(g.lam_max),
                   "text": {k: number_text(getattr(g, k), spec) for k, spec in
                            (("V_bound", ".8g"), ("W_bound", ".8g"), ("V_margin", "+.3e"), ("W_margin", "+.3e"),
                             ("lam_max", ".8g"))}}
            for name, g in gains.items()}


def _as_dict(r) -> dict:
    return to_dict(r) if isinstance(r, Report) else r


def render_json(r) -> str:
    return json.dumps(_as_dict(r), indent=2)


# ---------------------------------------------------------------- text

def render_text(r) -> str:
    """The readable report of one design (a `Report` or its dict)."""
    d = _as_dict(r)
    if d.get("error") is not None:
        return f"{shown(d['design'])}: {d['error']}"
    lines = [f"{shown(d['design'])}  —  {d.get('name') or shown(Path(d['design']).name)}"]
    if d.get("f") is not None:
        lines.append(f"  f = {d['f']}")
    lines.append("")
    for p, v in d["properties"].items():
        lines.append(f"  {p}  {MARK[v['verdict']]}  {v['reason']}")
        if v.get("witness") is not None and v["verdict"] != "proved":
            lines.append(f"               witness: {json.dumps(v['witness'])}")
    kf = d["kf"]
    lines.append("")
    if kf["upper"] is None:
        lines.append(f"  kf: {'infinite' if kf.get('unbounded') else 'undecided'} — {kf['reason']}")
    else:
        att = {True: "attained", False: "approached at infinity, not attained", None: "attainment undecided"}
        how = att[kf["attained"]] + ("" if kf["kernel_checked"] else "; the search's, not re-checked by the kernel")
        if kf["exact"] is not None:
            digits = f" = {kf['exact_digits']}..." if kf.get("exact_digits") else ""
            lines.append(f"  kf = {kf['exact']}{digits}  ({how})")
        else:
            lines.append(f"  kf in {kf['enclosure']}  ({how})")
    if d["gains"]:
        lines.append("")
        lines.append("  bound (10)     |V| bound  margin          |W| bound  margin          lam_max")
        for name, g in d["gains"].items():
            v_ok, w_ok = ({True: "PASS", False: "FAIL", None: "????"}[g[k]] for k in ("V_ok", "W_ok"))
            t = g["text"]
            lines.append(f"  {name:<12} {t['V_bound']:>10}  {t['V_margin']} {v_ok}  "
                         f"{t['W_bound'] or no_w_bound(g):>10}  {t['W_margin'] or '—'} {w_ok}  {t['lam_max'] or '?'}")
    if d.get("kernel") is not None:
        lines.append("")
        lines.append(f"  {kernel_text(d['kernel'])}")
    lines.append("")
    pr = d["proof_replay"]
    lines.append("  proof replay: " + ("not run" if not pr.get("steps") else f"{'ok' if pr.get('ok') else 'NOT ok'} — "
                 + "; ".join(f"{k}: {'ok' if s['ok'] else 'no'}" for k, s in pr["steps"].items())))
    served = ", served from the cache" if d.get("cached") else ""
    lines.append(f"  => {status_text(d)}  ({d['seconds']:.2f} s{served})")
    return "\n".join(lines)


def kernel_text(k: dict) -> str:
    """The kernel line of the text report (see `batch.kernel_summary`; its
    lists come in the certificate's order, P1..P8 then kf)."""
    why = k.get("error") or k.get("stopped")
    if why:
        return f"kernel: nothing re-checked ({why})"
    bugs = "".join([f"; the checker rejected the proposer's certificate of {name} (a bug: please report it)"
                    for name, _ in k.get("failed", ())] +
                   [f"; the search proved {name}, which the witness of {by} refutes (a bug: please report it)"
                    for name, by in k.get("refuted_by", {}).items()])
    if not k["search"]:
        return f"kernel: re-checked {' '.join(k['checked'])} (every decided verdict){bugs}"
    checked = f"re-checked {' '.join(k['checked'])}; " if k["checked"] else ""
    return (f"kernel: {checked}resting on the search alone: {' '.join(k['search'])} (counted only with "
            f"--trust-search; --certificate FILE says why){bugs}")


NO_GAINS = "no gain scenarios given, so bound (10) was not checked"


def status_text(d: dict) -> str:
    """The verdict line of a result dict; a design without ``gains`` is never
    said to be within the limits."""
    if d["exit_status"] == 0 and not d.get("gains"):
        return f"all properties proved; {NO_GAINS}"
    if d["exit_status"] == 1 and d.get("simulation") and not any(
            v["verdict"] == "refuted" for v in d["properties"].values()) and \
            not any(_gain_word(g) == "FAIL" for g in (d.get("gains") or {}).values()):    # (--simulate set it)
        return "a simulation check fails (nothing refuted, no gain check failed)"
    return STATUS_TEXT[d["exit_status"]]


def _kf_summary(kf: dict) -> str:
    if kf["upper"] is None:
        return "infinite" if kf.get("unbounded") else "undecided"
    if kf["exact"] is not None and len(kf["exact"]) <= 20:
        return kf["exact"]
    if kf["exact"] is not None:     # exact, too long for the column: its leading 17 digits
        return f"{Decimal(kf['exact_digits'] or kf['exact']):.17g}..."   # (an integer written out has no digits)
    return f"~{kf_upper_text(kf)}"


def kf_upper_text(kf: dict) -> str:
    """The upper end of kf's enclosure as printed (rounded up, at any scale:
    the float `upper` is 5e-324 for a kf of 10^-400)."""
    return kf["enclosure"].strip("[]").split(", ")[1]


def no_w_bound(g: dict, infinite: str = "inf") -> str:
    """The |W| bound's place without one: `infinite` for an infinite kf, ?
    for an undecided one."""
    return infinite if g["W_ok"] is False else "?"


def _undecided_text(g: dict, name: str) -> str:
    """Why bound (10) of scenario `name` is unchecked."""
    if g["V_ok"] is None:
        return f"the sign of the |V| margin of scenario {name}, {g['V_margin']}, is undecided"
    if g["W_margin"] is None:
        return f"kf undecided: |W| bound of scenario {name} unchecked"
    return (f"the |W| margin of scenario {name} is undecided (Wmax lies within the bounds that kf's enclosure "
            f"gives, or the sign of {g['W_margin']} is undecided)")


def _gain_word(g: dict) -> str:
    if g["V_ok"] is False or g["W_ok"] is False:
        return "FAIL"
    return "ok" if g["V_ok"] and g["W_ok"] else "?"


def shown(path: str) -> str:
    """A file name as one line: control characters (a newline in a name would
    start a line of its own, a GitHub workflow command even) as escapes."""
    return path if path.isprintable() else repr(path)[1:-1]


def render_summary(results: list[dict]) -> str:
    """One table for a set of designs, and the count of each outcome."""
    width = max([len("design")] + [len(shown(d["design"])) for d in results])
    lines = ["Summary (P proved, R refuted, ? unknown; kf certified; bound (10) per scenario)",
             f"{'design':<{width}}  P1..P8    {'kf':<20} {'gains':<30} exit  time"]
    for d in results:
        if d.get("error") is not None:
            lines.append(f"{shown(d['design']):<{width}}  unusable: {d['error']}")
            continue
        row = "".join(LETTER[d["properties"][p]["verdict"]] for p in d["properties"])
        gains = " ".join(f"{n}:{_gain_word(g)}" for n, g in d["gains"].items()) or "-"
        gains += "".join(f" sim:{n}:FAIL" for n, why in simulation_failures(d).items() if not why.startswith("skip"))
        cached = "  (cached)" if d.get("cached") else ""
        lines.append(f"{shown(d['design']):<{width}}  {row:<8}  {_kf_summary(d['kf']):<20} {gains:<30} "
                     f"{d['exit_status']:>4}  {d['seconds']:5.2f} s{cached}")
    counts = {s: sum(1 for d in results if d["exit_status"] == s) for s in (0, 1, 3, 2)}
    lines.append(f"{len(results)} design file(s): {counts[0]} proved, {counts[1]} refuted or failing a check, "
                 f"{counts[3]} inconclusive, {counts[2]} unusable")
    return "\n".join(lines)


def render_markdown_summary(results: list[dict]) -> str:
    """The summary table as Markdown (for $GITHUB_STEP_SUMMARY)."""
    word = {0: "proved", 1: "**refuted / gains fail**", 2: "**unusable**", 3: "inconclusive"}
    lines = ["### uwmr-verify", "", "| design | P1..P8 | kf | bound (10) | result |", "|---|---|---|---|---|"]
    for d in results:
        if d.get("error") is not None:
            error = d["error"].replace("|", "\\|")
            lines.append(f"| `{shown(d['design'])}` | | | | {word[2]}: {error} |")
            continue
        row = "".join(LETTER[v["verdict"]] for v in d["properties"].values())
        gains = " ".join(f"{n}:{_gain_word(g)}" for n, g in d["gains"].items()) or "-"
        lines.append(f"| `{shown(d['design'])}` | `{row}` | {_kf_summary(d['kf'])} | {gains} | {word[d['exit_status']]} |")
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------- JUnit XML

def _classname(path: str) -> str:
    p = Path(path).with_suffix("")
    parts = [x for x in (p.parts[1:] if p.is_absolute() else p.parts) if x not in (".", "..")]
    return ".".join(parts) or p.name


def _testcases(d: dict):
    """(name, outcome, type, message, text) per property, proof replay, gain
    scenario and `--simulate` scenario; outcome is 'passed', 'failure',
    'error' or 'skipped'."""
    if d.get("error") is not None:
        yield "load", "error", "unusable", d["error"], d["error"]
        return
    for p, v in d["properties"].items():
        if v["verdict"] == "proved":
            yield p, "passed", None, None, v["reason"]
        else:
            text = v["reason"] + ("" if v.get("witness") is None else f"\nwitness: {json.dumps(v['witness'])}")
            yield p, "failure", v["verdict"], f"{p} {v['verdict']}: {v['reason']}", text
    pr = d["proof_replay"]
    steps = "\n".join(f"{k}: {'ok' if s['ok'] else 'no'} — {s.get('detail', '')}" for k, s in pr.get("steps", {}).items())
    if pr.get("ok"):
        yield "proof_replay", "passed", None, None, steps
    else:
        yield "proof_replay", "failure", "unknown", "proof replay not ok", steps
    if not d["gains"]:
        yield "gains", "skipped", None, "the design has no gain scenarios", ""
    kf_line = f"kf = {_kf_summary(d['kf'])}: {d['kf']['reason']}"
    for name, g in d["gains"].items():
        text = f"{_bound_text(g, 'V')}\n{_bound_text(g, 'W')}\nlargest lam within the limits: {g['lam_max_exact']}\n{kf_line}"
        word = _gain_word(g)
        if word == "ok":
            yield f"gains[{name}]", "passed", None, None, text
        elif word == "FAIL":
            which = " and ".join(w for w, ok in (("|V|", g["V_ok"]), ("|W|", g["W_ok"])) if ok is False)
            yield f"gains[{name}]", "failure", "refuted", f"bound (10) fails for {which} in scenario {name}", text
        else:
            yield f"gains[{name}]", "failure", "unknown", _undecided_text(g, name), text
    failures = simulation_failures(d)
    for name in d.get("simulation") or {}:
        why = failures.get(name)
        if why is None:
            yield f"simulation[{name}]", "passed", None, None, ""
        elif why.startswith("skipped"):
            yield f"simulation[{name}]", "skipped", None, why, why
        else:
            yield f"simulation[{name}]", "failure", "simulation", f"simulation of scenario {name} failed: {why}", why


def simulation_failures(d: dict) -> dict:
    """{scenario: why} for each `--simulate` scenario that failed a check
    (the failed checks per run) or was skipped ("skipped: ...")."""
    out = {}
    for name, entry in (d.get("simulation") or {}).items():
        if "skipped" in entry:
            out[name] = f"skipped: {entry['skipped']}"
        elif not entry.get("ok", True):
            runs = [f"{kind}: {', '.join(entry[kind]['failed'])}" for kind in ("continuous", "digital")
                    if entry.get(kind) and not entry[kind]["ok"]]
            if entry.get("monte_carlo") and not entry["monte_carlo"].get("ok", True):
                runs.append("monte carlo")
            out[name] = "; ".join(runs) or "a check failed"
    return out


def render_junit(results: list[dict]) -> str:
    """JUnit XML in the shape pytest writes (xunit2): one <testcase> per design
    and property P1-P8, proof replay and gain scenario; classname is the design
    file's path.  refuted and unknown are <failure type="refuted|unknown">,
    an unusable file is an <error>.  No timestamp or hostname, so the same
    results always give the same bytes."""
    suite = ET.Element("testsuite", name="uwmr-verify")
    counts = {"tests": 0, "failures": 0, "errors": 0, "skipped": 0}
    total = 0.0
    for d in results:
        cls = _classname(d["design"])
        cases = list(_testcases(d))
        seconds = d.get("seconds", 0.0)
        total += seconds
        for i, (name, outcome, kind, message, text) in enumerate(cases):
            # the design's verification time goes on its first test case
            tc = ET.SubElement(suite, "testcase", classname=cls, name=name,
                               time=f"{seconds if i == 0 else 0.0:.3f}")
            counts["tests"] += 1
            if outcome == "passed":
                if text:
                    ET.SubElement(tc, "system-out").text = text
                continue
            tag = {"failure": "failure", "error": "error", "skipped": "skipped"}[outcome]
            counts[{"failure": "failures", "error": "errors", "skipped": "skipped"}[outcome]] += 1
            el = ET.SubElement(tc, tag, message=message)
            if kind:
                el.set("type", kind)
            el.text = text or None
    for k in ("errors", "failures", "skipped", "tests"):
        suite.set(k, str(counts[k]))
    suite.set("time", f"{total:.3f}")
    root = ET.Element("testsuites", name="uwmr-verify")
    root.append(suite)
    for el in root.iter():          # what XML 1.0 cannot hold (a file named with \x01): escaped as \x01
        el.text = el.text and _XML_BAD.sub(lambda m: repr(m.group())[1:-1], el.text)
        for k, v in el.attrib.items():
            el.set(k, _XML_BAD.sub(lambda m: repr(m.group())[1:-1], v))
    ET.indent(root)
    return '<?xml version="1.0" encoding="utf-8"?>\n' + ET.tostring(root, encoding="unicode")


_XML_BAD = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]")


# ---------------------------------------------------------------- GitHub annotations

def _gh_data(s: str) -> str:
    return s.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def _gh_prop(s: str) -> str:
    return _gh_data(s).replace(":", "%3A").replace(",", "%2C")


def _annotation(level: str, file: str, line: int, title: str, message: str) -> str:
    return f"::{level} file={_gh_prop(file)},line={line},title={_gh_prop(title)}::{_gh_data(message)}"


def _bound_text(g: dict, which: str) -> str:
    """e.g. '|W| bound 2.000012851 FAIL, margin -1.285e-05 = 3/10 - 13857*sqrt(3)/80000'."""
    ok = g[f"{which}_ok"]
    word = {True: "ok", False: "FAIL", None: "unchecked"}[ok]
    margin, exact = g["text"][f"{which}_margin"], g[f"{which}_margin"]
    m = "—" if exact is None else (margin or "?") + \
        ("" if exact in (None, "0") or "/" not in exact and "sqrt" not in exact else f" = {exact}")
    return f"|{which}| bound {g['text'][f'{which}_bound'] or no_w_bound(g)} {word}, margin {m}"


def render_github(results: list[dict]) -> str:
    """GitHub Actions workflow commands: ::error at the line defining f for each
    refuted property (at the `gains` line for a failing bound (10)), ::warning
    for each unknown, ::notice for a design proved in full, ::error for an
    unusable file (at the line of its syntax error or exception when known)."""
    out = []
    for d in results:
        path = d["design"]
        if d.get("error") is not None:
            m = re.search(r"at line (\d+)", d["error"])
            out.append(_annotation("error", path, int(m.group(1)) if m else 1,
                                   "uwmr-verify: unusable design", d["error"]))
            continue
        f_line, gains_line = d.get("f_line") or 1, d.get("gains_line") or d.get("f_line") or 1
        name = d.get("name") or Path(path).name
        for p, v in d["properties"].items():
            if v["verdict"] == "proved":
                continue
            level = "error" if v["verdict"] == "refuted" else "warning"
            msg = v["reason"] + ("" if v.get("witness") is None else f" (witness: {json.dumps(v['witness'])})")
            out.append(_annotation(level, path, f_line, f"uwmr-verify {p} {v['verdict']} ({name})", msg))
        if not d["proof_replay"].get("ok"):
            out.append(_annotation("warning", path, f_line, f"uwmr-verify proof replay ({name})",
                                   "the proof replay did not go through"))
        for scen, g in d["gains"].items():
            word = _gain_word(g)
            if word == "FAIL":
                out.append(_annotation("error", path, gains_line, f"uwmr-verify bound (10) fails ({name}, {scen})",
                                       f"{_bound_text(g, 'V')}; {_bound_text(g, 'W')}; "
                                       f"largest lam within the limits: {g['lam_max_exact']}"))
            elif word == "?":
                out.append(_annotation("warning", path, gains_line, f"uwmr-verify bound (10) unchecked ({name}, {scen})",
                                       _undecided_text(g, scen)))
        for scen, why in simulation_failures(d).items():
            if not why.startswith("skipped"):
                out.append(_annotation("error", path, gains_line, f"uwmr-verify simulation fails ({name}, {scen})", why))
        if d["exit_status"] == 0:
            out.append(_annotation("notice", path, f_line, f"uwmr-verify proved ({name})",
                                   f"P1-P8 proved, kf = {_kf_summary(d['kf'])}, "
                                   + ("every gain scenario within bound (10)" if d["gains"] else NO_GAINS)))
    return "\n".join(out)
