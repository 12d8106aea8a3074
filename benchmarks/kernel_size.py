"""The size of the trusted kernel (issue 9's goal: <= 1.5k lines): per file,
physical lines and lines of code (neither blank, nor a comment, nor part of a
docstring -- the kernel's docstrings state each rule and its premises)."""
import ast
from pathlib import Path

KERNEL = Path(__file__).resolve().parent.parent / "uwmr_symbolic" / "kernel"


def sizes(path: Path) -> tuple[int, int]:
    text = path.read_text()
    docstrings = set()
    for node in ast.walk(ast.parse(text)):
        body = getattr(node, "body", None)
        if isinstance(body, list) and body and isinstance(body[0], ast.Expr) \
                and isinstance(body[0].value, ast.Constant) and isinstance(body[0].value.value, str):
            docstrings.update(range(body[0].lineno, body[0].end_lineno + 1))
    lines = text.splitlines()
    code = sum(1 for i, line in enumerate(lines, 1)
               if line.strip() and not line.strip().startswith("#") and i not in docstrings)
    return len(lines), code


if __name__ == "__main__":
    total = [0, 0]
    for path in sorted(KERNEL.glob("*.py")):
        lines, code = sizes(path)
        total = [total[0] + lines, total[1] + code]
        print(f"{path.name:16} {lines:6} lines {code:6} of code")
    print(f"{'kernel':16} {total[0]:6} lines {total[1]:6} of code (goal 1.5k)")
    lines, code = sizes(KERNEL.parent / "design_certificate.py")
    print(f"{'links to P1-P8':16} {lines:6} lines {code:6} of code (design_certificate.py, trusted too)")
