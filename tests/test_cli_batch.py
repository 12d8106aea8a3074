"""`uwmr-verify` on many files: a folder mixing proved, refuted, inconclusive and
malformed designs, every output format (JUnit XML parsed with ElementTree),
the worst exit status, and the result cache (a second run is served from it,
a changed parameter or gain is not, a corrupt entry is ignored)."""
import json
import os
import re
import shutil
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from xml.etree import ElementTree as ET

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _cli import SEARCH_ONLY, ROOT  # noqa: E402

from uwmr_symbolic import batch, cache  # noqa: E402
from uwmr_symbolic.batch import Progress, expand_paths, worst_status  # noqa: E402
from uwmr_symbolic.report import assignment_line  # noqa: E402
from uwmr_symbolic.design import load_design  # noqa: E402

pytestmark = pytest.mark.slow        # more than a few seconds: not in make test-fast

PROPS = [f"P{i}" for i in range(1, 9)]
#: --timeout for runs that include the design that hangs while loading
SLOW_TIMEOUT = 8

#: An inconclusive design whatever the verifier learns: loading it outlasts
#: --timeout, so every property ends "unknown" (exit status 3).
SLOW_DESIGN = '''"""Inconclusive: loading takes longer than --timeout."""
import time
import sympy as sp
e1, e2 = sp.symbols("e1 e2", real=True)
time.sleep(600)
f = sp.log(1 + e1**2 + e2**2) / 2
'''

#: name in the mixed folder -> (source, expected exit status)
MIXED = {
    "a_proved.py": ("designs/design1_jiang.py", 0),
    "b_refuted.py": ("designs/design5_rational.py", 1),
    "c_inconclusive.py": (None, 3),
    "d_syntax_error.py": ("tests/bad_inputs/syntax_error.py", 2),
    "e_no_f.py": ("tests/bad_inputs/no_f.py", 2),
}


def run(args, cache_dir, timeout=300, env_extra=None):
    """`python -m uwmr_symbolic.cli *args` with its own cache folder."""
    env = {**os.environ, "UWMR_CACHE_DIR": str(cache_dir), **(env_extra or {})}
    t0 = time.monotonic()
    proc = subprocess.run([sys.executable, "-m", "uwmr_symbolic.cli", *map(str, args)], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=timeout, stdin=subprocess.DEVNULL)
    proc.elapsed = time.monotonic() - t0
    assert "Traceback" not in proc.stderr and "Traceback" not in proc.stdout, proc.stderr
    return proc


def describe(proc):
    return f"exit {proc.returncode}\nstderr:\n{proc.stderr[-3000:]}\nstdout:\n{proc.stdout[:3000]}"


@pytest.fixture(scope="module")
def mixed(tmp_path_factory):
    """The mixed folder, checked once per format (concurrently; one shared cache)."""
    folder = tmp_path_factory.mktemp("designs")
    for name, (src, _) in MIXED.items():
        (folder / name).write_text(SLOW_DESIGN if src is None else (ROOT / src).read_text())
    cache_dir = tmp_path_factory.mktemp("cache")
    junit_file = folder.parent / "report.xml"
    glob_arg = str(folder / "*.py")          # a glob the CLI expands itself (no shell here)
    common = [glob_arg, "--timeout", SLOW_TIMEOUT]
    # json first (it computes and caches design 1 and 5), then the other formats
    # at once: they are served from the cache and only wait for the slow file.
    runs = {"json": run([*common, "--format", "json", "--junit-xml", junit_file], cache_dir)}
    with ThreadPoolExecutor(3) as pool:
        step_summary = folder.parent / "step_summary.md"
        futs = {fmt: pool.submit(run, [*common, "--format", fmt], cache_dir,
                                 env_extra={"GITHUB_STEP_SUMMARY": str(step_summary)} if fmt == "github" else None)
                for fmt in ("junit", "github", "text")}
        runs.update({fmt: f.result() for fmt, f in futs.items()})
    return {"folder": folder, "runs": runs, "junit_file": junit_file, "cache": cache_dir,
            "step_summary": step_summary}


def _paths(folder):
    return {name: str(folder / name) for name in MIXED}


def test_mixed_folder_json_and_exit_status(mixed):
    r = mixed["runs"]["json"]
    assert r.returncode == 2, describe(r)           # malformed files make the set unusable
    results = json.loads(r.stdout)
    assert isinstance(results, list)
    assert [d["design"] for d in results] == [str(mixed["folder"] / n) for n in sorted(MIXED)]
    by_name = {Path(d["design"]).name: d for d in results}
    for name, (_, status) in MIXED.items():
        assert by_name[name]["exit_status"] == status, (name, by_name[name])
    proved, refuted, slow = by_name["a_proved.py"], by_name["b_refuted.py"], by_name["c_inconclusive.py"]
    assert {p: v["verdict"] for p, v in proved["properties"].items()} == dict.fromkeys(PROPS, "proved")
    assert refuted["properties"]["P3"]["verdict"] == "refuted" and refuted["properties"]["P3"]["witness"]
    assert refuted["gains"]["circle"]["W_ok"] is False
    assert all(v["verdict"] == "unknown" for v in slow["properties"].values())
    assert "timeout" in slow["properties"]["P1"]["reason"]
    assert by_name["d_syntax_error.py"]["error"].startswith("syntax error at line 5")
    assert "defines no `f`" in by_name["e_no_f.py"]["error"]
    # malformed files: one line each on stderr, naming the file
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 2 and "d_syntax_error.py" in lines[0] and "e_no_f.py" in lines[1], r.stderr
    assert proved["f_line"] == assignment_line((ROOT / MIXED["a_proved.py"][0]).read_text(), "f")


