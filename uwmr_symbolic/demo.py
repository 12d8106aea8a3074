"""`make demo`: verify every design in a folder with `uwmr-verify` and print
its reports and summary table.  Refuted designs are expected here (the paper's
designs 2, 4, 5 and the baseline), so only unusable input fails the demo."""
from __future__ import annotations

import sys

from .cli import main as verify_main


def main(argv=None) -> int:
    folder = (argv or sys.argv[1:] or ["designs"])[0]
    status = verify_main([folder, "--no-cache"])
    print(f"\nuwmr-verify exit status {status} (the codes: 0 all proved, 1 something refuted or a gain check failed, "
          "3 inconclusive, 2 unusable input). "
          "Next: `.venv/bin/uwmr-verify designs/design1_jiang.py --codegen --simulate`.")
    return 2 if status == 2 else 0


if __name__ == "__main__":
    sys.exit(main())
