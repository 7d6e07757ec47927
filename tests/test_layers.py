"""The layers of unityscaffold, checked on the import statements themselves.

Bottom up (a package may import from lower layers only, never from a peer or from above):

0. ``errors`` (the one error family), ``usercache`` (where caches live) and the package's own
   ``__init__`` (its version).
1. ``fileout`` (desired file → change → atomic write; every layer above writes through it)
   and ``resources`` (the package's templates and JSON Schema).
2. ``interfaces`` (the ROS side) and ``unity`` (the Unity side); neither knows the other.
3. ``manifest`` (its model names a ROS dialect; ``manifest.edit`` adds discovered interfaces),
   ``codegen`` (ROS types in, C# and ``.meta`` files for a Unity project out) and ``urdf`` (a
   robot's URDF in, what ROS#'s importer would build out).
4. ``apply``: plans the whole project and writes it.
5. ``cli``, then ``__main__``: the command line over all of it.

Imports under ``if TYPE_CHECKING:`` count too: a type-only back-edge is still a back-edge.
Separately, a module or name starting with ``_`` is private to the package that holds it: it
is imported only from inside that package (its subpackages included).
"""

from __future__ import annotations

import ast
from collections.abc import Iterator
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1] / "unityscaffold"

LAYERS: tuple[frozenset[str], ...] = (
    frozenset({"errors", "usercache", ""}),  # "": the package's own __init__
    frozenset({"fileout", "resources"}),
    frozenset({"interfaces", "unity"}),
    frozenset({"manifest", "codegen", "urdf"}),
    frozenset({"apply"}),
    frozenset({"cli"}),
    frozenset({"__main__"}),
)


def _rank(package: str) -> int:
    for rank, layer in enumerate(LAYERS):
        if package in layer:
            return rank
    raise AssertionError(f"unityscaffold.{package} is in no layer: add it to LAYERS in {__file__}")


def _module_name(path: Path, root: Path) -> str:
    parts = [root.name, *path.relative_to(root).with_suffix("").parts]
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imports(path: Path, module: str) -> Iterator[str]:
    """Every ``unityscaffold`` name ``path`` imports: modules, and ``module.name`` for the
    names of a ``from`` import (which may be submodules or attributes)."""
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            yield from (alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                anchor = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join([*anchor, base] if base else anchor)
            yield base
            yield from (f"{base}.{alias.name}" for alias in node.names)


def import_graph(root: Path = ROOT) -> dict[str, set[str]]:
    """Module → the ``unityscaffold`` names it imports, for every module under ``root``."""
    graph: dict[str, set[str]] = {}
    for path in sorted(root.rglob("*.py")):
        module = _module_name(path, root)
        names = _imports(path, module)
        graph[module] = {n for n in names if n.split(".")[0] == root.name}
    return graph


def _module(name: str, modules: set[str]) -> str:
    """The module an imported name lives in: ``name`` itself or its longest prefix that is one."""
    while name not in modules and "." in name:
        name = name.rpartition(".")[0]
    return name


def _package(module: str) -> str:
    """The top-level package of a module: ``unityscaffold.apply.run`` → ``apply``."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else ""


def layer_violations(graph: dict[str, set[str]]) -> list[str]:
    modules = set(graph)
    found = []
    for module, names in sorted(graph.items()):
        own = _rank(_package(module))
        for name in sorted(names):
            target = _package(_module(name, modules))
            if target != _package(module) and _rank(target) >= own:
                found.append(f"{module} imports {name} (layer {_rank(target)}, not below {own})")
    return found


def _private_part(name: str) -> tuple[str, str] | None:
    """``(package that holds it, private name)`` when ``name`` reaches a ``_private`` part."""
    parts = name.split(".")
    for i, part in enumerate(parts):
        if part.startswith("_") and not part.startswith("__"):
            return ".".join(parts[:i]), ".".join(parts[: i + 1])
    return None


def private_violations(graph: dict[str, set[str]]) -> set[tuple[str, str]]:
    """``(importer, private name)`` for every ``_name`` imported from outside its package (a
    private name in a module belongs to the module's package)."""
    modules = set(graph)
    found = set()
    for module, names in graph.items():
        for name in names:
            private = _private_part(name)
            if private is None:
                continue
            holder, private_name = private
            if not any(m.startswith(f"{holder}.") for m in modules):
                holder = holder.rpartition(".")[0]  # a module, not a package
            if module != holder and not module.startswith(f"{holder}."):
                found.add((module, private_name))
    return found


def test_no_package_imports_a_peer_or_a_higher_layer() -> None:
    assert layer_violations(import_graph()) == []


def test_no_module_imports_another_packages_private_module() -> None:
    assert private_violations(import_graph()) == set()


def test_every_package_is_in_a_layer() -> None:
    for module in import_graph():
        _rank(_package(module))


def test_the_checks_catch_a_back_edge_a_peer_edge_and_a_private_import() -> None:
    """The edge removed in issue 10 (codegen importing from ``apply``) would be caught again,
    as would an import between peers and a private module or name used from elsewhere."""
    graph = {
        "unityscaffold": set(),
        "unityscaffold.fileout": set(),
        "unityscaffold.apply.files": set(),
        "unityscaffold.apply.plan": {"unityscaffold.unity._edits", "unityscaffold.fileout"},
        "unityscaffold.cli": {"unityscaffold.__version__", "unityscaffold.unity.scene._quote"},
        "unityscaffold.codegen.layout": {"unityscaffold.apply.files.DesiredFile"},
        "unityscaffold.interfaces.model": set(),
        "unityscaffold.unity": {"unityscaffold.unity._edits.edit"},
        "unityscaffold.unity._edits": {"unityscaffold.unity.scene._quote"},
        "unityscaffold.unity.scene": {
            "unityscaffold.interfaces.model",
            "unityscaffold.unity._edits",
        },
    }
    assert layer_violations(graph) == [
        "unityscaffold.codegen.layout imports unityscaffold.apply.files.DesiredFile "
        "(layer 4, not below 3)",
        "unityscaffold.unity.scene imports unityscaffold.interfaces.model (layer 2, not below 2)",
    ]
    assert private_violations(graph) == {
        ("unityscaffold.apply.plan", "unityscaffold.unity._edits"),
        ("unityscaffold.cli", "unityscaffold.unity.scene._quote"),
    }