def _xml_cases(xml_text):
    root = ET.fromstring(xml_text)
    assert root.tag == "testsuites"
    suites = root.findall("testsuite")
    assert len(suites) == 1
    return suites[0], suites[0].findall("testcase")


def test_mixed_folder_junit(mixed):
    r = mixed["runs"]["junit"]
    assert r.returncode == 2, describe(r)
    suite, cases = _xml_cases(r.stdout)
    # the counts agree with the test cases (what CI services display)
    assert int(suite.get("tests")) == len(cases)
    assert int(suite.get("failures")) == sum(1 for c in cases if c.find("failure") is not None)
    assert int(suite.get("errors")) == sum(1 for c in cases if c.find("error") is not None)
    assert int(suite.get("skipped")) == sum(1 for c in cases if c.find("skipped") is not None)
    for c in cases:
        float(c.get("time"))
    by_design = {}
    for c in cases:
        by_design.setdefault(c.get("classname"), {})[c.get("name")] = c
    folder_cls = ".".join(mixed["folder"].parts[1:])
    proved = by_design[f"{folder_cls}.a_proved"]
    assert set(proved) == set(PROPS) | {"proof_replay", "gains[circle]", "gains[lemniscate]"}
    assert all(len(c.findall("failure")) == 0 and len(c.findall("error")) == 0 for c in proved.values())
    refuted = by_design[f"{folder_cls}.b_refuted"]
    fail = refuted["P3"].find("failure")
    assert fail is not None and fail.get("type") == "refuted" and "witness" in fail.text
    assert refuted["gains[circle]"].find("failure").get("type") == "refuted"
    assert refuted["gains[lemniscate]"].find("failure") is None
    assert refuted["P1"].find("failure") is None
    slow = by_design[f"{folder_cls}.c_inconclusive"]
    assert all(slow[p].find("failure").get("type") == "unknown" for p in PROPS)
    assert slow["gains"].find("skipped") is not None          # no gain scenarios in that file
    for bad in ("d_syntax_error", "e_no_f"):
        cases_bad = by_design[f"{folder_cls}.{bad}"]
        assert list(cases_bad) == ["load"] and cases_bad["load"].find("error") is not None
    # --junit-xml beside --format json writes the same report
    # the time of the file that hangs differs between the runs, nothing else
    assert re.sub(r' time="[0-9.]+"', "", mixed["junit_file"].read_text().strip()) == \
        re.sub(r' time="[0-9.]+"', "", r.stdout.strip())


def test_mixed_folder_github_annotations(mixed):
    r = mixed["runs"]["github"]
    assert r.returncode == 2, describe(r)
    ann = [line for line in r.stdout.splitlines() if line.startswith("::")]
    paths = _paths(mixed["folder"])
    f_line_refuted = assignment_line((ROOT / "designs/design5_rational.py").read_text(), "f")
    gains_line_refuted = assignment_line((ROOT / "designs/design5_rational.py").read_text(), "gains")
    assert f"::error file={paths['b_refuted.py']},line={f_line_refuted},title=uwmr-verify P3 refuted" \
        in "\n".join(ann)
    assert any(a.startswith(f"::error file={paths['b_refuted.py']},line={gains_line_refuted},")
               and "bound (10) fails" in a for a in ann)
    warnings = [a for a in ann if a.startswith(f"::warning file={paths['c_inconclusive.py']},")]
    assert len(warnings) >= 8 and all("unknown" in a for a in warnings[:8])
    assert any(a.startswith(f"::error file={paths['d_syntax_error.py']},line=5,") for a in ann)
    assert any(a.startswith(f"::error file={paths['e_no_f.py']},line=1,") for a in ann)
    assert any(a.startswith(f"::notice file={paths['a_proved.py']},") for a in ann)
    assert not any(a.startswith(("::error", "::warning")) and paths["a_proved.py"] in a for a in ann)
    for a in ann:   # workflow-command syntax: ::level key=value,...::message on one line
        assert re.fullmatch(r"::(error|warning|notice) file=[^,:]+,line=\d+,title=[^:]+::.+", a), a
    assert "5 design file(s): 1 proved, 1 refuted or failing a check, 1 inconclusive, 2 unusable" in r.stdout
    md = mixed["step_summary"].read_text()          # $GITHUB_STEP_SUMMARY gets a Markdown table
    assert md.count("\n| `") == 5 and "| `PPPPPPPP` |" in md and "**unusable**" in md


def test_mixed_folder_text_summary(mixed):
    r = mixed["runs"]["text"]
    assert r.returncode == 2, describe(r)
    out = r.stdout
    assert "Summary" in out and "P1  proved" in out and "P3  REFUTED" in out
    rows = {Path(line.split()[0]).name: line for line in out.splitlines()
            if line.startswith(str(mixed["folder"])) and ("  " in line)}
    assert re.search(r"PPPPPPPP .* 0 ", rows["a_proved.py"]), rows
    assert re.search(r"PPRPPPPP .* 1 ", rows["b_refuted.py"]), rows
    assert re.search(r"\?\?\?\?\?\?\?\? .* 3 ", rows["c_inconclusive.py"]), rows
    assert "unusable: syntax error" in rows["d_syntax_error.py"]
    assert "5 design file(s): 1 proved, 1 refuted or failing a check, 1 inconclusive, 2 unusable" in out
    assert r.stderr.count("\n") == 2         # the two malformed files; no progress output off a TTY


