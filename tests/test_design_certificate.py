"""Design certificates (issue 9): what the kernel re-checks of a report, the
link from its theorems to f, tampering, the CLI and the cache re-check.

Expected facts, by hand:
* design 1, f = log(1 + rho)/2 with rho = e1^2 + e2^2 (Jiang's design):
  F(s) = log(1 + s^2)/2 > 0 and F'(s) = s/(1 + s^2) > 0 for s > 0;
  f(0, 0) = log(1)/2 = 0;
* design 2, F(s) = sqrt(1 + s^2) - 1 (> 0 for s > 0), F' = s/sqrt(1 + s^2).
"""
import copy
import dataclasses
import json

import pytest
import sympy as sp

from uwmr_symbolic import design_certificate as DC
from uwmr_symbolic.batch import check_file
from uwmr_symbolic.cache import ResultCache, design_key
from uwmr_symbolic.design import load_design
from uwmr_symbolic.kernel.parse import parse
from uwmr_symbolic.profile import E2, S
from uwmr_symbolic.verify import verify_design

from _cli import ROOT, run_cli

pytestmark = pytest.mark.slow     # verifies designs / runs the proposer: seconds of CPU

DESIGN1 = ROOT / "designs" / "design1_jiang.py"
DESIGN2 = ROOT / "designs" / "design2_sqrt.py"
PROPS = [f"P{i}" for i in range(1, 9)]


@pytest.fixture(scope="module")
def cert1():
    return DC.build(verify_design(DESIGN1))


def _by_name(checks):
    return {c.name: c for c in checks}


def test_certificate_round_trips_and_names_what_it_rests_on(cert1):
    checks = _by_name(DC.check(json.dumps(cert1)))
    assert set(checks) == {f"P{i}" for i in range(1, 9)} | {"kf"}
    assert all(c.status == "proved" for c in checks.values())
    assert checks["P2"].kernel_checked and checks["P2"].theorems == 1
    # f = log(1 + e1^2 + e2^2)/2 is literally F(sqrt(e1^2 + e2^2)): P4 rests on SymPy's core only
    assert checks["P4"].kernel_checked and checks["P4"].assumptions == ["sympy-core"]
    # kf = 1/2 = F'(1): 1/2 - F' = (s - 1)^2/(2 (1 + s^2)) >= 0, three theorems
    assert checks["kf"].kernel_checked and checks["kf"].theorems == 3
    # P3: F > 0 and F -> oo (s F' = s^2/(1 + s^2) >= k > 0 on [R, oo): F grows like log s);
    # P5: F' > 0, and F, F' continuous at 0+ with F'(0) = 0; with P4's identity
    # checked, the reduction to one variable no longer counts as unchecked
    assert checks["P3"].kernel_checked and checks["P3"].theorems == 2
    assert checks["P5"].kernel_checked and checks["P5"].theorems == 3
    # P1: F' > 0, F and F' continuous at 0+ with F'(0) = 0, F' <= 1/2;
    # P6: F' > 0 and F'(s)/s = 1/(1 + s^2) <= k, F and F' continuous at 0+ with F'(0) = 0
    assert checks["P1"].kernel_checked and checks["P1"].theorems == 4
    assert checks["P6"].kernel_checked and checks["P6"].theorems == 4
    # P8: F' continuous on (0, oo) and F'(0+) = 0; P7: also F'' on (0, oo) and at 0+, F at 0+
    assert checks["P8"].kernel_checked and checks["P8"].theorems == 2
    assert checks["P7"].kernel_checked and checks["P7"].theorems == 5
    assert "sympy-diff" in checks["P7"].assumptions       # the link differentiates F


def test_design3_is_kernel_checked_through_the_limit_rules():
    """Design 3, f = log cosh(sqrt(4 rho + 1) - 1): kf = 2 is approached at
    infinity, F' = 4 s tanh(Y)/sqrt(4 s^2 + 1) with Y = sqrt(4 s^2 + 1) - 1.
    kf's lower bound comes from tanh(Y) -> 1 (Y diverges) times
    4 s/sqrt(4 s^2 + 1) -> 2; its upper bound from 2 - F' =
    (2 - 4 s/sqrt(.)) + 4 s/sqrt(.) (1 - tanh Y), tanh < 1.  Every verdict is
    kernel-checked, none rests on simplify; a certificate claiming kf = 3
    fails its link."""
    cert = DC.build(verify_design(ROOT / "designs" / "design3_logcosh.py"))
    checks = _by_name(DC.check(json.dumps(cert)))
    assert all(c.kernel_checked for c in checks.values()), [c.name for c in checks.values() if not c.kernel_checked]
    assert not any("sympy-simplify" in c.assumptions for c in checks.values())
    rules = {n["rule"] for n in cert["properties"]["kf"]["kernel"]["theorems"]}
    assert {"limit_of_bounded", "limit_of_product", "sup_lower_from_limit", "sign_below_sup"} <= rules
    bad = copy.deepcopy(cert)
    bad["properties"]["kf"]["exact"] = sp.srepr(sp.Integer(3))
    with pytest.raises(DC.CertificateError, match="kf: the kernel's conclusions are not"):
        DC.check(bad)


def test_kf_and_p4_links(cert1):
    """A certificate whose kf is changed, or whose P4 identity is about
    another profile, fails its link to f."""
    bad = copy.deepcopy(cert1)
    bad["properties"]["kf"]["exact"] = sp.srepr(sp.Rational(1, 3))
    with pytest.raises(DC.CertificateError, match="kf: the kernel's conclusions are not"):
        DC.check(bad)
    bad = copy.deepcopy(cert1)
    bad["properties"]["P4"]["kernel"], bad["properties"]["P2"]["kernel"] = (
        bad["properties"]["P2"]["kernel"], bad["properties"]["P4"]["kernel"])
    with pytest.raises(DC.CertificateError, match="P2|P4"):
        DC.check(bad)


def test_kernel_conclusions_are_the_claims_about_this_f(cert1):
    """P3 proves F > 0 and P5 proves F' > 0 on (0, oo) for F(s) = f(s, 0)."""
    F = sp.log(1 + S ** 2) / 2
    for name, expr in (("P3", F), ("P5", sp.diff(F, S))):
        kernel = cert1["properties"][name]["kernel"]
        claim = kernel["theorems"][kernel["conclusions"][0]]["claim"]
        later = [kernel["theorems"][i]["claim"]["kind"] for i in kernel["conclusions"][1:]]
        assert later == (["diverges"] if name == "P3" else ["limit", "limit"])
        assert sp.simplify(parse(claim["expr"]) - expr) == 0
        assert (claim["lo"], claim["hi"], claim["want"], claim["strict"]) == ("Integer(0)", "oo", 1, True)


def test_p7_and_p8_parts_swapped_fail_the_link(cert1):
    bad = copy.deepcopy(cert1)
    bad["properties"]["P7"]["kernel"], bad["properties"]["P8"]["kernel"] = (
        bad["properties"]["P8"]["kernel"], bad["properties"]["P7"]["kernel"])
    with pytest.raises(DC.CertificateError, match="P7: the kernel's conclusions are not the ones P7 needs"):
        DC.check(bad)


def test_swapped_kernel_parts_fail_the_link(cert1):
    bad = copy.deepcopy(cert1)
    bad["properties"]["P3"]["kernel"], bad["properties"]["P5"]["kernel"] = (
        bad["properties"]["P5"]["kernel"], bad["properties"]["P3"]["kernel"])
    with pytest.raises(DC.CertificateError, match="P3: the kernel's conclusion is not F > 0"):
        DC.check(bad)


def test_certificate_for_another_f_fails_the_link(cert1):
    other = DC.build(verify_design(DESIGN2))
    bad = copy.deepcopy(cert1)
    bad["design"]["f"] = other["design"]["f"]
    with pytest.raises(DC.CertificateError, match="^P1: the kernel.s conclusions are not the ones P1 needs"):
        DC.check(bad)


def test_tampered_step_is_rejected(cert1):
    bad = copy.deepcopy(cert1)
    steps = bad["properties"]["P5"]["kernel"]["theorems"]
    step = next(t for t in steps if t["rule"] == "sign_by_sturm")
    step["data"]["want"] = -step["data"]["want"]            # claim the other sign
    with pytest.raises(DC.CertificateError, match="P5: theorem"):
        DC.check(bad)


def test_proved_without_anything_to_rest_on_is_rejected(cert1):
    bad = copy.deepcopy(cert1)
    bad["properties"]["P7"]["kernel"], bad["properties"]["P7"]["unchecked"] = None, []
    with pytest.raises(DC.CertificateError, match="P7: proved with neither"):
        DC.check(bad)


def test_a_verdict_proved_with_nothing_behind_it_is_written_as_the_search_alone():
    """A proposer that leaves a proved verdict with no kernel theorems and no
    unchecked facts must not write a certificate that fails to re-check (it
    would take every other verdict down with it): such an entry rests on the
    search, visibly."""
    report = verify_design(DESIGN2)
    report.properties["P7"].details.update(kernel=[], unchecked=[])
    cert = DC.build(report)
    assert cert["properties"]["P7"]["kernel"] is None
    assert cert["properties"]["P7"]["unchecked"] == [DC.SEARCH_ONLY]
    checks = _by_name(DC.check(cert))
    assert not checks["P7"].kernel_checked
    assert all(checks[p].kernel_checked for p in PROPS if p != "P7")


