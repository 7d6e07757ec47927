"""All interface types of one dialect: lookup by name, dependency closure, diagnostics.

Files are indexed up front (a directory listing) and parsed on first use, so looking up one
type does not parse every package on the machine.
"""

from __future__ import annotations

import difflib
from collections.abc import Callable, Iterable, Mapping, Sequence
from pathlib import Path
from typing import NamedTuple

from unityscaffold.errors import Diagnostic, LocatedError, SourceLocation, UserError
from unityscaffold.interfaces import ros1, ros2
from unityscaffold.interfaces.model import (
    ActionSpec,
    Dialect,
    Field,
    Interface,
    InterfaceKind,
    MessageSpec,
    ServiceSpec,
)
from unityscaffold.interfaces.sources import InterfaceFile, SearchRoot, find_packages, search_roots
from unityscaffold.interfaces.suffixes import (
    ROS1_PART_SUFFIXES,
    ROS2_GET_RESULT,
    ROS2_REQUEST,
    ROS2_RESPONSE,
    ROS2_SEND_GOAL,
)

__all__ = ["Registry", "TypeNotFound"]

# text, package, name, path -> the parsed interface
_Parser = Callable[[str, str, str, str], Interface]
_PARSERS: dict[Dialect, dict[InterfaceKind, _Parser]] = {
    Dialect.ROS1: {
        InterfaceKind.MSG: ros1.parse_message,
        InterfaceKind.SRV: ros1.parse_service,
        InterfaceKind.ACTION: ros1.parse_action,
    },
    Dialect.ROS2: {
        InterfaceKind.MSG: ros2.parse_message,
        InterfaceKind.SRV: ros2.parse_service,
        InterfaceKind.ACTION: ros2.parse_action,
    },
}


def _read_text(path: Path) -> str:
    """The file's text exactly as ``read_text(encoding="utf-8")`` gives it, newlines translated.

    Reading bytes and decoding them in one call skips the text-mode reader, which cost more
    than reading a small interface file. Text that is not UTF-8 raises ``UnicodeDecodeError``,
    whose ``object`` is the file's content.
    """
    with open(path, "rb", buffering=0) as handle:  # no buffered reader for one read
        data = handle.readall()
    text = data.decode("utf-8")
    return text.replace("\r\n", "\n").replace("\r", "\n") if "\r" in text else text


class TypeNotFound(UserError):
    """A type name that no search root defines; ``advice`` is the hint without where the
    search looked (so several can share that)."""

    def __init__(self, message: str, *, hint: str | None = None, advice: str = "") -> None:
        super().__init__(message, hint=hint)
        self.advice = advice


class _Key(NamedTuple):  # a tuple hashes in C: the registry's dicts are hit per field
    kind: InterfaceKind
    package: str
    name: str