def test_worst_status_of_a_set(mixed, tmp_path):
    folder = mixed["folder"]
    assert run([folder / "a_proved.py", folder / "b_refuted.py", "--format", "json"], mixed["cache"]).returncode == 1
    r = run([folder / "a_proved.py", folder / "c_inconclusive.py", "--timeout", SLOW_TIMEOUT, "--format", "json"],
            mixed["cache"])
    assert r.returncode == 3, describe(r)
    assert run([folder / "a_proved.py", "--format", "json"], mixed["cache"]).returncode == 0
    assert [worst_status(s) for s in ([], [0, 0], [0, 3], [3, 1, 0], [1, 2, 3])] == [0, 0, 3, 1, 2]


# ---------------------------------------------------------------- cache

@pytest.fixture
def two_designs(tmp_path):
    folder = tmp_path / "designs"
    folder.mkdir()
    shutil.copy(ROOT / "designs/design1_jiang.py", folder / "proved.py")
    shutil.copy(ROOT / "designs/design5_rational.py", folder / "refuted.py")
    return folder


def _strip_cached(results):
    return [{k: v for k, v in d.items() if k != "cached"} for d in results]


def test_second_run_is_served_from_the_cache_and_prints_the_same(two_designs, tmp_path):
    files = [two_designs / "proved.py", two_designs / "refuted.py"]
    outputs = {}
    for fmt in ("json", "junit", "github", "text"):
        cache_dir = tmp_path / f"cache-{fmt}"
        extra = ["--junit-xml", tmp_path / f"{fmt}-%d.xml"] if fmt == "json" else []
        first = run([*files, "--format", fmt] + [str(a).replace("%d", "1") for a in extra], cache_dir)
        second = run([*files, "--format", fmt] + [str(a).replace("%d", "2") for a in extra], cache_dir)
        assert first.returncode == second.returncode == 1, describe(first) + describe(second)
        assert len(list(cache_dir.glob("*.json"))) == 2        # one entry per design
        assert not list(cache_dir.glob(".tmp-*"))               # atomic writes leave nothing behind
        outputs[fmt] = (first.stdout, second.stdout)
    cold, warm = (json.loads(s) for s in outputs["json"])
    assert [d["cached"] for d in cold] == [False, False] and [d["cached"] for d in warm] == [True, True]
    assert _strip_cached(cold) == _strip_cached(warm)
    assert outputs["json"][0].replace('"cached": false', '"cached": true') == outputs["json"][1]
    assert (tmp_path / "json-1.xml").read_text() == (tmp_path / "json-2.xml").read_text()
    assert outputs["junit"][0] == outputs["junit"][1]
    assert re.sub(r"(\d+\.\d\d s)\n", r"\1  (cached)\n", outputs["github"][0]) == outputs["github"][1]
    text_cold, text_warm = outputs["text"]
    assert "served from the cache" not in text_cold and text_warm.count("served from the cache") == 2
    marked = re.sub(r"\((\d+\.\d\d) s\)", r"(\1 s, served from the cache)", text_cold)
    assert re.sub(r"(\d+\.\d\d s)\n", r"\1  (cached)\n", marked) == text_warm


def test_cache_is_keyed_by_content_not_path(two_designs, tmp_path):
    cache_dir = tmp_path / "cache"
    run([two_designs / "proved.py", "--format", "json"], cache_dir)
    shutil.copy(two_designs / "proved.py", two_designs / "renamed.py")
    r = run([two_designs / "renamed.py", "--format", "json"], cache_dir)
    d = json.loads(r.stdout)
    assert d["cached"] is True and d["design"].endswith("renamed.py") and r.returncode == 0


def test_changed_parameter_or_gain_is_not_served_from_the_cache(tmp_path):
    folder = tmp_path / "d"
    folder.mkdir()
    src = (ROOT / "tests/designs/v06_param_float.py").read_text()
    design = folder / "param.py"
    design.write_text(src)
    cache_dir = tmp_path / "cache"
    first = json.loads(run([design, "--format", "json"], cache_dir).stdout)
    again = json.loads(run([design, "--format", "json"], cache_dir).stdout)
    assert (first["cached"], again["cached"]) == (False, True)
    assert "params = {c: 0.5}" in src
    design.write_text(src.replace("params = {c: 0.5}", "params = {c: 2}"))
    changed = json.loads(run([design, "--format", "json"], cache_dir).stdout)
    assert changed["cached"] is False
    assert changed["kf"]["exact"] != first["kf"]["exact"]     # kf = sqrt(c)
    design.write_text(src.replace("k2=0.5, lam=1.0, Vmax=0.75, Wmax=1.85356", "k2=0.5, lam=0.9, Vmax=0.75, Wmax=1.85356"))
    gain_changed = json.loads(run([design, "--format", "json"], cache_dir).stdout)
    assert gain_changed["cached"] is False
    assert len(list(cache_dir.glob("*.json"))) == 3