def test_a_property_whose_kernel_theorems_do_not_recheck_is_left_to_the_search_alone(cert1, monkeypatch, tmp_path):
    """A proposer bug in one property's theorems (here P5's Sturm step made to
    claim the other sign) costs that verdict only: the verifier re-checks the
    others, reports P5 as resting on the search, and names the failure."""
    from uwmr_symbolic import verify as V

    def build(report):
        bad = copy.deepcopy(cert1)
        step = next(t for t in bad["properties"]["P5"]["kernel"]["theorems"] if t["rule"] == "sign_by_sturm")
        step["data"]["want"] = -step["data"]["want"]
        return bad
    monkeypatch.setattr(DC, "build", build)
    cert, kernel = V._kernel_check(None)
    assert kernel["search"] == ["P5"] and set(kernel["checked"]) == set(PROPS) - {"P5"} | {"kf"}
    assert len(kernel["failed"]) == 1 and kernel["failed"][0][0] == "P5" and kernel["failed"][0][1].startswith("P5: theorem")
    assert cert["properties"]["P5"]["kernel"] is None and "do not re-check" in cert["properties"]["P5"]["unchecked"][0]
    assert not _by_name(DC.check(cert))["P5"].kernel_checked        # what is written re-checks, P5 left open
    from uwmr_symbolic import batch                  # such a result is not cached (its hit could never be served)
    key = design_key(load_design(DESIGN1))
    batch.check_file(str(DESIGN1), 60, tmp_path, True)
    assert ResultCache(tmp_path).get(key) is None


def test_a_proof_that_another_property_s_checked_witness_refutes_is_a_refutation(monkeypatch):
    """Red team 18a: a certificate calling P1 proved (by the search) beside a
    kernel-checked refutation of P5 whose witness refutes P1 too was accepted.
    f = |e|: df/de1 jumps from -1 to 1 across the origin on the e1 axis, which
    refutes P1 as well as P5 (`_REFUTES["origin_jump"]`).  The checker now
    refuses such a certificate, and a search that "proves" P1 gets P1 refuted
    by P5's witness, kernel-checked, also with --trust-search."""
    from uwmr_symbolic import properties, verify as V
    from uwmr_symbolic.report import kernel_text
    norm = ROOT / "tests" / "designs" / "r07_norm.py"
    cert = DC.build(verify_design(norm))
    assert cert["properties"]["P1"]["status"] == "refuted"
    assert cert["properties"]["P5"]["witness"]["kind"] == "origin_jump"
    cert["properties"]["P1"] = {"status": "proved", "reason": "so the search said", "kernel": None,
                                "unchecked": [DC.SEARCH_ONLY]}
    with pytest.raises(DC.CertificateError, match=r"^P1: the certificate says proved, but the kernel-checked "
                                                  r"witness of P5 refutes P1 too \(df/de1 -> 1 and -1 along the e1 "
                                                  r"axis on either side of the origin\)$"):
        DC.check(cert)
    monkeypatch.setitem(properties.VERIFIERS, "P1", lambda analysis: V.Verdict("proved", "the search's wrong proof"))
    for kernel_only in (True, False):
        report = V.verify_design(norm, kernel_only=kernel_only)
        p1 = report.properties["P1"]
        assert p1.refuted and p1.reason.startswith("the witness of P5 refutes P1 as well: "), p1.reason
        assert p1.reason.endswith("(the search had proved P1, wrongly: the search's wrong proof)")
        assert "P1" in report.kernel["checked"] and report.kernel["refuted_by"] == {"P1": "P5"}
        assert kernel_text(report.kernel).endswith("; the search proved P1, which the witness of P5 refutes "
                                                   "(a bug: please report it)")
        checks = _by_name(DC.check(report.certificate))
        assert checks["P1"].refutation_checked and checks["P1"].witness == checks["P5"].witness


def test_malformed_entries_and_unknown_properties_are_rejected(cert1):
    """Found by a review: an `unchecked` entry that is not a list of texts
    crashed the report; a property the checker does not know ("P9" holding
    P2's theorems) was re-checked as kernel-checked; no property at all
    re-checked as fine."""
    bad = copy.deepcopy(cert1)
    bad["properties"]["P7"].update(kernel=None, unchecked=[{}])
    with pytest.raises(DC.CertificateError, match="P7: 'unchecked' must be a list of texts"):
        DC.check(bad)
    bad = copy.deepcopy(cert1)
    bad["properties"]["P9"] = bad["properties"]["P2"]
    with pytest.raises(DC.CertificateError, match="must be among P1-P8 and kf, and they are P1, P2, .*, P8, P9, kf"):
        DC.check(bad)
    bad["properties"] = {}
    with pytest.raises(DC.CertificateError, match="and they are none"):
        DC.check(bad)


def test_other_version_gives_a_clear_error(cert1):
    bad = dict(cert1, version=1)        # version 1: P4 without f defined on the plane
    with pytest.raises(DC.CertificateError, match="version 1 is not supported: this checker reads version 2"):
        DC.check(bad)
    older = copy.deepcopy(cert1)        # kernel certificates of version 2: join_at_zero beside join_at_point
    older["properties"]["P2"]["kernel"]["version"] = 2
    with pytest.raises(DC.CertificateError, match="^P2: certificate format version 2 is not supported: this kernel "
                                                  "reads version 3 only; re-create the certificate$"):
        DC.check(older)


def test_cli_writes_and_rechecks_a_certificate(tmp_path):
    out = tmp_path / "d1.cert.json"
    r = run_cli([str(DESIGN1), "--certificate", str(out), "--no-cache", "-q"])
    assert r.returncode == 0, r.describe()
    ok = run_cli(["--check-certificate", str(out)])
    assert ok.returncode == 0, ok.describe()
    assert "P2: proved; 1 kernel theorem(s) re-checked (rests on arb, sympy-core); kernel-checked" in ok.stdout
    # which f was checked, the certified k of P6 (F'(s)/s = 1/(1 + s^2) <= 1) and kf = sup s/(1 + s^2) = 1/2
    head = (f"{out}: certificate re-checked for the f it holds, f = log(e1**2 + e2**2 + 1)/2 (it names the design "
            f"'Design 1 (Jiang et al.)', file {str(DESIGN1)!r})")
    assert ok.stdout.splitlines()[0] == head and "  P6: proved (k = 1); 4 kernel" in ok.stdout
    assert "  kf: proved (kf = 1/2); " in ok.stdout
    data = json.loads(out.read_text())
    data["properties"]["P2"]["kernel"]["theorems"][0]["claim"]["want"] = 1     # f(0, 0) > 0: false
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(data))
    r = run_cli(["--check-certificate", str(bad)])
    assert r.returncode == 1 and r.stderr.count("\n") == 1 and "does not check" in r.stderr, r.describe()
    r = run_cli(["--check-certificate", str(tmp_path / "missing.json")])
    assert r.returncode == 2 and "cannot read the certificate" in r.stderr, r.describe()
    deep = tmp_path / "deep.json"          # JSON nested past Python's recursion limit: one line, no traceback
    deep.write_text("[" * 100_000 + "]" * 100_000)
    r = run_cli(["--check-certificate", str(deep)])
    assert (r.returncode, r.stderr) == (1, f"{deep}: the certificate does not check: not JSON: nested too deeply\n"), \
        r.describe()
    # several files are checked in parallel and reported in the order given; the worst status wins
    both = run_cli(["--check-certificate", str(out), str(bad), str(out), "--jobs", "2"])
    assert both.returncode == 1 and both.stderr.startswith(f"{bad}: the certificate does not check"), both.describe()
    assert [ln for ln in both.stdout.splitlines() if not ln.startswith(" ")] == [head] * 2
    # --timeout bounds a check too: a file whose check outlives it does not check (one line, exit 1)
    slow = run_cli(["--check-certificate", str(out), "--timeout", "0.001"])
    assert slow.returncode == 1 and slow.stderr == (f"{out}: the certificate does not check: not finished within "
                                                    "--timeout 0.001 s (a step ran that long; a larger --timeout "
                                                    "gives it more time)\n"), slow.describe()
    assert slow.stdout == ""
    # a property the certificate leaves out is named as absent, not passed over in silence
    del data["properties"]["P5"], data["properties"]["kf"]
    data["properties"]["P2"] = json.loads(out.read_text())["properties"]["P2"]
    partial = tmp_path / "partial.json"
    partial.write_text(json.dumps(data))
    r = run_cli(["--check-certificate", str(partial)])
    assert r.returncode == 0, r.describe()
    assert r.stdout.splitlines()[-2:] == [
        "  P5: absent (this certificate says nothing about it)",
        "  kf: absent (a certificate holds kf only when the verifier certified a finite kf)"]
    assert "P1: proved" in ok.stdout and "absent" not in ok.stdout


def test_a_certificate_rechecks_in_a_fresh_process_whatever_form_the_prover_held(tmp_path):
    """f = (e1 cos 1 + e2 sin 1)^2 + (e1 sin 1 - e2 cos 1)^2 is rho (cos^2 1 +
    sin^2 1 = 1): P1 false (kf infinite: df/de2 = 2 e2), P2-P8 true.  The
    prover built 2 (s cos^2 1 + s sin^2 1 - 2) undistributed; a checker in a
    fresh process reads it back distributed and once printed the claim so,
    rejecting the certificate (and re-verifying the design on every cache hit)."""
    design = tmp_path / "rotated.py"
    design.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\n"
                      "f = (e1*sp.cos(1) + e2*sp.sin(1))**2 + (e1*sp.sin(1) - e2*sp.cos(1))**2\n")
    out = tmp_path / "rotated.cert.json"
    r = run_cli([str(design), "--certificate", str(out), "--no-cache", "-q"])
    assert r.returncode == 1, r.describe()                  # P1 refuted
    ok = run_cli(["--check-certificate", str(out)])
    assert ok.returncode == 0, ok.describe()
    statuses = {name: entry["status"] for name, entry in json.loads(out.read_text())["properties"].items()}
    assert statuses == {"P1": "refuted", **{p: "proved" for p in PROPS[1:]}}      # no finite kf to certify


