"""Modules keep to their own internals, checked on the syntax tree of every library module.

1. **No reaching into another module's private members.** ``x._name`` (one leading underscore,
   not a dunder) is flagged unless

   - ``x`` is ``self`` or ``cls``;
   - ``_name`` is defined in the same module (a function, class, method or assigned name, or a
     ``self._name = …`` attribute), so ``other._name`` inside the class that owns ``_name``
     passes: the module that defines a private member may use it on any instance;
   - ``x`` is a module of the same package imported under that name (``_fields as F``), because
     a ``_name`` in a module is private to its package (the rule ``tests/test_layers.py`` checks
     for imports).

   This is an approximation without types: a private member that happens to share its name
   with one the accessing module defines is not caught. It needs no list of exceptions today.
2. **No import cycle between modules**, counting imports inside functions and under
   ``if TYPE_CHECKING:``: a cycle broken by a lazy import is still a cycle.
"""

from __future__ import annotations

import ast
from collections.abc import Iterator
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1] / "unityscaffold"


def _module_name(path: Path, root: Path) -> str:
    parts = [root.name, *path.relative_to(root).with_suffix("").parts]
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _sources(root: Path) -> dict[str, tuple[ast.Module, bool]]:
    """Module name → (its syntax tree, whether it is a package ``__init__``)."""
    return {
        _module_name(path, root): (
            ast.parse(path.read_text(encoding="utf-8")),
            path.name == "__init__.py",
        )
        for path in sorted(root.rglob("*.py"))
    }


def _is_private(name: str) -> bool:
    return name.startswith("_") and not name.startswith("__")


def _package_of(module: str, is_package: bool) -> str:
    return module if is_package else module.rpartition(".")[0]


def _imported_modules(
    tree: ast.Module, module: str, is_package: bool, modules: set[str]
) -> Iterator[tuple[str, str]]:
    """(local name, module) for every module of ``modules`` that ``tree`` imports, anywhere."""
    package = _package_of(module, is_package)
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name in modules:
                    yield alias.asname or alias.name.partition(".")[0], alias.name
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parts = package.split(".")
                anchor = parts[: len(parts) - node.level + 1]
                base = ".".join([*anchor, base] if base else anchor)
            for alias in node.names:
                full = f"{base}.{alias.name}"
                if full in modules:
                    yield alias.asname or alias.name, full
                elif base in modules:
                    yield "", base  # a name from the module itself: an edge, no module alias


def _defined_names(tree: ast.Module) -> set[str]:
    names: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
            names.add(node.id)
        elif isinstance(node, ast.Attribute) and isinstance(node.ctx, ast.Store):
            names.add(node.attr)  # ``self._x = …``, or ``other._x = …`` in the owner's module
    return names


def private_accesses(sources: dict[str, tuple[ast.Module, bool]]) -> list[str]:
    """``module:line: expression`` for every access to another module's private member."""
    modules = set(sources)
    found: list[tuple[str, int, str]] = []
    for module, (tree, is_package) in sorted(sources.items()):
        package = _package_of(module, is_package)
        own = _defined_names(tree)
        siblings = {
            local
            for local, target in _imported_modules(tree, module, is_package, modules)
            if local and (target == package or target.startswith(f"{package}."))
        }
        for node in ast.walk(tree):
            if not isinstance(node, ast.Attribute) or not _is_private(node.attr):
                continue
            if node.attr in own:
                continue
            if isinstance(node.value, ast.Name) and node.value.id in {"self", "cls", *siblings}:
                continue
            found.append((module, node.lineno, ast.unparse(node)))
    return [f"{module}:{line}: {text}" for module, line, text in sorted(found)]


def import_cycles(sources: dict[str, tuple[ast.Module, bool]]) -> list[list[str]]:
    """Every set of modules that import each other in a ring (strongly connected, size > 1)."""
    modules = set(sources)
    edges = {
        module: {
            target
            for _, target in _imported_modules(tree, module, is_package, modules)
            if target != module
        }
        for module, (tree, is_package) in sources.items()
    }
    # Tarjan's algorithm, iterative so that deep import chains need no recursion limit.
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    cycles: list[list[str]] = []
    for start in sorted(edges):
        if start in index:
            continue
        work = [(start, iter(sorted(edges[start])))]
        index[start] = low[start] = len(index)
        stack.append(start)
        while work:
            node, targets = work[-1]
            target = next(targets, None)
            if target is not None:
                if target not in index:
                    index[target] = low[target] = len(index)
                    stack.append(target)
                    work.append((target, iter(sorted(edges[target]))))
                elif target in stack:
                    low[node] = min(low[node], index[target])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                ring = []
                while True:
                    member = stack.pop()
                    ring.append(member)
                    if member == node:
                        break
                if len(ring) > 1:
                    cycles.append(sorted(ring))
    return cycles


def test_no_module_uses_another_modules_private_members() -> None:
    assert private_accesses(_sources(ROOT)) == []


def test_no_modules_import_each_other_even_lazily() -> None:
    assert import_cycles(_sources(ROOT)) == []


def _parse(modules: dict[str, str]) -> dict[str, tuple[ast.Module, bool]]:
    return {
        name.removesuffix(".__init__"): (ast.parse(text), name.endswith(".__init__"))
        for name, text in modules.items()
    }


def test_the_checks_catch_the_pattern_issue_10_removed() -> None:
    """The scene edits once used ``SceneDocument``'s private members, and ``scene`` imported
    ``_edits`` inside its methods while ``_edits`` imported ``scene`` for type checking."""
    sources = _parse(
        {
            "pkg.__init__": "",
            "pkg.scene": (
                "class SceneDocument:\n"
                "    def __init__(self):\n"
                "        self._docs = []\n"
                "    def __eq__(self, other):\n"
                "        return self._docs == other._docs\n"
                "    def edit(self):\n"
                "        from pkg._edits import edit\n"
                "        return edit(self)\n"
            ),
            "pkg._edits": (
                "from typing import TYPE_CHECKING\n"
                "from pkg import _fields as F\n"
                "if TYPE_CHECKING:\n"
                "    from pkg.scene import SceneDocument\n"
                "def edit(scene):\n"
                "    F._span(scene)\n"
                "    return scene._docs\n"
            ),
            "pkg._fields": "def _span(doc):\n    return doc\n",
        }
    )
    assert private_accesses(sources) == ["pkg._edits:7: scene._docs"]
    assert import_cycles(sources) == [["pkg._edits", "pkg.scene"]]