def test_corrupt_cache_entries_are_ignored_and_replaced(two_designs, tmp_path):
    cache_dir = tmp_path / "cache"
    files = [two_designs / "proved.py", two_designs / "refuted.py"]
    cold = json.loads(run([*files, "--format", "json"], cache_dir).stdout)
    entries = sorted(cache_dir.glob("*.json"))
    entries[0].write_text("{ not json")
    entries[1].write_text(json.dumps({"key": {"something": "else"}, "result": {}}))
    r = run([*files, "--format", "json"], cache_dir)
    again = json.loads(r.stdout)
    assert r.returncode == 1 and [d["cached"] for d in again] == [False, False]
    assert [d["exit_status"] for d in again] == [d["exit_status"] for d in cold]
    assert [d["properties"] for d in again] == [d["properties"] for d in cold]
    assert all(json.loads(e.read_text())["result"]["exit_status"] in (0, 1) for e in entries)


def test_no_cache_neither_reads_nor_writes(two_designs, tmp_path):
    cache_dir = tmp_path / "cache"
    files = [two_designs / "proved.py", two_designs / "refuted.py"]
    r = run([*files, "--format", "json", "--no-cache"], cache_dir)
    assert r.returncode == 1 and not cache_dir.exists()
    run([*files, "--format", "json"], cache_dir)
    again = json.loads(run([*files, "--format", "json", "--no-cache"], cache_dir).stdout)
    assert [d["cached"] for d in again] == [False, False]


def test_changed_verifier_source_is_a_different_key(monkeypatch):
    from uwmr_symbolic.design import load_design
    d = load_design(ROOT / "designs/design1_jiang.py")
    key = cache.design_key(d)
    assert key["f"].startswith("Mul(") or key["f"].startswith("Add(") or "log" in key["f"]
    assert key["tool"] and len(key["source"]) == 64
    monkeypatch.setattr(cache, "source_hash", lambda: "0" * 64)
    assert cache.digest(cache.design_key(d)) != cache.digest(key)


def test_a_result_with_an_expired_time_limit_answers_no_longer_run(tmp_path):
    """design 3 needs about a second: with --timeout 0.2 it ends inconclusive,
    a result that depends on the time given: it is stored with its timeout
    and answers only runs with no more time (tests/test_cache.py has the
    whole round)."""
    # design 3 with parameters no other test uses: nothing of it is memoised in this process (serial `make test`)
    design = tmp_path / "design3_other.py"
    design.write_text((ROOT / "designs/design3_logcosh.py").read_text().replace("{alpha: 1.0, beta: 4.0}",
                                                                                "{alpha: 3.0, beta: 7.0}"))
    cache_dir = tmp_path / "cache"
    d = batch.check_file(str(design), 0.2, str(cache_dir), True)
    assert d["exit_status"] == 3 and d["cached"] is False
    (entry,) = [json.loads(p.read_text()) for p in cache_dir.glob("*.json")]
    assert (entry["timeout"], entry["timed_out"]) == (0.2, True)
    key = cache.design_key(load_design(design))
    assert cache.ResultCache(cache_dir).get(key, 0.2) is not None
    assert cache.ResultCache(cache_dir).get(key, 1.0) is None


def test_cache_put_into_an_unwritable_place_is_harmless(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("")
    assert cache.ResultCache(blocker / "sub").put({"k": 1}, {"exit_status": 0}) is False
    c = cache.ResultCache(tmp_path / "ok")
    assert c.put({"k": 1}, {"exit_status": 0}) and c.get({"k": 1}) == {"exit_status": 0}
    assert c.get({"k": 2}) is None


# ---------------------------------------------------------------- small pieces

def test_expand_paths(tmp_path):
    for n in ("b.py", "a.py", "c.txt"):
        (tmp_path / n).write_text("")
    a, b = str(tmp_path / "a.py"), str(tmp_path / "b.py")
    assert expand_paths([str(tmp_path / "*.py")]) == [a, b]
    assert expand_paths([str(tmp_path)]) == [a, b]
    assert expand_paths([b, str(tmp_path / "*.py")]) == [b, a]          # order kept, no duplicates
    assert expand_paths([str(tmp_path / "none*.py")]) == [str(tmp_path / "none*.py")]   # reported as missing


def test_glob_matching_nothing_is_unusable_input(tmp_path):
    r = run([tmp_path / "nothing*.py", "--format", "json"], tmp_path / "cache")
    assert r.returncode == 2 and "nothing*.py" in r.stderr and len(r.stderr.strip().splitlines()) == 1


class _Stream:
    def __init__(self, tty):
        self.tty, self.text = tty, ""

    def isatty(self):
        return self.tty

    def write(self, s):
        self.text += s

    def flush(self):
        pass


def test_progress_only_on_a_terminal():
    tty, pipe = _Stream(True), _Stream(False)
    for stream in (tty, pipe):
        p = Progress(2, stream)
        p.step("x.py")
        p.step("y.py")
        p.close()
    assert "[1/2] x.py" in tty.text and "[2/2] y.py" in tty.text
    assert pipe.text == ""
    single = _Stream(True)
    Progress(1, single).step("x.py")
    assert single.text == ""


def test_cache_key_is_the_same_in_every_process():
    """The key must not depend on Python's hash seed (set iteration, dict order)."""
    code = ("import glob; from uwmr_symbolic.design import load_design; from uwmr_symbolic import cache; "
            "print(' '.join(cache.digest(cache.design_key(load_design(p))) for p in sorted(glob.glob('designs/*.py'))))")
    outs = {subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, check=True,
                           env={**os.environ, "PYTHONHASHSEED": seed}).stdout for seed in ("1", "2")}
    assert len(outs) == 1 and len(outs.pop().split()) == len(list((ROOT / "designs").glob("*.py")))