def test_cache_hit_is_used_only_when_its_certificate_rechecks(tmp_path):
    first = check_file(str(DESIGN1), 60, str(tmp_path))
    assert first["cached"] is False and first["exit_status"] == 0
    second = check_file(str(DESIGN1), 60, str(tmp_path))
    assert second["cached"] is True
    cache = ResultCache(tmp_path)
    key = design_key(load_design(DESIGN1))
    entry = json.loads(cache.path_for(key).read_text())
    entry["result"]["properties"]["P6"]["verdict"] = "refuted"       # disagrees with the certificate
    cache.path_for(key).write_text(json.dumps(entry))
    assert check_file(str(DESIGN1), 60, str(tmp_path))["cached"] is False
    entry = json.loads(cache.path_for(key).read_text())
    steps = entry["result"]["certificate"]["properties"]["P3"]["kernel"]["theorems"]
    steps[0]["claim"]["want"] = -steps[0]["claim"]["want"]           # a tampered kernel step
    cache.path_for(key).write_text(json.dumps(entry))
    third = check_file(str(DESIGN1), 60, str(tmp_path))
    assert third["cached"] is False and third["properties"]["P3"]["verdict"] == "proved"


def test_trust_search_takes_no_verdict_resting_on_the_search_from_the_cache(tmp_path):
    """With --trust-search a verdict resting on the search counts, but an
    entry's word that the search found it is not the search: such an entry
    (here P7 given a note, kernel summary to match) is verified again."""
    assert check_file(str(DESIGN1), 60, str(tmp_path), kernel_only=False)["cached"] is False
    assert check_file(str(DESIGN1), 60, str(tmp_path), kernel_only=False)["cached"] is True
    cache = ResultCache(tmp_path)
    path = cache.path_for(design_key(load_design(DESIGN1)) | {"trust_search": True})
    entry = json.loads(path.read_text())
    entry["result"]["certificate"]["properties"]["P7"]["unchecked"] = ["F'' continuous (the search's)"]
    entry["result"]["kernel"] = {"checked": ["P1", "P2", "P3", "P4", "P5", "P6", "P8", "kf"], "search": ["P7"]}
    path.write_text(json.dumps(entry))
    again = check_file(str(DESIGN1), 60, str(tmp_path), kernel_only=False)
    assert again["cached"] is False and "P7" in again["kernel"]["checked"]


def test_cache_hit_derives_kf_gains_replay_and_exit_status_again(tmp_path):
    """What a certificate does not hold is never served as stored: design 2's
    lemniscate scenario fails bound (10) by 1.77e-5 (kf = 1 exactly, W bound
    1.832 + 0.0285 * 0.6322 * 1 + 0.15 = 2.0000177 > Wmax = 2), exit 1.  An entry
    whose gain row, proof replay and exit status were edited is served with
    all three derived again; one whose kf was edited is a miss."""
    design2 = ROOT / "designs" / "design2_sqrt.py"
    first = check_file(str(design2), 60, str(tmp_path))
    assert first["exit_status"] == 1 and first["gains"]["lemniscate"]["W_ok"] is False
    cache = ResultCache(tmp_path)
    key = design_key(load_design(design2))
    entry = json.loads(cache.path_for(key).read_text())
    entry["result"]["gains"]["lemniscate"].update(W_ok=True, W_margin="177/10000000", W_margin_float=1.77e-5)
    entry["result"]["proof_replay"] = {"ok": False, "steps": {}}
    entry["result"]["exit_status"] = 0
    cache.path_for(key).write_text(json.dumps(entry))
    hit = check_file(str(design2), 60, str(tmp_path))
    assert hit["cached"] is True and hit["exit_status"] == 1
    assert hit["gains"] == first["gains"] and hit["proof_replay"] == first["proof_replay"]
    assert hit["gains"]["lemniscate"]["W_margin"] == "-177/10000000" and hit["proof_replay"]["ok"] is True
    for edit in ({"exact": "1/2"}, {"exact": "1", "upper": 0.5}, {"unbounded": True}):
        entry = json.loads(cache.path_for(key).read_text())
        entry["result"]["kf"].update(edit)
        cache.path_for(key).write_text(json.dumps(entry))
        again = check_file(str(design2), 60, str(tmp_path))
        assert again["cached"] is False and again["kf"]["exact"] == "1", edit



def _edit_entry(cache_dir, design, edit):
    """Apply edit(result) to the cached entry of `design` (a path)."""
    cache = ResultCache(cache_dir)
    path = cache.path_for(design_key(load_design(design)))
    entry = json.loads(path.read_text())
    edit(entry["result"])
    path.write_text(json.dumps(entry))


def test_a_tampered_entry_is_not_served(tmp_path):
    """Red team 18a's cache attacks.  Design 4 (33) jumps on the circle
    |e| = sqrt((1 + pi)^2 - 1), so P1, P5, P6, P7 are refuted (exit 1); an
    entry without them, in its verdicts and its certificate, kernel summary
    to match, had been served as "all properties proved", exit 0.  Design 1
    (f = log(1 + rho)/2): P6 holds with k = 1 (F'(s)/s = 1/(1 + s^2) <= 1),
    kf = 1/2 = 0.5 exactly (F' = s/(1 + s^2), at s = 1); an entry's k = 3,
    kf digits 0.7071..., and keys no result has (a "simulation") had been
    served as stored."""
    design4 = ROOT / "designs" / "design4_cosine.py"
    first = check_file(str(design4), 60, str(tmp_path))
    refuted = [p for p, v in first["properties"].items() if v["verdict"] == "refuted"]
    assert refuted == ["P1", "P5", "P6", "P7"] and first["exit_status"] == 1

    def drop(result):
        for p in refuted:
            del result["properties"][p], result["certificate"]["properties"][p]
        result["kernel"] = {"checked": [p for p in result["kernel"]["checked"] if p not in refuted], "search": []}
    _edit_entry(tmp_path, design4, drop)
    again = check_file(str(design4), 60, str(tmp_path))
    assert again["cached"] is False and again["exit_status"] == 1 and again["properties"]["P1"]["verdict"] == "refuted"

    first = check_file(str(DESIGN1), 60, str(tmp_path))
    assert first["properties"]["P6"]["k"] == "1" and first["kf"]["exact_digits"] == "0.50000000000000000000"
    _edit_entry(tmp_path, DESIGN1, lambda r: r["properties"]["P6"].update(k="3", k_float=3.0))
    assert check_file(str(DESIGN1), 60, str(tmp_path))["cached"] is False
    _edit_entry(tmp_path, DESIGN1, lambda r: r.update(simulation={"circle": {"ok": True}}))
    _edit_entry(tmp_path, DESIGN1, lambda r: r["kf"].update(exact_digits="0.70710678118654752440", enclosure="[7, 8]"))
    _edit_entry(tmp_path, DESIGN1, lambda r: r["properties"]["P6"].update(k_float=5.0))
    _edit_entry(tmp_path, DESIGN1, lambda r: r.update(properties=dict(reversed(r["properties"].items()))))
    hit = check_file(str(DESIGN1), 60, str(tmp_path))
    assert hit["cached"] is True and "simulation" not in hit and hit["kf"]["exact_digits"] == "0.50000000000000000000"
    assert hit["kf"]["enclosure"] == "[0.5, 0.5]" and hit["properties"]["P6"]["k_float"] == 1.0
    assert list(hit["properties"]) == PROPS      # in order: the summary's column reads them so (red team 19)
    # a field no result has, a time no run takes, an entry nested beyond Python's recursion: each a miss
    for edit in (lambda r: r["properties"]["P1"].update(k="9"), lambda r: r.update(seconds=10 ** 400),
                 lambda r: r.update(seconds=float("nan"))):
        _edit_entry(tmp_path, DESIGN1, edit)
        again = check_file(str(DESIGN1), 60, str(tmp_path))
        assert again["cached"] is False and "k" not in again["properties"]["P1"] and again["seconds"] < 60
    cache = ResultCache(tmp_path)
    path = cache.path_for(design_key(load_design(DESIGN1)))
    path.write_text(path.read_text()[:-1] + ', "deep": ' + "[" * 100_000 + "]" * 100_000 + "}")
    assert check_file(str(DESIGN1), 60, str(tmp_path))["cached"] is False


def test_a_kf_the_kernel_did_not_check_is_not_served(tmp_path):
    """f = (e1^2 + e1^4)^(1/4) + log(1 + e2^2): df/de2 = 2 e2/(1 + e2^2), so
    kf = 1 (at e2 = 1), while df/de1(h, 0) ~ h^(-1/2)/2 -> oo (P1 refuted).
    The verifier leaves kf undecided; an entry claiming kf = 1/10, or kf
    infinite, rests on nobody's proof and is computed again."""
    design = tmp_path / "cusp.py"
    design.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\n"
                      "f = (e1**2 + e1**4)**sp.Rational(1, 4) + sp.log(1 + e2**2)\n")
    cache_dir = tmp_path / "cache"
    first = check_file(str(design), 60, str(cache_dir))
    assert first["kf"]["upper"] is None and first["kf"]["unbounded"] is False
    for edit in ({"exact": "1/10", "lower": 0.1, "upper": 0.1, "attained": True}, {"unbounded": True}):
        _edit_entry(cache_dir, design, lambda r: r["kf"].update(edit))
        again = check_file(str(design), 60, str(cache_dir))
        assert again["cached"] is False and again["kf"]["upper"] is None and not again["kf"]["unbounded"], edit
    assert check_file(str(design), 60, str(cache_dir))["cached"] is True


# ---------------------------------------------------------------- refuted designs

