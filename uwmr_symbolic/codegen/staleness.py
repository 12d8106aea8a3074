"""`uwmr-verify --check-generated`: does generated/ hold exactly what the
current designs and the current tool generate?  Used by CI of repositories
that commit generated code (this one included)."""
from __future__ import annotations

from pathlib import Path

from . import CodegenRefused, build


def stale_files(designs, generated_root, orphans: bool = True) -> list[str]:
    """One line per problem: a missing, differing or unexpected file (and,
    with `orphans`, a folder of generated_root that no design produces)."""
    problems = []
    root = Path(generated_root)
    for path in sorted(Path(p) for p in designs):
        try:
            _, files = build(path, force=True)
        except CodegenRefused as exc:       # with force, only an unusable design file
            exc.path = path
            raise
        folder = root / path.stem
        for name, text in sorted(files.items()):
            target = folder / name
            if not target.exists():
                problems.append(f"{target}: missing (write it with `python -m uwmr_symbolic.codegen --force "
                                f"--out {root} {path}`)")
            elif target.read_text(encoding="utf-8") != text:
                problems.append(f"{target}: stale, differs from what {path} generates now")
        if folder.is_dir():
            for extra in sorted(set(p.name for p in folder.iterdir() if p.is_file()) - set(files)):
                problems.append(f"{folder / extra}: not produced by the generator")
    known = {Path(p).stem for p in designs}
    if orphans and root.is_dir():
        for folder in sorted(p for p in root.iterdir() if p.is_dir() and p.name not in known
                             and not p.name.startswith(".")):
            problems.append(f"{folder}: no design file {folder.name}.py")
    return problems
