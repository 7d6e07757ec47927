"""Messages and hints below ``cli`` name a command-line flag only where one command reaches them.

A library module shared by several commands cannot know which one is running: a hint naming
``msgs gen``'s ``--namespace`` is wrong during ``apply``, whose setting is the manifest key
``namespace:``. Such a module words its hint without flags, and the command adds its own.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1] / "unityscaffold"
FLAG = re.compile(r"(?:^|(?<=[\s`(]))--[a-z]")
# A flag right after its command ("apply --force") says which command it belongs to.
COMMANDS = ("apply", "plan", "init", "discover", "msgs gen", "msgs list", "msgs show")

# Module -> the one command that reaches the text naming its flags.
ONE_COMMAND = {
    "apply/init.py": "init",
    "interfaces/live/__init__.py": "discover",
    "interfaces/live/_graph.py": "discover",  # rclpy missing: --rosbridge instead
    "interfaces/live/_rosapi_details.py": "discover",  # no definition: --ros2 instead
    "interfaces/live/model.py": "discover",  # NameFilter.of: --select / --exclude
    "manifest/edit.py": "discover",  # --print
    "unity/setvalue.py": "scene attach",  # --set
}


def _docstrings(tree: ast.Module) -> set[int]:
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Module | ast.ClassDef | ast.FunctionDef | ast.AsyncFunctionDef):
            body = node.body
            if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
                found.add(id(body[0].value))
    return found


def _texts_naming_flags(path: Path, shown: str) -> list[str]:
    """Every string literal in ``path`` (docstrings aside) that names a ``--flag``."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    skip = _docstrings(tree)
    return [
        f"{shown}:{node.lineno}: {node.value!r}"
        for node in ast.walk(tree)
        if isinstance(node, ast.Constant)
        and isinstance(node.value, str)
        and id(node) not in skip
        and _names_a_bare_flag(node.value)
    ]


def _names_a_bare_flag(text: str) -> bool:
    for match in FLAG.finditer(text):
        before = text[: match.start()].rstrip()
        if not before.endswith(COMMANDS) and not re.search(r"scene \w+$", before):
            return True
    return False


def test_shared_library_modules_name_no_command_line_flag() -> None:
    found = []
    for path in sorted(ROOT.rglob("*.py")):
        shown = path.relative_to(ROOT).as_posix()
        if not shown.startswith("cli/") and shown not in ONE_COMMAND:
            found += _texts_naming_flags(path, shown)
    assert found == []


def test_the_scan_sees_a_flag_in_a_hint_but_not_in_a_docstring(tmp_path: Path) -> None:
    module = tmp_path / "m.py"
    lines = ['"""Doc naming --doc."""', 'HINT = "pass it with --namespace"', 'X = "a--b"']
    lines += ['Y = "run apply --force"', 'Z = "scene attach --create"']
    module.write_text("\n".join(lines) + "\n")
    assert _texts_naming_flags(module, "m.py") == ["m.py:2: 'pass it with --namespace'"]