REFUTED = sorted((ROOT / "tests" / "designs").glob("r*.py"))


@pytest.fixture(scope="module")
def refuted_certs():
    return {p.stem: DC.build(verify_design(p)) for p in REFUTED + [ROOT / "designs" / "design4_cosine.py"]}


def test_certificates_of_refuted_designs_recheck(refuted_certs):
    """Every refuted design's certificate re-checks; each refuted property
    either has a kernel-checked witness or says it rests on the search."""
    refutation_checked = set()
    for stem, cert in refuted_certs.items():
        checks = _by_name(DC.check(json.dumps(cert)))
        for name, c in checks.items():
            if c.status == "refuted":
                assert c.refutation_checked or c.unchecked[0].startswith(DC.WITNESS_SEARCH), (stem, c.line())
                if c.refutation_checked:
                    refutation_checked.add((stem, name))
    # by hand: r01 f(0, 1/3) != f(1/3, 0); r03 f = sqrt(1 + s^2) - 1 - log(1 + s^2) has F(2) < 0 and
    # F'(1) = 1/sqrt(2) - 1 < 0; r05 f(0, 0) = 1; r07 |e| has df/de -> +-1 on either side of the origin;
    # r09 F'(s) = 0 exactly at s = sqrt((1 + 2 pi)^2 - 1); design 4 drops from 2 to 1 past s = sqrt((1 + pi)^2 - 1);
    # r06 f = log(1 + rho) (+ 1 for rho > 4) jumps at t = 2 on the e1 axis; r02 F = 1 - exp(-s^2) <= 2; r04 F = s^4 has df/de2(0, h) = 4 h^3 and F'(h)/h = 4 h^2 -> oo
    assert {("r01_nonradial", "P4"), ("r03_negative_near_zero", "P3"), ("r03_negative_near_zero", "P5"),
            ("r03_negative_near_zero", "P6"), ("r05_offset", "P2"), ("r09_slope_zero", "P5"),
            ("design4_cosine", "P5"), ("design4_cosine", "P6"), ("r02_bounded", "P3"), ("r04_quartic", "P1"),
            ("r04_quartic", "P6"), ("r08_rho_three_quarters", "P6"), ("design4_cosine", "P1"),
            *[("r06_jump", p) for p in ("P1", "P5", "P6")],
            *[("r07_norm", p) for p in ("P1", "P5", "P6", "P7", "P8")]} <= refutation_checked
    c = _by_name(DC.check(refuted_certs["r03_negative_near_zero"]))
    assert c["P3"].line() == ("P3: refuted; 1 kernel theorem(s) re-checked (rests on arb, sympy-core); "
                              "kernel-checked: f(2, 0) <= 0")
    assert c["P5"].witness == "df/de1(1, 0) has sign -1"
    # P7 at a Piecewise boundary, along the e2 axis: r10 F'' = 1 inside, 0 outside s = 1; design 4 and r06
    # f(0, t) itself jumps (2 -> 1, log 5 -> 1 + log 5), so df/de2 does not exist at the jump
    lines = {stem: _by_name(DC.check(refuted_certs[stem]))["P7"].line() for stem in ("r10_c1_piecewise", "r06_jump")}
    assert lines["r10_c1_piecewise"].endswith("kernel-checked: d2f/de2^2(0, t) jumps at t = 1: left limit 1, "
                                              "right limit 0")
    assert lines["r06_jump"].endswith("kernel-checked: f(0, t) jumps at t = 2: left limit log(5), right limit "
                                      "1 + log(5), value log(5)")
    assert _by_name(DC.check(refuted_certs["design4_cosine"]))["P7"].refutation_checked
    # an infinite limit at the origin: r08's F''(h) ~ (3/4) h^(-1/2), so F''(1/h) grows like sqrt(h)
    # (`diverges_by_growth` at the rate p = 1/2: sqrt(h) (F''(1/h))' -> 3/8)
    c = _by_name(DC.check(refuted_certs["r08_rho_three_quarters"]))["P7"]
    assert c.refutation_checked and c.line().endswith("kernel-checked: d2f/de2^2(0, h) -> oo as h -> 0+")


def test_tampered_refutation_witness_is_rejected(refuted_certs):
    cert = refuted_certs["r03_negative_near_zero"]
    moved = copy.deepcopy(cert)
    moved["properties"]["P3"]["witness"]["points"][0][0] = "Integer(3)"      # the kernel's claim is about f(2, 0)
    with pytest.raises(DC.CertificateError, match="P3: the kernel's conclusions are not the witness 'value'"):
        DC.check(moved)
    # moved to (10, 0), where f = sqrt(101) - 1 - log(101) > 0, kernel step and claim changed to match
    f10 = sp.srepr(sp.sqrt(101) - 1 - sp.log(101))
    moved = copy.deepcopy(cert)
    entry = moved["properties"]["P3"]
    entry["witness"]["points"][0][0] = "Integer(10)"
    entry["kernel"]["theorems"][0]["data"]["value"]["$"] = f10
    entry["kernel"]["theorems"][0]["claim"]["expr"] = f10
    with pytest.raises(DC.CertificateError, match="P3: theorem 0"):
        DC.check(moved)
    flipped = copy.deepcopy(cert)
    flipped["properties"]["P5"]["kernel"]["theorems"][0]["claim"]["want"] = 1
    with pytest.raises(DC.CertificateError, match="P5: theorem 0"):
        DC.check(flipped)
    jump = copy.deepcopy(refuted_certs["r07_norm"])
    jump["properties"]["P8"]["kernel"]["theorems"][1]["claim"]["other"] = "Integer(1)"   # df/de2(0, -h) -> 1
    with pytest.raises(DC.CertificateError, match="P8: theorem 1"):
        DC.check(jump)


def test_tampered_jump_of_a_derivative_is_rejected(refuted_certs):
    """r10's P7 witness is a jump of d2f/de2^2 along the e2 axis at (0, 1):
    read as a jump of df/de2 (order 1) the kernel's limits are not about the
    claimed derivative; a jump of the second derivative does not refute P1;
    an order the checker does not know refutes nothing."""
    cert = refuted_certs["r10_c1_piecewise"]
    witness = cert["properties"]["P7"]["witness"]
    assert (witness["kind"], witness["var"], witness["order"], witness["points"]) == (
        "jump", "e2", 2, [["Integer(0)", "Integer(1)"]])
    for change, msg in (({"order": 1}, "P7: the kernel's conclusions are not the witness 'jump'"),
                        ({"order": 3}, "P7: a jump of the order-3 derivative in e2 does not refute P7"),
                        ({"var": "e1"}, "P7: a jump of the order-2 derivative in e1 does not refute P7")):
        bad = copy.deepcopy(cert)
        bad["properties"]["P7"]["witness"].update(change)
        with pytest.raises(DC.CertificateError, match=msg):
            DC.check(bad)
    moved = copy.deepcopy(cert)
    moved["properties"]["P1"] = copy.deepcopy(cert["properties"]["P7"])
    with pytest.raises(DC.CertificateError, match="P1: a jump of the order-2 derivative in e2 does not refute P1"):
        DC.check(moved)


def test_tampered_jump_of_a_mixed_derivative_is_rejected():
    """P7 of a switch across e1 = 1 (tests/adversarial/mixed_slope_switch.py):
    d2f/de1de2 jumps at (1, 1), -4/9 on the left and -7/36 on the right.
    Without `mixed` (d2f/de1^2) it refutes nothing, nor along e2 or of order
    3; read as a jump of df/de2 the limits are not the kernel's; a condition that
    also reads e2 leaves the branches' partial derivatives unknown."""
    design = ROOT / "tests" / "adversarial" / "mixed_slope_switch.py"
    cert = DC.build(verify_design(design))
    witness = cert["properties"]["P7"]["witness"]
    assert (witness["var"], witness["order"], witness["mixed"], witness["points"]) == (
        "e1", 2, True, [["Integer(1)", "Integer(1)"]])
    assert "left limit -4/9, right limit -7/36" in _by_name(DC.check(cert))["P7"].witness
    for change, msg in (({"mixed": False}, "P7: a jump of the order-2 derivative in e1 does not refute P7"),
                        ({"order": 1}, "P7: the kernel's conclusions are not the witness 'jump'"),
                        ({"var": "e2"}, "P7: a jump of the order-2 derivative in e2 does not refute P7"),
                        ({"order": 3}, "P7: a jump of the order-3 derivative in e1 does not refute P7")):
        bad = copy.deepcopy(cert)
        bad["properties"]["P7"]["witness"].update(change)
        with pytest.raises(DC.CertificateError, match=msg):
            DC.check(bad)
    other = copy.deepcopy(cert)             # the same steps, for f whose first condition also reads e2
    f = load_design(design).f
    other["design"]["f"] = sp.srepr(sp.Piecewise((f.args[0][0], sp.And(f.args[0][1], E2 < 5)), f.args[1]))
    other["properties"] = {"P7": other["properties"]["P7"]}
    with pytest.raises(DC.CertificateError, match="P7: a jump of a derivative in e2 needs branches chosen by e1"):
        DC.check(other)


def test_cache_rechecks_a_refutation_witness(tmp_path):
    design = ROOT / "tests" / "designs" / "r03_negative_near_zero.py"
    first = check_file(str(design), 60, str(tmp_path))
    assert first["cached"] is False and first["properties"]["P3"]["verdict"] == "refuted"
    assert check_file(str(design), 60, str(tmp_path))["cached"] is True
    cache = ResultCache(tmp_path)
    key = design_key(load_design(design))
    entry = json.loads(cache.path_for(key).read_text())
    entry["result"]["certificate"]["properties"]["P3"]["witness"]["points"][0][0] = "Integer(3)"
    cache.path_for(key).write_text(json.dumps(entry))
    again = check_file(str(design), 60, str(tmp_path))
    assert again["cached"] is False and again["properties"]["P3"]["verdict"] == "refuted"