def test_the_kernel_line_says_what_the_certificate_rechecks(tmp_path):
    """The result's "kernel" entry is read off the re-checked design
    certificate: design 1 is kernel-checked throughout; r05's refuted P2
    (f(0, 0) = 1/100) has a kernel-checked witness; every decided verdict is
    in exactly one of the two lists, and a tampered certificate loses its
    checks (the cache entry is not served)."""
    designs = [ROOT / "designs/design1_jiang.py", ROOT / "tests/designs/r05_offset.py"]
    proc = run([*designs, "--format", "json"], tmp_path / "cache")
    one, offset = json.loads(proc.stdout)
    assert one["kernel"] == {"checked": [*PROPS, "kf"], "search": []}
    assert "P2" in offset["kernel"]["checked"] and offset["properties"]["P2"]["verdict"] == "refuted"
    for d in (one, offset):
        decided = {p for p, v in d["properties"].items() if v["verdict"] in ("proved", "refuted")}
        lists = d["kernel"]["checked"] + d["kernel"]["search"]
        assert len(lists) == len(set(lists)) and set(lists) - {"kf"} == decided
    text = run([designs[0]], tmp_path / "cache").stdout
    assert "kernel: re-checked P1 P2 P3 P4 P5 P6 P7 P8 kf (every decided verdict)" in text
    entry = next(e for e in (tmp_path / "cache").glob("*.json")        # design 1's entry, not r05's
                 if json.loads(e.read_text())["result"]["design"].endswith("design1_jiang.py"))
    data = json.loads(entry.read_text())
    data["result"]["kernel"]["search"].append("P9")     # a summary the certificate does not give
    entry.write_text(json.dumps(data))
    again = json.loads(run([designs[0], "--format", "json"], tmp_path / "cache").stdout)
    assert again["cached"] is False and again["kernel"] == one["kernel"]


def test_kernel_only_by_default_and_trust_search(tmp_path):
    """By default only the kernel's verdicts count (--kernel-only says it
    again): sqrt(rho + 10^-40) - 10^-20 (tests/_cli.py) has P1 proved by
    the search; it needs a bound of F' near 0 that the proposer does not
    find for the kernel.  P1 then becomes unknown, bound
    (10) is not checked (no
    kernel-checked kf: W undecided) and the exit status is 3, while P2, P4
    and P5 (F' > 0) stay proved.  With --trust-search P1 is proved and the W
    bound is checked with the enclosure.  r09 (F = u - sin u) has P5
    refuted with a kernel-checked witness (F' = 0 exactly at u = 2 pi) and
    every proof kernel-checked: exit 1 either way.  Design 1 is
    kernel-checked throughout and keeps exit 0.  The two modes have cache
    entries of their own."""
    nested = tmp_path / "search_only.py"
    nested.write_text("import sympy as sp\nfrom sympy import Rational, sqrt\n"
                      "e1, e2 = sp.symbols('e1 e2', real=True)\nrho = e1**2 + e2**2\n"
                      f"f = {SEARCH_ONLY}\n"
                      "gains = {'easy': dict(k1=0.1, k2=0.1, lam=0.1, Vmax=1.0, Wmax=2.0, Vr_max=0.5, Wr_max=0.5)}\n")
    designs = [ROOT / "designs/design1_jiang.py", ROOT / "tests/designs/r09_slope_zero.py", nested]
    proc = run([*designs, "--format", "json"], tmp_path / "cache")
    one, slope, slow = json.loads(proc.stdout)
    assert one["exit_status"] == 0 and {v["verdict"] for v in one["properties"].values()} == {"proved"}
    verdicts = {p: v["verdict"] for p, v in slope["properties"].items()}
    assert verdicts == {"P1": "proved", "P2": "proved", "P3": "proved", "P4": "proved", "P5": "refuted",
                        "P6": "proved", "P7": "proved", "P8": "proved"}
    assert slope["exit_status"] == 1
    verdicts = {p: v["verdict"] for p, v in slow["properties"].items()}
    assert verdicts["P1"] == "unknown" and {verdicts[p] for p in ("P2", "P4", "P5")} == {"proved"}
    assert slow["properties"]["P1"]["reason"].startswith(
        "not re-checked by the kernel (the search says proved, which counts only with --trust-search: ")
    assert "P1" in slow["kernel"]["search"] and slow["gains"]["easy"]["W_ok"] is None
    # JSON says whose kf it shows (red team 18b): the search's here, the kernel's kf = 1/2 of design 1
    assert slow["kf"]["upper"] is not None and slow["kf"]["kernel_checked"] is False
    assert one["kf"]["exact"] == "1/2" and one["kf"]["kernel_checked"] is True
    assert slow["exit_status"] == 3 and proc.returncode == 1      # the batch: r09's refutation
    searched = json.loads(run([nested, "--format", "json", "--trust-search"], tmp_path / "cache").stdout)
    assert searched["cached"] is False                            # not the default's entry
    assert searched["properties"]["P1"]["verdict"] == "proved" and searched["gains"]["easy"]["W_ok"] is True
    assert searched["kernel"] == slow["kernel"]                   # the same certificate, the same summary
    # its kf rests on the search alone: what an entry says the search found could be anybody's, so it is
    # computed again, also by default
    again = json.loads(run([nested, "--format", "json", "--kernel-only"], tmp_path / "cache").stdout)
    assert again["cached"] is False and again["properties"] == slow["properties"]


