"""Which script a ``components:`` entry's ``script:`` names, one way (docs/manifest.md,
"Which script a name means"):

- a path ending in ``.cs`` names that file, and the class Unity binds it to;
- a qualified name (``UnityEngine.UI.Image``) names the class with that full name;
- a bare class name (``Image``) is looked for among components only, in every place at once:
  the scripts this manifest generates, the project's own scripts (``Assets/``, embedded packages
  under ``Packages/``), ROS#'s release (its catalog) and uGUI's table. One candidate is the
  answer; two or more are an error listing each with its full name and where it comes from.

Unity's ``Library/`` is never read: what Unity installs there is known from the catalogs.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from unityscaffold.unity import ScriptRef
from unityscaffold.unity.behaviours import Kind, UnityClass, kind_of, unity_class
from unityscaffold.unity.catalog import rossharp_catalog
from unityscaffold.unity.csharp import SourceError, TypeDecl, parse_file
from unityscaffold.unity.project import ScriptInfo
from unityscaffold.unity.ugui import UGUI_SCRIPTS, ugui_script

__all__ = ["Candidate", "ProjectClasses", "named_candidates"]


@dataclass(frozen=True, slots=True)
class Candidate:
    """A component a name may mean: its reference, full C# name, and where it comes from."""

    ref: ScriptRef
    full_name: str
    origin: str


@dataclass(slots=True)
class ProjectClasses:
    """The project's own scripts read as Unity reads them (each file once per run)."""

    root: Path
    scripts: dict[str, ScriptInfo]  # GUID -> the project's scripts (not ROS#'s, not generated)
    _decls: dict[str, list[TypeDecl] | None] = field(default_factory=dict)
    _texts: dict[str, str | None] = field(default_factory=dict)
    _kinds: dict[str, Kind | None] = field(default_factory=dict)

    def _text(self, info: ScriptInfo) -> str | None:
        if info.guid not in self._texts:
            try:
                data = (self.root / info.path).read_bytes()
                self._texts[info.guid] = data.decode("utf-8-sig", errors="replace")
            except OSError:
                self._texts[info.guid] = None
        return self._texts[info.guid]

    def decls(self, info: ScriptInfo) -> list[TypeDecl] | None:
        """The file's declarations; None when it cannot be read."""
        if info.guid not in self._decls:
            text = self._text(info)
            try:
                self._decls[info.guid] = None if text is None else parse_file(text, info.path)
            except (SourceError, ValueError, IndexError):
                self._decls[info.guid] = None
        return self._decls[info.guid]

    def unity_class(self, info: ScriptInfo) -> UnityClass | None:
        """The class Unity binds the file to (None when the file cannot be read)."""
        decls = self.decls(info)
        return None if decls is None else unity_class(decls, info.class_name, self.kind)

    def kind(self, class_name: str) -> Kind | None:
        """The kind of a base class the project or ROS# declares (None: neither does)."""
        if class_name not in self._kinds:
            self._kinds[class_name] = Kind.UNKNOWN  # a class deriving from itself stops here
            self._kinds[class_name] = self._declared_kind(class_name)
        return self._kinds[class_name]

    def _declared_kind(self, class_name: str) -> Kind | None:
        for info in self.scripts.values():
            if info.class_name == class_name:
                decl = next((d for d in self.decls(info) or [] if d.name == class_name), None)
                if decl is not None:
                    return kind_of(decl, self.kind)
        rossharp = rossharp_catalog().named(class_name)
        if rossharp is not None:
            return Kind.COMPONENT if rossharp.bases[-1:] == ("MonoBehaviour",) else Kind.OTHER
        return None

    def declaring(self, class_name: str) -> list[tuple[ScriptInfo, TypeDecl, Kind]]:
        """Every file Unity binds to a class named ``class_name``, with that class's kind."""
        pattern = re.compile(rf"\bclass\s+{re.escape(class_name)}\b")
        found = []
        for info in sorted(self.scripts.values(), key=lambda i: i.path):
            if info.class_name != class_name and not pattern.search(self._text(info) or ""):
                continue
            chosen = self.unity_class(info)
            if chosen is None:  # unreadable: known by its file name only, as Unity would
                if info.class_name == class_name:
                    found.append((info, _unread(info), Kind.UNKNOWN))
            elif chosen.decl is not None and chosen.decl.name == class_name:
                found.append((info, chosen.decl, kind_of(chosen.decl, self.kind)))
        return found


def _unread(info: ScriptInfo) -> TypeDecl:
    return TypeDecl("class", info.class_name, "", (), info.path)


def named_candidates(
    name: str,
    generated: list[Candidate],
    project: ProjectClasses,
    rossharp: list[Candidate],
) -> list[Candidate]:
    """Every component ``name`` (bare or qualified) may mean, in the documented order."""
    namespace, _, bare = name.rpartition(".")
    found = [c for c in generated if c.ref.class_name == bare]
    for info, decl, kind in project.declaring(bare):
        if kind is not Kind.OTHER:
            ref = ScriptRef(info.guid, class_name=decl.name, namespace=decl.namespace)
            found.append(Candidate(ref, decl.full_name, info.path))
    found += [c for c in rossharp if c.ref.class_name == bare]
    ugui = ugui_script(bare)
    if ugui is not None:
        label = f"uGUI (com.unity.ugui), {UGUI_SCRIPTS[bare][0]}"
        found.append(Candidate(ugui, f"{ugui.namespace}.{bare}", label))
    if namespace:
        found = [c for c in found if c.full_name == name]
    return found