def test_piecewise_profiles_are_kernel_checked_through_their_branches(refuted_certs):
    """Piecewise F (hand facts in the design files):
    * r10: F = s^2/2 (s <= 1), s - 1/2 (s > 1); F' = s, 1 agree at 1 (C^1), F'' does not;
    * v05: F = 1 - cos(u) (u <= pi/2), u - pi/2 + 1 beyond, u = sqrt(s^2 + 1) - 1: C^2;
    * design 4: F = 1 - cos(u) up to u = pi, then u - pi + 1: F jumps from 2 to 1;
    * r06: F = log(1 + s^2), + 1 beyond s = 2: F jumps.
    P3 (F > 0, F -> oo) is a claim about the Piecewise F itself for all four.
    P1, P5, P6 need F (and F') continuous across the boundary: kernel-checked
    for r10 and v05 (P7 too for v05), refuted for design 4 and r06, whose F
    the kernel must not call continuous.  Their P8 and kf rest on F and F'
    continuous on each piece instead ("pieces"): design 4 F' = sin(u) q
    (u < pi), q (beyond), q = s/sqrt(s^2 + 1), so 0 <= F' < 1 -> 1; r06 F' =
    2s/(1 + s^2) <= 1 = F'(1) on both pieces."""
    certs = {**refuted_certs, "v05_cosine_c2": DC.build(verify_design(ROOT / "tests" / "designs" / "v05_cosine_c2.py"))}
    checked = {(stem, c.name) for stem, cert in certs.items() for c in DC.check(cert) if c.kernel_checked}
    for stem in ("r10_c1_piecewise", "v05_cosine_c2", "design4_cosine", "r06_jump"):
        assert (stem, "P3") in checked
    # kf = 1 for both: r10 F' = 1 beyond s = 1; v05 F' = q(s) = s/sqrt(s^2 + 1) -> 1 outside, sin(u) q < 1 inside;
    # P1 (C^1, kf finite) and P6 (F'(s)/s = 1 and 1/s, resp. sin(u)/sqrt(s^2 + 1) and 1/sqrt(s^2 + 1), <= 1)
    assert {("r10_c1_piecewise", p) for p in ("P1", "P5", "P6", "P8", "kf")} <= checked
    assert {("v05_cosine_c2", p) for p in ("P1", "P5", "P6", "P7", "P8", "kf")} <= checked
    assert {("design4_cosine", "P8"), ("r06_jump", "P8"), ("design4_cosine", "kf"), ("r06_jump", "kf")} <= checked
    assert not {("design4_cosine", "P1"), ("r06_jump", "P1"), ("design4_cosine", "P5")} & checked
    for stem in ("design4_cosine", "r06_jump"):
        kernel = certs[stem]["properties"]["kf"]["kernel"]
        kinds = [kernel["theorems"][i]["claim"]["kind"] for i in kernel["conclusions"]]
        assert kinds[:3] == ["sign", "sup_upper", "sup_lower"] and kinds[3] == "pieces", kinds
    kernel = certs["design4_cosine"]["properties"]["kf"]["kernel"]
    lower = kernel["theorems"][kernel["conclusions"][2]]["claim"]
    assert lower["lo"] != "Integer(0)" and lower["hi"] == "oo"        # the limit at oo, past the jump
    rules = {n["rule"] for n in certs["v05_cosine_c2"]["properties"]["P7"]["kernel"]["theorems"]}
    assert {"continuous_piecewise", "select_branch"} <= rules
    # P5 without the continuity of F and F' across s = 1: the derivative's existence there is the search's
    bad = copy.deepcopy(certs["r10_c1_piecewise"])
    kernel = bad["properties"]["P5"]["kernel"]
    kernel["conclusions"] = kernel["conclusions"][:3]
    c = _by_name(DC.check(bad))["P5"]
    assert not c.kernel_checked and c.unchecked == ["F' exists at the boundaries of F's pieces (the search's)"]
    # P8 with the continuity of the Piecewise F left out fails its link
    bad = copy.deepcopy(certs["r10_c1_piecewise"])
    bad["properties"]["P8"]["kernel"]["conclusions"] = bad["properties"]["P8"]["kernel"]["conclusions"][:-1]
    with pytest.raises(DC.CertificateError, match="P8: the kernel's conclusions are not the ones P8 needs"):
        DC.check(bad)


def test_kf_of_a_constant_derivative_is_kernel_checked(refuted_certs):
    """r07, f = |e|: F(s) = s, F' = 1 everywhere, kf = 1.  The gap 1 - F' is
    the zero polynomial: weakly signed (Sturm), and sup F' >= 1 comes from
    F' -> 1 at infinity (the candidate point s = 0 lies outside (0, oo))."""
    kf = _by_name(DC.check(refuted_certs["r07_norm"]))["kf"]
    assert kf.kernel_checked
    kernel = refuted_certs["r07_norm"]["properties"]["kf"]["kernel"]
    lower = kernel["theorems"][kernel["conclusions"][2]]["claim"]
    assert (lower["kind"], lower["lo"], lower["lo_open"], lower["other"]) == ("sup_lower", "Integer(0)", True, "Integer(1)")


ELLIPTIC = ["r01_nonradial", "v10_elliptic_sqrt", "v11_elliptic_sign_change", "v09_slope_changes_sign"]


@pytest.fixture(scope="module")
def elliptic_certs():
    return {stem: DC.build(verify_design(ROOT / "tests" / "designs" / f"{stem}.py")) for stem in ELLIPTIC}


def test_elliptic_reduction_and_a_slope_of_both_signs_are_kernel_checked(elliptic_certs):
    """By hand (the design files): r01 f = log(1 + e1^2 + 2 e2^2) = F(sqrt(e1^2 + 2 e2^2)), F = log(1 + s^2),
    kf = sqrt(2) * 1 ... sup F' = 1 at s = 1, so kf = sqrt(2); v10 sqrt(1 + e1^2 + 3 e2^2) - 1, kf = sqrt(3)
    (sup F' = 1 at oo); v09 F' = 2s(s^2 - 1)/(1 + s^2)^2 < 0 on (0, 1), sup |F'| = 1/2 at s = 1 + sqrt(2)
    (and -1/2 at sqrt(2) - 1); v11 the same F with r = 4: kf = 2 * 1/2 = 1.  Every proved verdict is
    kernel-checked, the elliptic ones through the reduction f = F(sqrt(e1^2 + r e2^2)), r > 0."""
    ratio = {"r01_nonradial": 2, "v10_elliptic_sqrt": 3, "v11_elliptic_sign_change": 4}
    for stem, cert in elliptic_certs.items():
        checks = _by_name(DC.check(cert))
        proved = [c for c in checks.values() if c.status == "proved"]
        assert all(c.kernel_checked for c in proved), [c.line() for c in proved if not c.kernel_checked]
        kernel = cert["properties"]["P8"]["kernel"]
        first = [kernel["theorems"][i]["claim"] for i in kernel["conclusions"][:2]]
        if stem in ratio:
            assert [c["kind"] for c in first] == ["identity_plane", "value_sign"]
            assert parse(first[1]["expr"]) == ratio[stem] and first[1]["want"] == 1
        else:
            assert first[0]["kind"] != "identity_plane"
    assert parse(elliptic_certs["v10_elliptic_sqrt"]["properties"]["kf"]["exact"]) == sp.sqrt(3)
    # F' of v09 changes sign: kf rests on |F'| <= 1/2 and sup F' >= 1/2
    kf = elliptic_certs["v09_slope_changes_sign"]["properties"]["kf"]["kernel"]
    claims = [kf["theorems"][i]["claim"] for i in kf["conclusions"]]
    dF = sp.diff(sp.log(1 + S ** 2) - 2 * S ** 2 / (1 + S ** 2), S)
    assert [(c["kind"], parse(c["expr"]), parse(c["other"])) for c in claims] == [
        ("sup_upper", sp.Abs(dF), sp.Rational(1, 2)), ("sup_lower", dF, sp.Rational(1, 2))]


def test_tampered_reductions_are_not_trusted(elliptic_certs):
    """The checker, not the certificate, decides whether the reduction to F is
    established: claims about F without it leave the reduction to the search."""
    cert = elliptic_certs["r01_nonradial"]
    # P3 with the reduction's theorems (identity, r > 0, f defined) dropped and nothing said to be unchecked
    bare = copy.deepcopy(cert)
    entry = bare["properties"]["P3"]
    entry["kernel"]["conclusions"] = entry["kernel"]["conclusions"][3:]
    entry["unchecked"] = []
    c = _by_name(DC.check(bare))["P3"]
    assert not c.kernel_checked and c.unchecked == [DC.REDUCTION]
    # r = 3 claimed positive beside the identity for r = 2: not the reduction of this f, and then
    # the identity is not the claim P5 needs either
    other = copy.deepcopy(cert)
    kernel = other["properties"]["P5"]["kernel"]
    value = kernel["theorems"][kernel["conclusions"][1]]
    value["claim"]["expr"] = value["data"]["value"]["$"] = "Integer(3)"
    assert DC.check_certificate(kernel)[1].claim.expr == "Integer(3)"        # the kernel step itself holds
    with pytest.raises(DC.CertificateError, match="P5: the kernel's conclusion is not dF/ds > 0"):
        DC.check(other)
    # kf = sqrt(3) * sup F' is not what the kernel showed (sqrt(2) * 1)
    wrong = copy.deepcopy(cert)
    wrong["properties"]["kf"]["exact"] = sp.srepr(sp.sqrt(3))
    with pytest.raises(DC.CertificateError, match="kf: the kernel's conclusions are not"):
        DC.check(wrong)
    # |F'| <= 1/2 with kf = 1 claimed for the radial v09
    wrong = copy.deepcopy(elliptic_certs["v09_slope_changes_sign"])
    wrong["properties"]["kf"]["exact"] = "Integer(1)"
    with pytest.raises(DC.CertificateError, match="kf: the kernel's conclusions are not"):
        DC.check(wrong)