def test_kernel_verdict_andkf_checked():
    """A verdict the kernel did not re-check becomes unknown with the search's
    claim in its reason; kf counts as checked by its own entry or by a
    checked refutation of P1 whose witness is df/de2 -> oo."""
    from uwmr_symbolic.verdict import proved, refuted
    from uwmr_symbolic.verify import kf_checked, kernel_verdict
    kernel = {"checked": ["P1"], "search": ["P3", "P5"]}
    v = kernel_verdict("P3", proved("F > 0"), kernel)
    assert (v.status, v.reason) == ("unknown", "not re-checked by the kernel (the search says proved, which "
                                  "counts only with --trust-search: F > 0)")
    assert kernel_verdict("P5", refuted("F' = 0 at 1", {"e1": 1}), kernel).status == "unknown"
    kept = proved("C^1")
    assert kernel_verdict("P1", kept, kernel) is kept
    unbounded = {"properties": {"P1": {"witness": {"kind": "unbounded", "var": "e2"}}}}
    assert kf_checked(unbounded, kernel) and not kf_checked(unbounded, {"checked": [], "search": ["P1"]})
    assert not kf_checked({"properties": {"P1": {"witness": {"kind": "jump"}}}}, kernel)
    # df/de1 -> oo at the origin refutes P1 but says nothing of sup |df/de2| (a red team's remark)
    assert not kf_checked({"properties": {"P1": {"witness": {"kind": "unbounded", "var": "e1"}}}}, kernel)
    assert kf_checked(None, {"checked": ["kf"], "search": []}) and not kf_checked(None, kernel)


def test_a_long_exact_kf_shows_its_digits_in_the_summary():
    from uwmr_symbolic.report import _kf_summary
    long = "2999999999999989999999999999991*sqrt(5)*sqrt(sqrt(9000000000000014000000000000009) + 3)/16"
    base = {"lower": 0.6495, "upper": 0.6496, "enclosure": "[0.6495, 0.6496]", "unbounded": False}
    assert _kf_summary({**base, "exact": "3*sqrt(3)/8", "exact_digits": "0.64951905283832898507"}) == "3*sqrt(3)/8"
    assert _kf_summary({**base, "exact": long, "exact_digits": "0.64951905283832876857"}) == "0.64951905283832877..."
    # 2 sqrt(1 + 2e-16): the digits show that it is not 2 (a double would round it to 2.0000000000000004)
    assert _kf_summary({**base, "exact": "sqrt(10000000000000002)/50000000",
                        "exact_digits": "2.0000000000000002000"}) == "2.0000000000000002..."
    assert _kf_summary({**base, "exact": long, "exact_digits": "1.4285714285714285966e-31"}) == \
        "1.4285714285714286e-31..."
    assert _kf_summary({**base, "exact": None, "exact_digits": None}) == "~0.6496"
    # an integer kf written out has no exact_digits (it is its own digits); 3 * 10**150 + 7 once raised a TypeError
    assert _kf_summary({**base, "exact": str(3 * 10**150 + 7), "exact_digits": None}) == "3.0000000000000000e+150..."


def test_an_enclosure_is_printed_rounded_outward():
    # a red team: P1 printed kf = sup|F'| in [1.29483614, 1.29483626] (nearest rounding) for log(1 + rho +
    # rho^(3/4)), whose kf is 1.2948361364...: below the printed lower end
    from fractions import Fraction
    from uwmr_symbolic.kf import show_interval
    lo, hi = Fraction(1294836136402, 10 ** 12), Fraction(1294836257, 10 ** 9)
    assert show_interval(lo, hi, 9) == "[1.29483613, 1.29483626]"
    assert show_interval(Fraction(12948361, 10 ** 7), Fraction(12948363, 10 ** 7), 12) == "[1.2948361, 1.2948363]"
    assert show_interval(-Fraction(2, 3), Fraction(1, 3), 4) == "[-0.667, 0.3334]"
    tiny = Fraction(1, 3 * 10 ** 400)        # beyond the doubles: by mpmath, still outward
    assert show_interval(tiny, 2 * tiny, 5) == "[3.3333e-401, 6.6667e-401]"


