"""How one generated file names the classes it uses: simple names, usings or ``global::``.

Usings go inside the namespace declaration, so an imported class wins over anything in the
enclosing ``RosSharp.RosBridgeClient`` namespace or the global namespace (a user's own
``Path`` or ``Odometry`` MonoBehaviour). A simple name that two imported namespaces (or the
file's own namespace) both define is written fully qualified with ``global::``.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterable
from dataclasses import dataclass, field

from unityscaffold.codegen.naming import CsClass

__all__ = ["KnownClasses", "References"]


@dataclass(slots=True)
class KnownClasses:
    """Class names per namespace, to tell when a simple name would be ambiguous."""

    by_namespace: dict[str, set[str]] = field(default_factory=lambda: defaultdict(set))

    def add(self, classes: Iterable[CsClass]) -> None:
        for cls in classes:
            self.by_namespace[cls.namespace].add(cls.name)

    def add_names(self, namespace: str, names: Iterable[str]) -> None:
        """Classes of ``namespace`` by their names (no CsClass made for each)."""
        self.by_namespace[namespace].update(names)

    def defines(self, namespace: str, name: str) -> bool:
        return name in self.by_namespace.get(namespace, ())


class References:
    """How one file (in ``namespace``) names each class it uses, and the usings it needs.

    A class in the file's namespace or an enclosing one is named simply; one elsewhere gets a
    using, unless its simple name is ambiguous there, or ``qualified`` asks for ``global::``.
    """

    def __init__(
        self, namespace: str, known: KnownClasses, wanted: Iterable[tuple[CsClass, bool]]
    ) -> None:
        self.namespace = namespace
        # Keyed by (namespace, name, qualified): tuples of strings hash and sort in C, a
        # CsClass through its generated methods. The order is CsClass's own.
        classes = {(cls.namespace, cls.name, qualified): cls for cls, qualified in wanted}
        keys = sorted(classes)
        scope = {namespace} | {
            ns for ns, _, qualified in keys if not qualified and not self._sees(ns)
        }
        self._names: dict[tuple[str, str, bool], str] = {}
        usings: set[str] = set()
        for key in keys:
            cls_namespace, name, qualified = key
            clash = any(known.defines(other, name) for other in scope if other != cls_namespace)
            if qualified or (clash and cls_namespace != namespace):
                self._names[key] = classes[key].qualified
            else:
                self._names[key] = name
                if not self._sees(cls_namespace):
                    usings.add(cls_namespace)
        self.usings: tuple[str, ...] = tuple(sorted(usings))

    def _sees(self, namespace: str) -> bool:
        """Whether classes of ``namespace`` are found by name from the file's namespace
        without a using."""
        return self.namespace == namespace or self.namespace.startswith(namespace + ".")

    def name(self, cls: CsClass, *, qualified: bool = False) -> str:
        return self._names[(cls.namespace, cls.name, qualified)]