def test_kf_link_where_f_jumps_keeps_the_sup_off_the_cuts():
    """With F known continuous only between the cuts, sup F' >= c must be
    shown on an interval with no cut inside or at a closed end (at a cut the
    Piecewise F' takes the value of whichever branch applies there, which
    need not be F's derivative).  F' = 1/(1 + s) here, one cut at s = 2."""
    from uwmr_symbolic.kernel import Claim
    dF = 1 / (1 + S)
    R = sp.srepr
    on = dict(var=R(S), lo="Integer(0)", hi="oo", lo_open=True, hi_open=True)
    sign = Claim("sign", R(dF), want=1, strict=False, **on)
    upper = Claim("sup_upper", R(dF), other="Integer(1)", **on)

    def lower(lo, hi, lo_open, hi_open):
        return Claim("sup_lower", R(dF), R(S), R(lo), R(hi), lo_open, hi_open, other="Integer(1)")
    cuts = sp.Tuple(2)
    assert DC._link_kf(dF, (sp.Integer(1),) * 2, [sign, upper, lower(0, 2, True, True)], cuts=cuts) == []
    assert DC._link_kf(dF, (sp.Integer(1),) * 2, [sign, upper, lower(2, 3, True, False)], cuts=cuts) == []
    for bad in (lower(1, 3, True, True), lower(2, 3, False, True), lower(0, 2, True, False), lower(2, 2, False, False)):
        with pytest.raises(DC.CertificateError, match="kf: the kernel's conclusions are not"):
            DC._link_kf(dF, (sp.Integer(1),) * 2, [sign, upper, bad], cuts=cuts)
    # without cuts (F continuous) the sup must be over all of (0, oo); F' >= 0 suffices, F' <= 0 does not
    with pytest.raises(DC.CertificateError):
        DC._link_kf(dF, (sp.Integer(1),) * 2, [sign, upper, lower(0, 2, True, True)])
    whole = Claim("sup_lower", R(dF), other="Integer(1)", **on)
    assert DC._link_kf(dF, (sp.Integer(1),) * 2, [sign, upper, whole]) == []
    with pytest.raises(DC.CertificateError):
        DC._link_kf(dF, (sp.Integer(1),) * 2, [dataclasses.replace(sign, want=-1), upper, whole])
    # an enclosure [1/2, 2] of kf follows from F' <= 1 and sup F' >= 1; [1/2, 9/10] does not
    assert DC._link_kf(dF, (sp.Rational(1, 2), sp.Integer(2)), [sign, upper, whole]) == []
    with pytest.raises(DC.CertificateError, match="inside"):
        DC._link_kf(dF, (sp.Rational(1, 2), sp.Rational(9, 10)), [sign, upper, whole])
    # elliptic, k = sqrt(2): [1.4142, 1.4143] holds sqrt(2) (certified by Arb), [1.4143, 2] does not
    r2 = sp.sqrt(2)
    assert DC._link_kf(dF, (sp.Rational(14142, 10000), sp.Rational(14143, 10000)), [sign, upper, whole], k=r2) == []
    with pytest.raises(DC.CertificateError, match="inside"):
        DC._link_kf(dF, (sp.Rational(14143, 10000), sp.Integer(2)), [sign, upper, whole], k=r2)


def test_slope_vanishing_on_circles_is_kernel_checked(refuted_certs):
    """r09, F = u - sin(u), u = sqrt(1 + s^2) - 1, F' = (1 - cos u) s/sqrt(1 + s^2):
    P3 from G(u) = u - sin(u) > 0 (`sign_by_substitution`) and F >= u - 1 -> oo
    (`diverges_by_comparison`); F' >= 0 only weakly (0 where u = 2 pi n), enough
    for P1 (with F' <= 2: on the tail in t = 1/s, 1 - cos u <= 2 and
    s/sqrt(1 + s^2) <= 1) and for P6 (h >= 0).  kf = 2, a sup approached
    along u = (2n + 1) pi, is only enclosed: the kernel checks [L, 2] with
    L = F'(p) >= 1.9999993 at the search's best point p (F'(p) < 2, so
    L < 2).  A narrower enclosure claimed is refused."""
    cert = refuted_certs["r09_slope_zero"]
    checks = _by_name(DC.check(cert))
    assert all(checks[p].kernel_checked for p in ("P1", "P2", "P3", "P4", "P6", "P7", "P8", "kf"))
    assert checks["P5"].refutation_checked
    kf = cert["properties"]["kf"]
    assert kf["exact"] is None and parse(kf["upper"]) == 2
    assert parse(kf["lower"]) == sp.Rational(19999993, 10**7)
    for key, value in (("upper", sp.Rational(39999999, 2 * 10**7)), ("lower", sp.Rational(19999994, 10**7)),
                       ("lower", sp.Integer(2))):
        bad = copy.deepcopy(cert)
        bad["properties"]["kf"][key] = sp.srepr(value)
        with pytest.raises(DC.CertificateError, match="kf: the kernel's conclusions"):
            DC.check(bad)
    wider = copy.deepcopy(cert)          # a wider claim follows from the kernel's
    wider["properties"]["kf"]["upper"] = sp.srepr(sp.Integer(3))
    assert _by_name(DC.check(wider))["kf"].kernel_checked

    def rules(name):
        return {t["rule"] for t in cert["properties"][name]["kernel"]["theorems"]}
    assert {"sign_by_substitution", "diverges_by_comparison"} <= rules("P3")
    for name in ("P1", "P6"):
        kernel = cert["properties"][name]["kernel"]
        first = kernel["theorems"][kernel["conclusions"][0]]["claim"]
        assert (first["kind"], first["want"], first["strict"]) == ("sign", 1, False)
    kernel = cert["properties"]["P1"]["kernel"]
    upper = kernel["theorems"][kernel["conclusions"][3]]["claim"]
    assert (upper["kind"], parse(upper["other"])) == ("sup_upper", 2)    # the search's upper end, exactly


def test_one_branch_prefix_links_only_what_it_says():
    """f = Piecewise((0, Eq(rho, 0)), (log(1 + rho), True)): F = log(1 + s^2)
    on (0, oo) (s^2 = 0 is false there) and F(0) - G(0) = 0, so the links
    read G = log(1 + s^2).  Refused: an origin value other than G(0) (the
    proposer gives only F = G on (0, oo), which P3 and P8 accept and no other
    property does, and a value_sign of 1 is not 0), an identity
    about another F, and one on [0, oo) (the links ask for F = G on (0, oo)
    and F(0) = G(0) apart, though the kernel now shows F = G on [0, oo) too)."""
    from uwmr_symbolic.certify import one_branch_theorems
    from uwmr_symbolic.kernel import rules as K
    G = sp.log(1 + S ** 2)
    F = sp.Piecewise((0, sp.Eq(S ** 2, 0)), (G, True))
    got, theorems = one_branch_theorems(F, S)
    claims = [t.claim for t in theorems]
    assert got == G and DC._one_branch(F, claims + ["rest"]) == (["rest"], G)
    jump = sp.Piecewise((1, sp.Eq(S ** 2, 0)), (G, True))           # f(0, 0) = 1, f -> 0: not G
    forged = [claims[0], K.value_sign(value=jump.subs(S, 0) - G.subs(S, 0)).claim]
    assert DC._one_branch(jump, forged) == (forged, jump)
    got, opened = one_branch_theorems(jump, S)          # F = G on (0, oo) only: P3 and P8 see no more
    assert got == G and len(opened) == 1 and DC._one_branch(jump, [opened[0].claim], open_only=True) == ([], G)
    assert DC._one_branch(jump, [opened[0].claim]) == ([opened[0].claim], jump)
    other = sp.Piecewise((0, sp.Eq(S ** 2, 0)), (2 * G, True))
    assert DC._one_branch(other, claims) == (claims, other)
    closed = [dataclasses.replace(claims[0], lo_open=False), claims[1]]
    assert DC._one_branch(F, closed) == (closed, F)
    # the kernel itself: F = G on [0, oo) holds (F(0) = 0 = G(0), the one root of s^2 = 0), the jump's does not
    closed_G = K.identity(lhs=G, rhs=G, var=S, lo=0, hi=sp.oo, lo_open=False, hi_open=True)
    assert K.select_branch(closed_G, expr=F).claim.other == sp.srepr(G)
    with pytest.raises(Exception, match="Arb disagrees"):
        K.select_branch(closed_G, expr=jump)


@pytest.mark.parametrize("stem, checked", [
    ("c2_log_squared", [*PROPS, "kf"]),   # F' = s log(1 + s^2)/(1 + s^2) <= U: log <= 4((1 + s^2)^(1/4) - 1)
    ("c2_log_log", [*PROPS, "kf"]),       # a log in F's denominator: over one denominator, log >= 1 - 1/Y
    ("c4_cancel", [*PROPS, "kf"]),        # P6 with k = 1/2 attained at sqrt(3): the kernel takes k = 9/16
    ("c6_erf", [*PROPS, "kf"]),           # F = s erf(s) + ...: s F' = s erf(s) >= k by the sign rules first
])
def test_tails_are_kernel_checked(stem, checked):
    """Designs whose F' has a log on the tail (its t-form is not defined at
    t = 0) are kernel-checked through `sign_by_log_bound`; kf of the first two
    is only enclosed, and the kernel checks an enclosure (`kf.kernel_bounds`).  The growth of s erf(s): a rate with
    functions in it is proved by the sign rules first (the t-form of erf(1/t)
    is not defined at t = 0); only an algebraic rate goes to s = 1/t first."""
    report = verify_design(ROOT / "tests" / "designs_codegen" / f"{stem}.py")
    assert report.kernel == {"checked": checked, "search": []}