def test_unusable_options_end_before_anything_is_verified_or_written(tmp_path):
    """Exit 2 with one line and nothing written: a --timeout that is not a
    number of seconds the workers can wait (inf, nan, above 1e6), a folder
    with no design file, --reference or --delay without --simulate, limits
    of --delay and --monte-carlo, two files of one name with --codegen or
    --certificate, a --reference naming no gain scenario (the certificate is
    not written first), --seed without --simulate, --trust-search with
    --kernel-only, argparse's own errors (one line, not the usage block).  A
    CSV reference may name its columns t,x,y."""
    d1 = ROOT / "designs/design1_jiang.py"
    (tmp_path / "empty").mkdir()
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    shutil.copy(d1, tmp_path / "a/d.py")
    shutil.copy(ROOT / "designs/design3_logcosh.py", tmp_path / "b/d.py")
    line = "t,x,y\n" + "".join(f"{t},{t * 0.1},0.0\n" for t in range(0, 61))
    (tmp_path / "line.csv").write_text(line)
    cases = [
        ([d1, "--timeout", "inf"], "--timeout must be a number of seconds above 0 and at most 1e+06, not inf"),
        ([d1, "--timeout", "nan"], "--timeout must be a number of seconds above 0 and at most 1e+06, not nan"),
        ([d1, "--timeout", "-inf"], "--timeout must be a number of seconds above 0 and at most 1e+06, not -inf"),
        ([d1, "--timeout", "2e6"], "--timeout must be a number of seconds above 0 and at most 1e+06, not 2e+06"),
        ([tmp_path / "empty"], f"no design files in {tmp_path / 'empty'} (a folder is read for its *.py files)"),
        ([d1, "--delay", "5"], "--reference, --delay and --seed only make sense with --simulate"),
        ([d1, "--reference", f"circle={tmp_path / 'line.csv'}"], "--reference, --delay and --seed only make sense"),
        ([d1, "--seed", "0"], "--reference, --delay and --seed only make sense with --simulate"),
        ([d1, "--monte-carlo", "2", "--seed", "-1"], "--seed must be a non-negative integer, not -1"),
        (["--check-generated", tmp_path / "nothere.py"],
         f"--check-generated: {tmp_path / 'nothere.py'}: unusable design: no such file"),
        ([d1, "--trust-search", "--kernel-only"], "--trust-search and --kernel-only contradict each other"),
        ([d1, "--formt", "json"], "unrecognized arguments: --formt json (uwmr-verify --help lists the options)"),
        ([d1, "--timeout", "abc"], "argument --timeout: invalid float value: 'abc'"),
        ([d1, "--simulate", "--delay", "1001"], "--monte-carlo must be in 0..100000 and --delay in 0..1000"),
        ([d1, "--monte-carlo", "100001"], "--monte-carlo must be in 0..100000 and --delay in 0..1000"),
        ([tmp_path / "a/d.py", tmp_path / "b/d.py", "--codegen", tmp_path / "out"],
         f"{tmp_path / 'a/d.py'} and {tmp_path / 'b/d.py'} have the same name 'd'"),
        ([d1, "--simulate", "--certificate", tmp_path / "c.json", "--reference", f"lien={tmp_path / 'line.csv'}"],
         "--reference lien=...: no design has a gain scenario 'lien' (theirs: circle, lemniscate)"),
        (["--codegen", d1], f"--codegen takes a folder, and {d1} is a design file; name the design files before"),
        (["--check-certificate", tmp_path / "c.json", d1],
         f"--check-certificate takes certificate files (.json), and {d1} looks like a design file"),
    ]
    for args, message in cases:
        proc = run([*args, "--no-cache"], tmp_path / "cache")
        assert proc.returncode == 2 and len(proc.stderr.strip().splitlines()) == 1, (args, proc.stderr)
        assert proc.stderr.startswith("uwmr-verify: " + message), (args, proc.stderr)
        assert proc.stdout == "", args
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a", "b", "empty", "line.csv"]
    from uwmr_symbolic.cli import load_references
    ref = load_references([f"line={tmp_path / 'line.csv'}"], 60)["line"]
    assert (ref.t0, ref.t1) == (0.0, 60.0)


def test_simulate_says_what_it_did_not_simulate(tmp_path):
    """--simulate on a design whose loading outlives --timeout, and on one
    without gain scenarios: one line each on stderr, no traceback; the exit
    status is the verification's (3, and 0 for the proved design without
    gains)."""
    slow, plain = tmp_path / "slow.py", tmp_path / "plain.py"
    slow.write_text(SLOW_DESIGN)
    plain.write_text((ROOT / "designs/design1_jiang.py").read_text().split("# Table 1")[0])
    proc = run([slow, plain, "--simulate", "--timeout", "2", "--no-cache", "-q"], tmp_path / "cache")
    assert proc.returncode == 3, proc.stderr
    assert proc.stderr.splitlines() == [f"{slow}: not simulated: the design file did not load within --timeout",
                                        f"{plain}: not simulated: the design has no gain scenarios"]


