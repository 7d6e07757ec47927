"""What an earlier run left that nothing asks for: temporary files and empty folders.

A run killed while writing (SIGKILL, a power cut) cannot remove its temporary files, and may
leave folders it made for files it never renamed into place; pruning can empty a folder too.
The next plan lists them with the files to remove, so ``apply`` clears them and ``--check``
reports them as drift.
"""

from __future__ import annotations

import bisect
import os
from collections.abc import Iterable, Sequence
from pathlib import Path

from unityscaffold.fileout import temp_leftovers
from unityscaffold.manifest.model import Manifest

__all__ = ["plan_leftovers", "temp_leftovers_of"]


def _output_folders(output: Path) -> list[Path]:
    found = []
    for folder, _subfolders, _files in os.walk(output):
        found.append(Path(folder))
    return found


def _meta(path: Path) -> Path:
    return path.with_name(path.name + ".meta")


def temp_leftovers_of(files: Sequence[Path]) -> list[Path]:
    """Temporary files left beside ``files`` (and only theirs: the folder is not apply's)."""
    prefixes = tuple(f".{f.name}." for f in files)
    found = temp_leftovers({f.parent for f in files})
    return [p for p in found if p.name.startswith(prefixes)]


def plan_leftovers(
    manifest: Manifest,
    desired: Iterable[Path],
    deletions: Sequence[Path],
    extra: Iterable[Path],
    made: Iterable[Path] = (),
) -> list[Path]:
    """Temporary files to remove, then folders left empty (deepest first) with their ``.meta``.

    ``desired`` are the files the plan writes or keeps, ``deletions`` those it removes already,
    ``extra`` more files whose folders may hold temporary files (scenes, settings), ``made``
    folders an earlier apply made (a robot's, which a user's file may have held up since).
    Only folders inside ``Assets/`` that are the output folder, inside it, ``made``, or held a
    removed file are candidates: a folder apply never wrote to is never touched.
    """
    wanted = set(desired)
    assets = manifest.project_root / "Assets"
    output = manifest.project_root / manifest.output
    inside_output = _output_folders(output)
    temps = temp_leftovers([*inside_output, *{p.parent for p in (*wanted, *deletions, *extra)}])
    gone = {*deletions, *temps}
    candidates = {*inside_output, *made}
    for path in gone:
        candidates.update(p for p in path.parents if p != assets and p.is_relative_to(assets))
    # Whether a wanted file lies under a folder, by a sorted list of paths as text: building
    # the set of every wanted file's ancestors costs far more than these few lookups.
    texts = sorted(str(p) for p in wanted)

    def holds(folder: Path) -> bool:
        prefix = str(folder) + os.sep
        at = bisect.bisect_left(texts, prefix)
        return at < len(texts) and texts[at].startswith(prefix)

    emptied: list[Path] = []
    metas: list[Path] = []
    for folder in sorted(candidates, key=lambda p: len(p.parts), reverse=True):
        if holds(folder) or not folder.is_dir():
            continue
        try:
            names = os.listdir(folder)
        except OSError:
            continue
        removed = gone | set(emptied) | {_meta(f) for f in emptied}
        if all(folder / name in removed for name in names):
            emptied.append(folder)
            meta = _meta(folder)
            if meta.is_file() and meta not in wanted and meta not in gone:
                metas.append(meta)
    return [*temps, *metas, *emptied]