def test_refutation_witnesses_have_a_budget_of_their_own(tmp_path):
    """f = 2 on the circle rho = 3, rho/(1 + rho) elsewhere: f jumps there, so
    P1, P5, P6 and P7 are refuted, each with a kernel-checked witness, and
    P3 (f -> 1) by f(h, 0) <= 2, shown piece by piece.  The witnesses are
    proposed after the search has spent its
    design budget, so `verify_design` gives them a budget of their own (as
    re-building the certificate afterwards does; with the search's budget
    only P5 and P6 had one)."""
    path = tmp_path / "point_value.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nrho = e1**2 + e2**2\n"
                    "f = sp.Piecewise((2, sp.Eq(rho, 3)), (rho/(1 + rho), True))\n")
    report = verify_design(path)
    refuted = [n for n, v in report.properties.items() if v.refuted]
    assert refuted == ["P1", "P3", "P5", "P6", "P7"]
    assert [n for n in report.kernel["checked"] if n in refuted] == ["P1", "P3", "P5", "P6", "P7"]


def test_kernel_only_checks_bound_10_on_the_kernels_kf_enclosure():
    """r09 (kf = 2, not attained), by default: kf is only enclosed, so bound
    (10) uses the kernel's [L, U] = [1.9999993, 2] (8 digits outward of the
    search's enclosure): the loose scenario (Wr_max 1, lam 0.5, Vr_max 0.5,
    k2 0.25, Wmax 2) has W <= 1 + 0.25 U + 0.25 = 1.75 <= 2.  The search's
    own lower end (--trust-search) is the tighter 1.99999934..."""
    from fractions import Fraction
    report = verify_design(ROOT / "tests" / "designs" / "r09_slope_zero.py")
    assert report.kf.kernel_bounds == (Fraction(19999993, 10**7), 2)
    assert (report.kf.lower, report.kf.upper) == report.kf.kernel_bounds
    assert "kernel's enclosure" in report.kf.reason
    assert report.gains["loose"].W_ok is True and report.gains["loose"].W_bound == sp.Rational(7, 4)
    searched = verify_design(ROOT / "tests" / "designs" / "r09_slope_zero.py", kernel_only=False)
    assert searched.kf.upper == 2 and Fraction(19999993, 10**7) < searched.kf.lower < 2


def test_an_exp_tail_with_terms_of_both_signs_is_kernel_checked(tmp_path):
    """f = c rho exp(-rho) + log(1 + rho), x = s^2: F'(s) = 2s g(x),
    g = c e^-x (1 - x) + 1/(1 + x).  c = 1: g > 0 (for x > 1,
    (x - 1) e^-x < 1/(1 + x) as x^2 - 1 < 1 + x + x^2/2 + x^3/6 <= e^x), g
    decreasing from g(0) = 2 (g' = e^-x (x - 2) - 1/(1 + x)^2 < 0), so P1-P8
    hold, P6 with k = 4, and kf = max F' = 1.4184252491514987... at
    s = 0.59181177... (50-digit mpmath).  The tail of F' in t = 1/s is not
    defined at t = 0 (exp(-1/t^2)/t^3): its terms in exp(-s^2) are bounded by
    exp(-x) <= 1/(1 + x + ... + x^4/24) (`sign_by_log_bound`).  c = 3:
    g(2) = 1/3 - 3/e^2 < 0, so P5 is refuted."""
    path = tmp_path / "exp_bump.py"
    head = "import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nrho = e1**2 + e2**2\n"
    path.write_text(head + "f = rho*sp.exp(-rho) + sp.log(1 + rho)\n")
    report = verify_design(path)
    assert all(report.properties[p].proved for p in PROPS)
    assert report.kernel == {"checked": [*PROPS, "kf"], "search": []}
    true_kf = 1.4184252491514987
    assert report.kf.lower <= true_kf <= report.kf.upper and report.kf.upper - report.kf.lower < 1e-6
    assert sp.sympify(report.properties["P6"].details["k"]) == 4
    path.write_text(head + "f = 3*rho*sp.exp(-rho) + sp.log(1 + rho)\n")
    worse = verify_design(path)
    assert worse.properties["P5"].refuted and "P5" in worse.kernel["checked"]


def _verified(tmp_path, formula):
    """The report of the design f = formula (sp, e1, e2 and rho = e1^2 + e2^2 in scope)."""
    path = tmp_path / "design.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nrho = e1**2 + e2**2\n"
                    f"f = {formula}\n")
    return verify_design(path)


def _assert_all_kernel_checked(report):
    assert all(report.properties[p].proved for p in PROPS)
    assert report.kernel == {"checked": [*PROPS, "kf"], "search": []}


@pytest.mark.parametrize("formula, refuted", [
    # F = log(1 + atan(s^2)) < log(1 + pi/2): log Y <= Y - 1 bounds F by atan(s^2) < pi/2
    ("sp.log(1 + sp.atan(rho))", ["P3"]),
    # F = log(2 - exp(-s^2)) < log 2: log Y <= Y - 1 bounds F by 1 - exp(-s^2) < 1
    ("sp.log(2 - sp.exp(-rho))", ["P3"]),
    # f(h, 0) = atan(h)^2 -> pi^2/4 (a product of two limits pi/2); not radial: P4 too
    ("sp.atan(e1)**2 + sp.atan(e2)**2", ["P3", "P4"]),
    # F' = 2s (1 + s^2)^(-1/4) - s^3 (1 + s^2)^(-5/4)/2 ~ 3 sqrt(s)/2: s^(1/2) F'' -> 3/4 > 0
    ("rho/(1 + rho)**sp.Rational(1, 4)", ["P1"]),
    # F = L/(1 + L) < 1, L = log(1 + s^2): a limit the limit calculus does not find (0 * oo), so
    # the search asks the kernel for F <= 1 (1 - F = 1/(1 + L) > 0), the integer above F(2^60)
    ("sp.log(1 + rho)/(1 + sp.log(1 + rho))", ["P3"]),
])
def test_bounded_profiles_and_power_growth_are_refuted_by_the_kernel(tmp_path, formula, refuted):
    """Refutations the search found and the kernel once could not check:
    a bound of F by log Y <= Y - 1 (p = 1 of `sign_by_log_bound`) or by
    an integer above its values (`properties._bounded_above`), a finite
    limit along a ray of a power of a bounded function (`limit_of_product`
    of repeated factors; the link "bounded" takes a limit at oo), and growth
    F' ~ c s^(1/2) by the rate p = 1/2 tried first (s^(1/2) F'' tends to a
    constant, a t-form defined at t = 0, where p = 1/4 gives one that is not)."""
    report = _verified(tmp_path, formula)
    assert [n for n, v in report.properties.items() if v.refuted] == refuted
    assert set(refuted) <= set(report.kernel["checked"])


def test_kf_attained_inside_a_piece_is_kernel_checked(tmp_path):
    """F = s^2/2 - s^4/16 for s^2 <= 2, 3/4 + log(s^2/2)/2 beyond: C^2 at
    s = sqrt(2) (values 3/4, slopes sqrt(2)/2, F'' = -1/2 on both sides).  F' =
    s - s^3/4 peaks at s = 2/sqrt(3) < sqrt(2) with kf = 4 sqrt(3)/9, and 1/s
    <= 1/sqrt(2) beyond.  kf - F' touches 0 inside the first piece: the
    piece is cut there (Taylor at the zero), not covered through it."""
    report = _verified(tmp_path, "sp.Piecewise((rho/2 - rho**2/16, rho <= 2), (sp.Rational(3, 4) + sp.log(rho/2)/2, True))")
    _assert_all_kernel_checked(report)
    assert sp.sympify(report.kf.exact) == 4 * sp.sqrt(3) / 9


def test_kf_approached_through_atan_of_a_reciprocal_is_kernel_checked(tmp_path):
    """F = s atan(s): F' = atan(s) + s/(1 + s^2) rises (F'' = 2/(1 + s^2)^2)
    to kf = pi/2, approached; F'(s)/s = atan(s)/s + 1/(1 + s^2) falls from 2
    (P6, k = 2).  Both bounds touch at s -> oo: the tail forms hold
    pi/2 - atan(t), which the kernel's identity now matches with atan(1/t)
    exactly (t > 0)."""
    report = _verified(tmp_path, "sp.sqrt(rho)*sp.atan(sp.sqrt(rho))")
    _assert_all_kernel_checked(report)
    assert report.kf.exact == sp.pi / 2 and not report.kf.attained
    assert sp.sympify(report.properties["P6"].details["k"]) == 2


def _forged(f, name, theorems):
    """A design certificate for f whose one property `name` rests on the
    given kernel theorems (after the reduction f = F(sqrt(e1^2 + 1 e2^2))),
    with no note of anything left to the search: every step is a true
    kernel theorem, only the link can tell what is missing."""
    from uwmr_symbolic.kernel import core as K
    from uwmr_symbolic.certify import to_certificate
    e1, e2 = sp.symbols("e1 e2", real=True)
    f = f(e1, e2)
    F = sp.piecewise_fold(f.xreplace({e1: S, e2: sp.Integer(0)}))
    red = K.identity_plane(lhs=f, rhs=F.xreplace({S: sp.sqrt(e1 ** 2 + e2 ** 2)}), x=e1, y=e2)
    proof = [red, K.value_sign(value=sp.Integer(1)), K.defined_on_plane(expr=f, x=e1, y=e2),
             *theorems(K, F, K.derivative(F, S))]
    return {"format": DC.FORMAT, "version": DC.VERSION, "design": {"name": "forged", "file": "forged.py",
                                                                   "f": sp.srepr(f)},
            "properties": {name: {"status": "proved", "unchecked": [], "witness": None,
                                  "kernel": to_certificate(proof)}}}