def test_a_failed_simulation_shows_in_every_format(tmp_path):
    """A --simulate scenario that fails a check (here written into design 1's
    result by hand: the circle's continuous run did not converge) is a JUnit
    failure, a GitHub ::error and "sim:circle:FAIL" in the summary; a passed
    one is a passed test case and a skipped one a skipped test case."""
    from uwmr_symbolic.report import render_github, render_junit, render_summary
    d = batch.check_file(str(ROOT / "designs/design1_jiang.py"), 60, None, use_cache=False)
    run = {"ok": True, "failed": []}
    d["simulation"] = {"circle": {"ok": False, "continuous": {"ok": False, "failed": ["convergence", "Lyapunov"]},
                                  "digital": run},
                       "lemniscate": {"ok": True, "continuous": run, "digital": run},
                       "line": {"skipped": "no reference for scenario 'line'", "ok": True}}
    suite = ET.fromstring(render_junit([d])).find("testsuite")
    cases = {c.get("name"): c for c in suite.iter("testcase")}
    failure = cases["simulation[circle]"].find("failure")
    assert failure.get("type") == "simulation" and failure.get("message") == \
        "simulation of scenario circle failed: continuous: convergence, Lyapunov"
    assert list(cases["simulation[lemniscate]"]) == [] and cases["simulation[line]"].find("skipped") is not None
    assert suite.get("failures") == "1" and suite.get("skipped") == "1"
    assert "title=uwmr-verify simulation fails (Design 1 (Jiang et al.)%2C circle)::continuous: convergence, " \
           "Lyapunov" in render_github([d])
    assert "circle:ok lemniscate:ok sim:circle:FAIL" in render_summary([d])
    # the verdict line says what failed: nothing is refuted, no gain check fails (red team 16b: it read
    # "REFUTED or a gain check fails", which the simulation's exit status 1 had set)
    from uwmr_symbolic.report import status_text
    d["exit_status"] = 1
    assert status_text(d) == "a simulation check fails (nothing refuted, no gain check failed)"
    d["properties"]["P3"] = dict(d["properties"]["P3"], verdict="refuted")
    assert status_text(d) == "REFUTED or a gain check fails"


def test_a_cache_hit_certificate_names_the_file_given_and_an_unwritable_cache_is_said(tmp_path):
    """The cache key is the design's content, so a copy of a design is served
    its original's entry: the certificate written from that hit names the
    copy.  A cache folder that cannot be written is one warning line, and the
    run goes on (exit 0), uncached."""
    copy = tmp_path / "mycopy.py"
    shutil.copy(ROOT / "designs/design1_jiang.py", copy)
    assert run([ROOT / "designs/design1_jiang.py", "-q"], tmp_path / "cache").returncode == 0
    proc = run([copy, "--format", "json", "--certificate", tmp_path / "c.json"], tmp_path / "cache")
    assert proc.returncode == 0 and json.loads(proc.stdout)["cached"] is True, describe(proc)
    # every verdict kernel-checked, P4 too: nothing is left to the search, the reduction included
    assert {p: v["unchecked"] for p, v in json.loads(proc.stdout)["properties"].items()} == {
        f"P{i}": [] for i in range(1, 9)}
    assert json.loads((tmp_path / "c.json").read_text())["design"]["file"] == str(copy)
    (tmp_path / "afile").write_text("")
    proc = run([copy, "-q"], tmp_path / "afile")
    assert proc.returncode == 0, describe(proc)
    assert proc.stderr.startswith(f"uwmr-verify: warning: the cache folder {tmp_path / 'afile'} cannot be written "
                                  f"(File exists); results are not cached") and proc.stderr.count("\n") == 1


def test_kf_at_any_scale_in_the_summary_and_the_cache(tmp_path):
    """Red team 15a.  By hand: f = c log(1 + rho)/2 has kf = c/2 (F' = c s/(1 + s^2), largest at s = 1).
    c = 2.4691357802469134e100: kf = 123456789012345670... *10^83, exact, which the summary table parsed with
    Decimal (a traceback with -q, junit, github); 10^-400 (rho/(1 + rho) + log(1 + rho)): F' = 2s/(1 + s^2)^2 +
    2s/(1 + s^2), largest at s = 0.7493682758 (mpmath's findroot of F''), kf = 1.5744006471e-400, enclosed,
    which the summary, JUnit and GitHub printed as its double, ~4.94e-324;
    c = 1e-25: kf = 1/(2·10^25) exactly, never served from the cache (its printed form was compared with
    str() of the value)."""
    folder = tmp_path / "d"
    folder.mkdir()
    head = "import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nrho = e1**2 + e2**2\n"
    gains = "gains = {'circle': dict(k1=0.25, k2=0.7, lam=0.3, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0)}\n"
    (folder / "a_int.py").write_text(head + "f = 2.4691357802469134e100*sp.log(1 + rho)/2\n" + gains)
    (folder / "b_tiny.py").write_text(head + "f = sp.Float('1e-400')*(rho/(1 + rho) + sp.log(1 + rho))\n" + gains)
    (folder / "c_small.py").write_text(head + "f = 1e-25*sp.log(1 + rho)/2\n" + gains)
    files = sorted(folder.glob("*.py"))
    cold = run([*files, "-q"], tmp_path / "cache")
    rows = {line.split()[0].rsplit("/", 1)[-1]: line.split() for line in cold.stdout.splitlines() if "/d/" in line}
    assert rows["a_int.py"][2] == "1.2345678901234567e+100..."
    shown = rows["b_tiny.py"][2]            # the enclosure's upper end, rounded up
    assert shown.startswith("~") and shown.endswith("e-400") and 0 <= float(shown[1:-5]) - 1.5744006471 < 1e-6
    assert rows["c_small.py"][2] == "1/(2*10**25)"
    for fmt in ("junit", "github"):
        out = run([*files, "--format", fmt, "--no-cache"], tmp_path / "cache").stdout
        assert "4.94065646e-324" not in out and "e-400" in out
    warm = json.loads(run([*files, "--format", "json"], tmp_path / "cache").stdout)
    assert [d["cached"] for d in warm] == [True, True, True]