class Registry:
    """The interface types visible to one dialect, first definition winning."""

    def __init__(self, dialect: Dialect, roots: Sequence[SearchRoot]) -> None:
        self.dialect = dialect
        self.roots = list(roots)
        self._files: dict[_Key, InterfaceFile] = {}
        self._shadowed: dict[_Key, list[InterfaceFile]] = {}
        self._parsed: dict[Path, Interface] = {}
        self._broken: dict[Path, LocatedError] = {}
        # find's answers by name: generation asks for the same field types thousands of times
        self._found: dict[str, Interface | None] = {}
        for package in find_packages(self.roots):
            for file in package.files():
                key = _Key(file.kind, file.package, file.name)
                if key in self._files:
                    self._shadowed.setdefault(key, []).append(file)
                else:
                    self._files[key] = file

    @classmethod
    def load(
        cls,
        dialect: Dialect,
        paths: Sequence[Path | str] = (),
        *,
        environ: Mapping[str, str] | None = None,
        use_environment: bool = True,
        use_builtin: bool = True,
    ) -> Registry:
        """Index every package visible for ``dialect``, user ``paths`` first."""
        missing = [str(p) for p in paths if not Path(p).is_dir()]
        if missing:
            raise UserError(
                f"interface folder not found: {', '.join(missing)}",
                hint="pass folders that contain ROS packages (with msg/, srv/ or action/)",
            )
        roots = search_roots(
            dialect,
            paths,
            environ=environ,
            use_environment=use_environment,
            use_builtin=use_builtin,
        )
        return cls(dialect, roots)

    # --- files ----------------------------------------------------------------------------

    def files(self) -> list[InterfaceFile]:
        """Every winning interface file, sorted by package, kind and name."""
        return sorted(self._files.values(), key=lambda f: (f.package, f.kind.value, f.name))

    def packages(self) -> list[str]:
        return sorted({key.package for key in self._files})

    def file_of(self, interface: Interface) -> InterfaceFile | None:
        """The file that defines ``interface`` (for a service half: the service's file)."""
        owner = interface.owner if isinstance(interface, MessageSpec) and interface.owner else None
        if owner is not None:
            if self.dialect is Dialect.ROS1:  # pkg/Name: the kind is the part's subfolder
                package, name = owner.split("/")
                owner = f"{package}/{interface.subfolder}/{name}"
            found = self.find(owner)
            if found is not None and found is not interface:
                return self.file_of(found)
        return self._files.get(_Key(interface.kind, interface.package, interface.name))

    def shadowed(self, interface: Interface) -> list[InterfaceFile]:
        """Files that define the same type but lost to ``interface``'s file."""
        return list(self._shadowed.get(_Key(interface.kind, interface.package, interface.name), []))

    def parse(self, file: InterfaceFile) -> Interface:
        """Parse one file (once); raises ``LocatedError`` when it is malformed."""
        if file.path in self._parsed:
            return self._parsed[file.path]
        if file.path in self._broken:
            raise self._broken[file.path]
        try:
            text = _read_text(file.path)
        except OSError as exc:
            error = LocatedError.at(
                SourceLocation(str(file.path)), f"cannot read: {exc.strerror or exc}"
            )
            self._broken[file.path] = error
            raise error from None
        except UnicodeDecodeError as exc:
            error = LocatedError.at(
                SourceLocation.at_byte(str(file.path), exc.object, exc.start),
                f"the file is not UTF-8 text (byte 0x{exc.object[exc.start]:02x})",
                hint="save it as UTF-8",
            )
            self._broken[file.path] = error
            raise error from None
        try:
            parsed = _PARSERS[self.dialect][file.kind](
                text, file.package, file.name, str(file.path)
            )
        except LocatedError as error:
            self._broken[file.path] = error
            raise
        self._parsed[file.path] = parsed
        return parsed

    def parse_all(self) -> tuple[list[Interface], list[Diagnostic]]:
        """Every type that parses, and the diagnostics of the files that do not."""
        good: list[Interface] = []
        problems: list[Diagnostic] = []
        for file in self.files():
            try:
                good.append(self.parse(file))
            except LocatedError as error:
                problems.extend(error.diagnostics)
        return good, problems

    # --- lookup ---------------------------------------------------------------------------

    def _file(self, kind: InterfaceKind, package: str, name: str) -> InterfaceFile | None:
        return self._files.get(_Key(kind, package, name))

    def find(self, name: str) -> Interface | None:
        """The message, service or action called ``name``, in any form users type.

        ``pkg/kind/Name`` names one file. ``pkg/Name`` names the one message, service or action
        of that name, except that in ROS 1 a message or service wins over an action (as
        ``rosmsg`` and ``rossrv`` read names: there an action is not a type, its messages
        ``pkg/NameGoal``, … are), so ``nav_msgs/GetMap`` is the service.
        """
        if name in self._found:
            return self._found[name]
        found = self._find(name)
        self._found[name] = found  # not reached when it raises: errors are raised every time
        return found

    def _find(self, name: str) -> Interface | None:
        parts = name.strip().split("/")
        if len(parts) == 3 and parts[1] in {k.value for k in InterfaceKind}:
            package, kind, short = parts[0], InterfaceKind(parts[1]), parts[2]
            if self.dialect is Dialect.ROS2:
                return self._find_ros2(package, kind, short)
            return self._find_in(package, short, (kind,))
        if len(parts) != 2 or not all(parts):
            return None
        kinds = self._short_form_kinds(*parts)
        if len(kinds) > 1:
            spelled = " or ".join(f"{parts[0]}/{k.value}/{parts[1]}" for k in kinds)
            raise UserError(
                f"'{name}' names both a {' and a '.join(k.value for k in kinds)}",
                hint=f"write {spelled}",
            )
        return self._find_in(parts[0], parts[1], kinds or ())

    def _find_in(
        self, package: str, short: str, kinds: Iterable[InterfaceKind]
    ) -> Interface | None:
        for kind in kinds:
            file = self._file(kind, package, short)
            if file is not None:
                return self.parse(file)
        return self._find_part(package, short)

    def _find_ros2(self, package: str, kind: InterfaceKind, short: str) -> Interface | None:
        file = self._file(kind, package, short)
        if file is not None:
            return self.parse(file)
        if kind is InterfaceKind.MSG:
            return None
        owner_name = short.rsplit("_", 1)[0]
        for candidate in (owner_name, owner_name.rsplit("_", 1)[0]):
            owner_file = self._file(kind, package, candidate)
            if owner_file is not None:
                owner = self.parse(owner_file)
                return _part_named(owner, short)
        return None

    def _find_part(self, package: str, short: str) -> MessageSpec | None:
        """A ROS 1 service half or action message, such as ``AddTwoIntsRequest``."""
        if self.dialect is not Dialect.ROS1:
            return None
        for kind, suffix in ROS1_PART_SUFFIXES:
            if short.endswith(suffix) and len(short) > len(suffix):
                file = self._file(kind, package, short[: -len(suffix)])
                if file is not None:
                    return _part_named(self.parse(file), short)
        return None

    def get(
        self,
        name: str,
        *,
        used_at: SourceLocation | None = None,
        kinds: tuple[InterfaceKind, ...] = (),
    ) -> Interface:
        """Like ``find``, but an unknown name raises ``TypeNotFound`` with suggestions (of
        ``kinds`` only, when given: where only an action fits, a message is no suggestion)."""
        found = self.find(name)
        if found is None:
            raise self._not_found(name, used_at, kinds=kinds)
        return found

    def message(self, full_name: str, *, used_at: SourceLocation | None = None) -> MessageSpec:
        """The message with this full name (as field types store it)."""
        found = self.get(full_name, used_at=used_at)
        if not isinstance(found, MessageSpec):
            raise self._not_found(
                full_name, used_at, note=f"'{full_name}' is a {found.kind.value}, not a message"
            )
        return found

    def known_names(self) -> list[str]:
        """Every type's name in a form ``find`` resolves to it (and to nothing else)."""
        return sorted(self._spelled(key) for key in self._files)

    def _spelled(self, key: _Key) -> str:
        short = f"{key.package}/{key.name}"
        if self.dialect is Dialect.ROS2:
            return f"{key.package}/{key.kind.value}/{key.name}"
        if self._short_form_kinds(key.package, key.name) != [key.kind]:
            return f"{key.package}/{key.kind.value}/{key.name}"
        return short

    def _short_form_kinds(self, package: str, name: str) -> list[InterfaceKind]:
        """The kinds ``pkg/Name`` may mean (``find``): one, or several when it is ambiguous."""
        kinds = [k for k in InterfaceKind if self._file(k, package, name) is not None]
        if self.dialect is Dialect.ROS1 and len(kinds) > 1:
            kinds = [k for k in kinds if k is not InterfaceKind.ACTION]
        return kinds

    def suggestions(self, name: str, kinds: tuple[InterfaceKind, ...] = ()) -> list[str]:
        """Known names close to ``name`` (of ``kinds`` when given): its own package's first."""
        parts = name.strip().split("/")
        package, short = parts[0], parts[-1]
        keys = [k for k in self._files if not kinds or k.kind in kinds]
        own = [k for k in keys if k.package == package]
        close = difflib.get_close_matches(short, sorted({k.name for k in own}), n=3, cutoff=0.6)
        found = [self._spelled(k) for c in close for k in sorted(own, key=str) if k.name == c]
        names = sorted(self._spelled(k) for k in keys) if kinds else self.known_names()
        others = difflib.get_close_matches(name, names, n=3, cutoff=0.6)
        return list(dict.fromkeys([*found, *others]))[:3]

    def looked_in(self) -> str:
        return ", ".join(f"{r.path} ({r.origin})" for r in self.roots)

    def _not_found(
        self,
        name: str,
        used_at: SourceLocation | None,
        note: str = "",
        kinds: tuple[InterfaceKind, ...] = (),
    ) -> UserError:
        parts = name.strip().split("/")
        owner = None if note else self._derived_service_owner(parts)
        if owner is not None:
            return self._derived_service(name, owner, used_at)
        message = note or f"unknown {self.dialect.label} type '{name}'"
        advice = ""
        looked = f"looked in: {self.looked_in()}"
        if not note and len(parts) in (2, 3) and parts[0] not in self.packages():
            message += f": no package '{parts[0]}' was found"
            packages = difflib.get_close_matches(parts[0], self.packages(), n=3, cutoff=0.85)
            advice = f"did you mean package {' or '.join(packages)}?" if packages else ""
            looked = f"packages are looked for in: {self.looked_in()}"
        else:
            close = self.suggestions(name, kinds)
            advice = f"did you mean {' or '.join(close)}?" if close else ""
        hint = f"{advice} {looked}" if advice else looked
        if used_at is not None:
            return LocatedError.at(used_at, message, hint=hint)
        return TypeNotFound(message, hint=hint, advice=advice)

    def _derived_service_owner(self, parts: list[str]) -> str | None:
        """The action (``pkg/action/X``) whose ``X_SendGoal`` or ``X_GetResult`` ROS 2
        service ``parts`` names (as ``pkg/X_SendGoal`` or ``pkg/action/X_SendGoal``), if any."""
        if self.dialect is not Dialect.ROS2 or len(parts) not in (2, 3):
            return None
        if len(parts) == 3 and parts[1] != InterfaceKind.ACTION.value:
            return None
        for suffix in (ROS2_SEND_GOAL, ROS2_GET_RESULT):
            short = parts[-1].removesuffix(suffix)
            if short != parts[-1] and self._file(InterfaceKind.ACTION, parts[0], short):
                return f"{parts[0]}/action/{short}"
        return None

    def _derived_service(self, name: str, owner: str, used_at: SourceLocation | None) -> UserError:
        """rosidl makes ``X_SendGoal`` and ``X_GetResult`` from the ``.action`` file: there is
        no text to show, and no entry but the action's own can use them."""
        spelled = f"{owner}{name.strip().split('/')[-1].removeprefix(owner.split('/')[-1])}"
        message = (
            f"'{name}' is a service rosidl derives from the action {owner}; it has no "
            "definition of its own"
        )
        advice = (
            f"show the action: scaffold msgs show {owner}; the service's messages are "
            f"{spelled}{ROS2_REQUEST} and {spelled}{ROS2_RESPONSE}"
        )
        if used_at is not None:
            return LocatedError.at(used_at, message, hint=advice)
        return TypeNotFound(message, hint=advice, advice=advice)

    def get_all(self, names: Iterable[str]) -> list[Interface]:
        """``get`` for each name; unknown names are all reported in one error."""
        found: list[Interface] = []
        missing: list[TypeNotFound] = []
        for name in names:
            try:
                found.append(self.get(name))
            except TypeNotFound as error:
                missing.append(error)
        if len(missing) == 1:
            raise missing[0]
        if missing:
            lines = [f"{len(missing)} types are unknown:"]
            for unknown in missing:
                lines.append(f"  {unknown.message}")
                if unknown.advice:
                    lines.append(f"    {unknown.advice}")
            raise TypeNotFound("\n".join(lines), hint=f"looked in: {self.looked_in()}")
        return found

    # --- dependencies ---------------------------------------------------------------------

    def field_type(self, owner: MessageSpec, field: Field) -> MessageSpec:
        """The message a field of ``owner`` refers to."""
        return self.message(field.type.base, used_at=field.location)

    def closure(self, roots: Iterable[Interface]) -> list[MessageSpec]:
        """Every message the roots define or use, directly or not, sorted by full name.

        Unknown types and cycles are all reported at once, each at the field that uses them.
        """
        found: dict[str, MessageSpec] = {}
        problems: list[Diagnostic] = []
        for root in roots:
            for message in _messages_of(root):
                self._visit(message, found, [], problems)
        if problems:
            raise LocatedError(_unique(problems))
        return [found[name] for name in sorted(found)]

    def _visit(
        self,
        message: MessageSpec,
        found: dict[str, MessageSpec],
        path: list[str],
        problems: list[Diagnostic],
        used_at: SourceLocation | str | None = None,  # the field using it, or its file
    ) -> None:
        if message.full_name in found:
            return
        if message.full_name in path:
            cycle = " -> ".join([*path[path.index(message.full_name) :], message.full_name])
            # at the field that closes the cycle
            where = (
                used_at
                if isinstance(used_at, SourceLocation)
                else SourceLocation(used_at or message.source or message.full_name)
            )
            problems.append(
                Diagnostic(
                    where,
                    f"types refer to each other in a cycle: {cycle}",
                    hint="ROS messages cannot contain themselves",
                )
            )
            return
        path.append(message.full_name)
        for field in message.fields:
            if not field.type.is_message:
                continue
            try:
                dependency = self.field_type(message, field)
            except LocatedError as error:
                problems.extend(error.diagnostics)
                continue
            except UserError as error:
                # placed only when it fails (as located_at would): this runs for every field
                where = field.location or SourceLocation(message.source or message.full_name)
                problems.extend(LocatedError.at(where, error.message, hint=error.hint).diagnostics)
                continue
            # where the field is, for a cycle it closes (only then is it worked out)
            self._visit(dependency, found, path, problems, field.location or message.source)
        path.pop()
        found[message.full_name] = message


def _messages_of(interface: Interface) -> tuple[MessageSpec, ...]:
    if isinstance(interface, MessageSpec):
        return (interface,)
    if isinstance(interface, ServiceSpec):
        return interface.parts
    return interface.messages


def _part_named(owner: Interface, name: str) -> MessageSpec | None:
    if isinstance(owner, ServiceSpec | ActionSpec):
        for part in _messages_of(owner):
            if part.name == name:
                return part
    return None


def _unique(problems: list[Diagnostic]) -> list[Diagnostic]:
    return list(dict.fromkeys(problems))