def _sturm(K, e, want=1):
    return K.sign_by_sturm(expr=e, var=S, lo=0, hi=sp.oo, lo_open=True, hi_open=True, want=want, strict=True)


@pytest.mark.parametrize("f, name, theorems, missing", [
    # rho/(1 + rho) > 0 away from 0, but it stays below 1: P3 also needs F -> oo
    (lambda x, y: (x ** 2 + y ** 2) / (1 + x ** 2 + y ** 2), "P3", lambda K, F, dF: [_sturm(K, F)],
     DC.DIVERGES),
    # |e|: F' = 1 > 0, but f has no derivative at the origin: P5 also needs F'(0+) = 0 there
    (lambda x, y: sp.sqrt(x ** 2 + y ** 2), "P5", lambda K, F, dF: [_sturm(K, dF)], DC.ORIGIN),
    # f = 1 at the origin, rho elsewhere: F' = 2s > 0, F'/s = 2 <= 3, F and F' continuous on
    # (0, oo), and yet df/de1 does not exist at the origin (f jumps there): P6 also needs F'(0+) = 0
    (lambda x, y: sp.Piecewise((1, sp.Eq(x ** 2 + y ** 2, 0)), (x ** 2 + y ** 2, True)), "P6",
     lambda K, F, dF: [K.select_branch(_sturm(K, 2 * S), _sturm(K, -S ** 2, -1), expr=dF),
                       K.select_branch(K.sup_upper_by_sign(_sturm(K, sp.Integer(1)), expr=sp.Integer(2),
                                                           bound=sp.Integer(3)), _sturm(K, -S ** 2, -1), expr=dF / S),
                       K.continuous_piecewise(_sturm(K, -S ** 2, -1), expr=F, var=S, cuts=[]),
                       K.continuous_piecewise(_sturm(K, -S ** 2, -1), expr=dF, var=S, cuts=[])], DC.ORIGIN),
])
def test_a_certificate_that_proves_half_a_property_is_not_kernel_checked(f, name, theorems, missing):
    """Found by a red team: the links took P3's F -> oo, P5's and P6's
    differentiability at the origin as optional, so these certificates (of
    false properties, made of true kernel theorems) re-checked as proofs,
    and an edited cache entry served them.  The link itself names what is
    missing, whatever the certificate's notes say."""
    (check,) = DC.check(json.dumps(_forged(f, name, theorems)))
    assert check.status == "proved" and not check.kernel_checked and check.unchecked == [missing]


def test_a_reduction_without_f_defined_on_the_plane_is_not_kernel_checked():
    """Found by a red team: f = log(1 + rho) + e2/(e2 - 2) - 2/(e2 - 2) - 1 is
    log(1 + rho) wherever it is defined, which `identity_plane` proves, but it
    has no value on the line e2 = 2; P1-P8 were proved and the certificate
    re-checked.  P4's link and the elliptic prefix now also ask for
    `defined_on_plane`, which the kernel refuses for this f."""
    from uwmr_symbolic.kernel import core as K
    from uwmr_symbolic.certify import to_certificate
    e1, e2 = sp.symbols("e1 e2", real=True)
    f = sp.log(1 + e1 ** 2 + e2 ** 2) + e2 / (e2 - 2) - 2 / (e2 - 2) - 1
    F = sp.log(1 + S ** 2)
    red = K.identity_plane(lhs=f, rhs=F.xreplace({S: sp.sqrt(e1 ** 2 + e2 ** 2)}), x=e1, y=e2)
    with pytest.raises(K.KernelError, match="not shown defined on the plane"):
        K.defined_on_plane(expr=f, x=e1, y=e2)
    design = {"name": "forged", "file": "forged.py", "f": sp.srepr(f)}
    p4 = {"format": DC.FORMAT, "version": DC.VERSION, "design": design,
          "properties": {"P4": {"status": "proved", "unchecked": [], "witness": None,
                                "kernel": to_certificate([red])}}}
    with pytest.raises(DC.CertificateError, match="P4: the kernel's conclusions are not .* and f defined at every"):
        DC.check(json.dumps(p4))
    rising = _sturm(K, K.derivative(F, S))            # F' = 2s/(1 + s^2) > 0: P5 but for the reduction (and origin)
    p5 = dict(p4, properties={"P5": {"status": "proved", "unchecked": [], "witness": None,
                                     "kernel": to_certificate([red, K.value_sign(value=sp.Integer(1)), rising])}})
    with pytest.raises(DC.CertificateError, match="P5: the kernel's conclusion is not dF/ds > 0"):
        DC.check(json.dumps(p5))        # (the prefix is no reduction; it was, without definedness)


def test_f_at_a_point_reads_the_conditions_in_order():
    """`at_point`: a condition is read only where no earlier one holds, an
    Or (And) is decided by one true (false) part, and f has no value (nan)
    where a condition read before the branch taken has none."""
    from uwmr_symbolic.design_certificate import at_point
    x, y = sp.symbols("e1 e2", real=True)
    r2 = x ** 2 + y ** 2
    f = sp.Piecewise((1, r2 <= 1), (2, sp.log(r2) > 1), (3, True))
    assert at_point(f, (0, 0)) == 1 and at_point(f, (3, 4)) == 2 and at_point(f, (1, 1)) == 3
    assert at_point(sp.Piecewise((1, sp.Eq(r2, 0) | (sp.log(r2) < 0)), (2, True)), (0, 0)) == 1
    assert at_point(sp.Piecewise((1, (r2 > 0) & (sp.log(r2) < 0)), (2, True)), (0, 0)) == 2
    assert at_point(sp.Piecewise((1, sp.log(x) > 0), (2, True)), (0, 1)) is sp.nan
    assert at_point(sp.Piecewise((1, sp.log(x) > 0), (2, True)), (-1, 1)) is sp.nan       # log(-1): not real
    assert at_point(f + x, (x, 0)) == sp.Piecewise((1, x ** 2 <= 1), (2, sp.log(x ** 2) > 1), (3, True)) + x


@pytest.mark.parametrize("name, witness", [
    # f = log(1 + e1^2 + e2^2)/2 is log(1/2)/2 < 0 at (1, i sqrt(3/2)), and df/de1 = -1/2 at (1, 2 i)
    ("P3", {"kind": "value", "points": [["Integer(1)", "Pow(Rational(-3, 2), Rational(1, 2))"]]}),
    ("P5", {"kind": "slope", "points": [["Integer(1)", "Mul(Integer(2), Pow(Integer(-1), Rational(1, 2)))"]]}),
    ("P6", {"kind": "slope", "points": [["Integer(1)", "Mul(Integer(2), Pow(Integer(-1), Rational(1, 2)))"]]}),
])
def test_a_witness_at_a_point_that_is_not_real_is_rejected(cert1, name, witness):
    """Found by a red team (forged certificates): the links never checked
    that a witness's coordinates are real, and design 1's true P3, P5 and
    P6 were "refuted" by points with an imaginary coordinate, where f and
    its derivative are real and negative."""
    from uwmr_symbolic.kernel import core as K
    from uwmr_symbolic.certify import to_certificate
    f = parse(cert1["design"]["f"], design=True)
    points = [tuple(parse(c, design=True) for c in p) for p in witness["points"]]
    value = DC.witness_values(witness["kind"], f, points)[0]
    assert value.is_real and value < 0                  # real and negative: the forgery's kernel step holds
    forged = copy.deepcopy(cert1)
    forged["properties"][name] = {"status": "refuted", "reason": "forged", "unchecked": [], "witness": witness,
                                  "kernel": to_certificate([K.value_sign(value=value)])}
    with pytest.raises(DC.CertificateError, match="not a real constant"):
        DC.check(forged)


def test_a_kf_enclosure_with_an_infinite_end_is_rejected(cert1):
    vacuous = copy.deepcopy(cert1)
    vacuous["properties"]["kf"].update(exact=None, lower="Mul(Integer(-1), oo)", upper="oo")
    with pytest.raises(DC.CertificateError, match="kf: .* is not an enclosure by finite numbers"):
        DC.check(vacuous)


def test_a_value_is_printed_only_where_the_kernel_checked_it():
    """`--check-certificate` prints P6's k and kf only on a kernel-checked
    line (red team 19: where the link leaves the claims to the search, they
    may be about another f), and a number too long for Python's str by its
    size, not a ValueError."""
    pc = DC.PropertyCheck("P6", "proved", theorems=4, unchecked=["the split of F"], value=sp.Integer(2))
    assert pc.line().startswith("P6: proved; 4 kernel theorem(s)")
    pc.unchecked = []
    assert pc.line().startswith("P6: proved (k = 2); 4 kernel theorem(s)")
    enclosed = DC.PropertyCheck("kf", "proved", theorems=3, value=(sp.Rational(1, 3), sp.Rational(1, 2)))
    assert enclosed.line().startswith("kf: proved (kf in [1/3, 1/2]); 3 kernel theorem(s)")
    big = DC.PropertyCheck("kf", "proved", theorems=3, value=sp.Integer(10) ** 5000)
    assert big.line().startswith("kf: proved (a number too long to print); 3 kernel theorem(s)")
