"""Which fileID each slot of a robot's import gets: the same one on every run for what the URDF
still has, a new one for what it gains.

A slot is an object of the import and a role on it (``("link[2]/visual[0]", "UrdfVisual#0")``,
the key telling the URDF element by position, as ``urdf.objects`` builds it). Positions shift
when a link is inserted, removed or reordered, so a slot is known across runs by its
*identity*: the key with its link told by name (``link "arm"/visual[0]``), a link's name being
unique in its robot. A new slot's fileID derives from its identity
(``candidate_file_ids(("robot", <robot path>, <identity>, <role>))``): a link keeps its
objects, components and children wherever the URDF moves it, and a link renamed is another
link.

Some fileIDs cannot be derived: those taken over from a robot imported by hand (``_adopt``),
and those of a robot an earlier version of this tool imported, which derived them from the
key itself. Both are *kept*: the lock records them by identity and role
(``LockRobot.adopted``), and every run takes them again while the scene holds them. A robot
of the earlier scheme is read against the URDF as it is now (the first apply after the
upgrade is expected to follow an unchanged URDF): a slot whose derived fileID the robot never
had, but whose fileID by key it has, keeps that one.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field

from unityscaffold.unity.owned import owned_file_id
from unityscaffold.urdf.objects import ImportedObject, Role

__all__ = ["Slots"]

Slot = tuple[str, str]  # (the object's key, the role)


@dataclass(slots=True)
class Slots:
    """The fileIDs of one robot's slots for one run. ``before``: every fileID the lock has
    for the robot; ``kept``: the lock's kept fileIDs by ``"<identity> <role>"`` (or, from an
    earlier version, ``"<key> <role>"``). Not frozen, unlike the model's values: it is the
    run's ledger, ``ids``, ``used`` and ``taken`` filled as slots are asked for, so that no
    two slots get one fileID."""

    robot: str  # the robot's GameObject path
    links: Mapping[str, str]  # a link's key -> its identity
    class_of: Callable[[int], int | None]
    before: frozenset[int] = frozenset()
    kept: Mapping[str, int] = field(default_factory=dict)
    ids: dict[Slot, int] = field(default_factory=dict)
    used: set[int] = field(default_factory=set)
    taken: dict[Slot, int] = field(default_factory=dict)  # slots whose fileID is kept
    kept_ids: frozenset[int] = field(init=False)

    def __post_init__(self) -> None:
        self.kept_ids = frozenset(self.kept.values())

    @classmethod
    def of(
        cls,
        robot: str,
        root: ImportedObject,
        class_of: Callable[[int], int | None],
        before: Iterable[int] = (),
        kept: Mapping[str, int] | None = None,
    ) -> Slots:
        links = {
            obj.key: f"link {json.dumps(obj.name, ensure_ascii=False)}"
            for _, obj in root.walk()
            if obj.role is Role.LINK
        }
        return cls(robot, links, class_of, frozenset(before), dict(kept or {}))

    def identity(self, key: str) -> str:
        """``link[2]/visual[0]`` -> ``link "arm"/visual[0]``; keys outside links are their own."""
        head, sep, rest = key.partition("/")
        return self.links.get(head, head) + sep + rest

    def take(self, slots: Mapping[Slot, int]) -> None:
        """Slots whose fileIDs come from a robot imported by hand (see ``_adopt``)."""
        self.taken.update(slots)
        self.ids.update(slots)
        self.used.update(slots.values())

    def file_id(self, key: str, role: str, class_id: int) -> int:
        slot = (key, role)
        if slot not in self.ids:
            self.ids[slot] = self._pick(key, role, class_id)
        return self.ids[slot]

    def recorded(self) -> tuple[tuple[str, int], ...]:
        """The kept slots this run used, as the lock records them."""
        return tuple(
            sorted(
                (f"{self.identity(key)} {role}", i)
                for (key, role), i in self.taken.items()
                if i in self.used
            )
        )

    def _pick(self, key: str, role: str, class_id: int) -> int:
        identity = self.identity(key)
        # the earlier scheme's role had no joint type (``HingeJoint#0``)
        former = role.partition(" of ")[0]
        kept = self.kept.get(f"{identity} {role}", self.kept.get(f"{key} {former}"))
        if kept is not None and kept not in self.used and self.class_of(kept) == class_id:
            return self._keep((key, role), kept)
        derived = self._first(("robot", self.robot, identity, role), class_id)
        if self.before and derived not in self.before and key != identity:
            # a robot of the earlier scheme, whose fileIDs derived from the key itself
            earlier = self._first(("robot", self.robot, key, former), class_id)
            if earlier in self.before and earlier not in self.kept_ids:
                return self._keep((key, role), earlier)
        self.used.add(derived)
        return derived

    def _keep(self, slot: Slot, file_id: int) -> int:
        self.taken[slot] = file_id
        self.used.add(file_id)
        return file_id

    def _first(self, parts: tuple[str, ...], class_id: int) -> int:
        """The fileID ``owned_file_id`` would give ``parts`` now, without taking it."""
        found = owned_file_id(parts, class_id, self.class_of, self.used)
        self.used.discard(found)  # it was not in ``used``: owned_file_id passes those by
        return found
