"""What each script a manifest names declares, wherever it comes from: ROS#'s from the catalog,
uGUI's from its table, the project's own from their ``.cs`` (read once per run), generated ones
not at all (apply writes their fields itself)."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from unityscaffold.apply._rossharp import RosSharp
from unityscaffold.unity.catalog import CatalogScript, rossharp_catalog
from unityscaffold.unity.project import ScriptInfo
from unityscaffold.unity.scriptfacts import ProjectFacts, read_script_facts
from unityscaffold.unity.ugui import ugui_class
from unityscaffold.unity.ugui_fields import UguiClass, ugui_enums, ugui_fields
from unityscaffold.unity.values import FieldValue, Verbatim

__all__ = ["NewFields", "ScriptFacts"]


@dataclass(frozen=True, slots=True)
class NewFields:
    """What a new component of a script is written with: its serialized fields in order, at
    the values Unity gives a new one, and those whose initial value apply cannot work out from
    the C# source (Unity writes them on its next save)."""

    values: tuple[tuple[str, FieldValue | Verbatim], ...] = ()
    unfilled: tuple[str, ...] = ()
    # laid out as Unity 2022.3 writes them: a file an older Unity wrote gets only the entry's
    # fields (its uGUI has fewer), which that Unity completes
    since_2022: bool = False


@dataclass(slots=True)
class ScriptFacts:
    root: Path
    rossharp: RosSharp
    scripts: dict[str, ScriptInfo]  # GUID -> the project's scripts
    rossharp_names: dict[str, str]  # GUID -> class of ROS#'s scripts
    generated: frozenset[str] = frozenset()  # classes this plan generates (maybe not on disk yet)
    enums: dict[str, dict[str, int]] = field(default_factory=dict)
    _read: dict[str, ProjectFacts | None] = field(default_factory=dict)
    _by_name: dict[str, list[ScriptInfo]] = field(default_factory=dict)

    def __post_init__(self) -> None:
        self.enums.update(rossharp_catalog().enums)
        self.enums.update(ugui_enums())
        for info in self.scripts.values():
            if info.guid not in self.rossharp_names:
                self._by_name.setdefault(info.class_name, []).append(info)

    def of(self, guid: str) -> CatalogScript | None:
        """The facts of the script with ``guid`` (None for a generated or unreadable one)."""
        name = self.rossharp_names.get(guid)
        if name is not None:
            return self.rossharp.facts(name)
        info = self.scripts.get(guid)
        if info is None:
            ugui = _ugui(guid)
            return ugui.script if ugui is not None else None
        found = self._project(info)
        return found.script if found is not None else None

    def defaults(self, guid: str) -> NewFields:
        """Every field Unity serializes for the script with ``guid``, in order, at the value
        a new component starts with (none for a script without facts)."""
        if guid not in self.rossharp_names and guid not in self.scripts:
            ugui = _ugui(guid)
            return NewFields(ugui.defaults, since_2022=True) if ugui is not None else NewFields()
        facts = self.of(guid)
        if facts is None:
            return NewFields()
        return NewFields(
            tuple(
                (f.name, Verbatim(f"  {f.name}:{f.default}"))
                for f in facts.fields
                if f.default is not None
            ),
            tuple(f.name for f in facts.fields if f.default is None),
        )

    def _project(self, info: ScriptInfo) -> ProjectFacts | None:
        if info.guid not in self._read:
            self._read[info.guid] = None  # a class deriving from itself stops here
            found = read_script_facts(
                self.root / info.path, info.class_name, self._named, self._is_script
            )
            if found is not None:
                self.enums.update(found.enums)
            self._read[info.guid] = found
        return self._read[info.guid]

    def _named(self, class_name: str) -> ProjectFacts | CatalogScript | None:
        """A base class: the project's script of that name if there is exactly one, else ROS#'s."""
        infos = self._by_name.get(class_name, [])
        if len(infos) == 1:
            return self._project(infos[0])
        return rossharp_catalog().named(class_name)

    def _is_script(self, class_name: str) -> bool:
        # Generated classes count from the first run on, before their files exist, so that a
        # field of that type resolves the same way on every run.
        return (
            class_name in self.generated
            or class_name in self._by_name
            or rossharp_catalog().named(class_name) is not None
        )


def _ugui(guid: str) -> UguiClass | None:
    """uGUI's script with ``guid`` (its GUID is the same in every project), or None."""
    name = ugui_class(guid)
    return ugui_fields(name) if name is not None else None
