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
        # CsClass's own ordering, by a key: its generated comparison methods are slow
        wanted = sorted(set(wanted), key=lambda w: (w[0].namespace, w[0].name, w[1]))
        imported = {c.namespace for c, q in wanted if not q and not self._visible(c)}
        self._names: dict[tuple[CsClass, bool], str] = {}
        usings: set[str] = set()
        for cls, qualified in wanted:
            clash = any(
                known.defines(other, cls.name)
                for other in ({namespace} | imported) - {cls.namespace}
            )
            if qualified or (clash and cls.namespace != namespace):
                self._names[(cls, qualified)] = cls.qualified
            else:
                self._names[(cls, qualified)] = cls.name
                if not self._visible(cls):
                    usings.add(cls.namespace)
        self.usings: tuple[str, ...] = tuple(sorted(usings))

    def _visible(self, cls: CsClass) -> bool:
        """Whether ``cls`` is found by name from the file's namespace without a using."""
        return self.namespace == cls.namespace or self.namespace.startswith(cls.namespace + ".")

    def name(self, cls: CsClass, *, qualified: bool = False) -> str:
        return self._names[(cls, qualified)]
