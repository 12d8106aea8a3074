"""Summary of a mutmut run over the trusted kernel (`make mutate`): reads the
results mutmut left in mutants/ and prints killed / total, the survivors by
function and those with no covering test.  Exit status 1 when fewer than
MUTATE_MIN percent (default 90) of the mutants are killed.  The survivors
that are equivalent mutants are listed in docs/kernel.md."""
import collections
import os
import re
import subprocess
import sys

BIN = os.path.dirname(sys.executable)


def main() -> int:
    out = subprocess.run([os.path.join(BIN, "mutmut"), "results", "--all", "true"],
                         capture_output=True, text=True, check=True).stdout
    status = {}
    for line in out.splitlines():
        name, sep, what = line.strip().rpartition(": ")
        if sep and "__mutmut_" in name:
            status[name] = what
    if not status:
        print("make mutate: no mutmut results in mutants/")
        return 1
    count = collections.Counter(status.values())
    total, killed = len(status), count["killed"]
    print(f"kernel mutants: {total}; killed {killed} ({100 * killed / total:.1f} %); "
          + "; ".join(f"{what} {k}" for what, k in sorted(count.items()) if what != "killed"))
    by_fn = collections.Counter(re.sub(r"__mutmut_\d+$", "", n.split("kernel.", 1)[1])
                                for n, what in status.items() if what != "killed")
    if by_fn:
        print("not killed, by function: " + ", ".join(f"{fn} {k}" for fn, k in by_fn.most_common()))
    print("list them: .venv/bin/mutmut results; one diff: .venv/bin/mutmut show NAME")
    return 0 if 100 * killed >= float(os.environ.get("MUTATE_MIN", "90")) * total else 1


if __name__ == "__main__":
    sys.exit(main())
