"""Expanding a ``.xacro`` robot into URDF bytes, in process, with PyPI's optional ``xacro``.

Determinism: ``$(find pkg)`` resolves only through the manifest entry's ``packages`` (never an
ament index or ROS_PACKAGE_PATH of the machine); ``$(env VAR)`` and ``$(optenv VAR default)``
read the entry's ``env`` and never the machine's environment (``$(optenv)`` of a variable the
entry leaves out is its default, or the empty string, as xacro gives it for an unset variable;
``$(env)`` of one is refused, as xacro refuses it); ``$(cwd)`` (the folder apply runs in) is
refused. So the URDF depends only on files in the repository and the entry's ``args`` and
``env``. xacro opens every file it reads with ``open``, which apply's no-op record observes like
any other read.

xacro prints its warnings to stderr; they are caught and returned with the file xacro was
reading, for apply to report as notes like its own.

xacro keeps its state in module globals (the ``find`` function, the file stack); they are
swapped in and restored around one expansion, which is why this is the one module that knows
xacro's internals.
"""

from __future__ import annotations

import contextlib
import io
import re
import xml.parsers.expat
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, NoReturn
from xml.sax.saxutils import escape

from unityscaffold.errors import LocatedError, SourceLocation, UserError

__all__ = ["Expanded", "expand_xacro", "is_xacro"]

_INSTALL = "install the extra that reads them: pip install 'unityscaffold[xacro]'"


class _Refused(Exception):
    """A substitution the project does not allow: its message and hint are the user's error,
    and ``pattern`` finds the substitution in the file xacro was reading (to give its line)."""

    def __init__(self, message: str, hint: str, pattern: str) -> None:
        super().__init__(message)
        self.hint = hint
        self.pattern = pattern


@dataclass(frozen=True, slots=True)
class Expanded:
    """A xacro file's URDF, and xacro's warnings (``<file>: xacro warns: <text>``)."""

    urdf: bytes
    warnings: tuple[str, ...] = ()


def is_xacro(path: Path) -> bool:
    return path.suffix == ".xacro"


def expand_xacro(
    path: Path,
    *,
    packages: Mapping[str, Path],
    args: Mapping[str, str],
    env: Mapping[str, str] | None = None,
) -> Expanded:
    """The URDF that ``path`` expands to with ``args`` and the variables ``env`` gives
    ``$(env)`` and ``$(optenv)``, with xacro's warnings; a xacro error names the file it is in
    (and the line, for XML errors and refused substitutions), and nothing else of the machine
    is read."""
    try:
        import xacro
        from xacro import substitution_args
    except ImportError:
        raise UserError(
            f"{path} is a xacro file, and the xacro package is not installed", hint=_INSTALL
        ) from None
    warnings: list[str] = []
    stray = io.StringIO()
    hooks = _Hooks(packages, env or {})
    with _hooked(xacro, substitution_args, hooks, warnings), contextlib.redirect_stderr(stray):
        try:
            document = xacro.process_file(str(path), mappings=dict(args), verbosity=0)
        except (Exception, RecursionError) as error:  # xacro raises what it meets
            _raise_located(path, list(xacro.filestack or [str(path)]), error)
        finally:
            xacro.all_includes.clear()  # grows across runs otherwise
    warnings += [f"{path}: xacro says: {line}" for line in _stray_lines(stray.getvalue())]
    # laid out as the xacro command prints it, so a URDF error's line is that output's line
    urdf = bytes(document.toprettyxml(indent="  ", encoding="utf-8"))
    return Expanded(hooks.unfound(urdf), tuple(dict.fromkeys(warnings)))


# What xacro prints after a warning to say where it was: the warning has its file already
_LOCATION_LINES = (
    "when processing file:",
    "included from:",
    "when instantiating macro:",
    "instantiated from:",
    "in file:",
)


def _stray_lines(text: str) -> list[str]:
    """What xacro printed besides its warnings (none today, but a release may add some)."""
    return [
        line.strip()
        for line in text.splitlines()
        if line.strip() and not line.strip().startswith(_LOCATION_LINES)
    ]


@dataclass(frozen=True, slots=True)
class _Hooks:
    """What ``$(find)``, ``$(env)`` and ``$(optenv)`` answer: the entry's packages and env."""

    packages: Mapping[str, Path]
    env: Mapping[str, str]
    # each package $(find) answered, with the folder it answered
    found: dict[str, str] = field(default_factory=dict)

    def unfound(self, urdf: bytes) -> bytes:
        """``urdf`` with each folder ``$(find)`` answered written back as ``$(find pkg)``.

        xacro needs the real folder to read what it includes or loads, but what it leaves of
        it in the URDF (a plugin's parameter file, ``file://$(find pkg)/…`` meshes) would put
        this checkout's place into the scene, so that a clone elsewhere (a teammate's, CI's)
        would see drift. Written back, the URDF depends on the repository alone; the mesh
        resolver reads ``$(find pkg)/…`` as the package's file."""
        for package, folder in sorted(self.found.items(), key=lambda p: -len(p[1])):
            # as minidom writes it in text and in attributes (a folder with & < > or ")
            spellings = (escape(folder), escape(folder, {'"': "&quot;"}))
            for spelled in dict.fromkeys(spellings):
                pattern = re.escape(spelled.encode()) + rb"(?=[/\\\s\"'<&]|$)"
                urdf = re.sub(pattern, f"$(find {package})".encode(), urdf)
        return urdf

    def find(self, package: str) -> str:
        folder = self.packages.get(package)
        if folder is None:
            listed = ", ".join(sorted(self.packages)) or "none"
            raise _Refused(
                f"$(find {package}): package '{package}' is not in this robot's `packages` "
                f"(listed: {listed})",
                hint=f"add {package}: <its folder, relative to the manifest> to `packages`",
                pattern=rf"\$\(\s*find\s+{re.escape(package)}(?=[\s)])",
            )
        self.found[package] = str(folder)
        return str(folder)

    def env_value(self, name: str) -> str:
        # xacro's $(env) is an error for an unset variable; the entry's env is the only one
        if name not in self.env:
            given = ", ".join(sorted(self.env)) or "none"
            raise _Refused(
                f"$(env {name}): variable '{name}' has no value in this robot's `env` "
                f"(given: {given}); the machine's environment is never read",
                hint=f"give it one in the entry: env: {{{name}: <value>}}",
                pattern=rf"\$\(\s*env\s+{re.escape(name)}(?=[\s)])",
            )
        return self.env[name]

    def optenv_value(self, name: str, default: str = "") -> str:
        # xacro's default for $(optenv VAR) with no default of its own is the empty string
        return self.env.get(name, default)


@contextlib.contextmanager
def _hooked(
    xacro: Any, substitution_args: Any, hooks: _Hooks, warnings: list[str]
) -> Iterator[None]:
    extension = xacro.eval_extension

    def eval_extension(text: str) -> object:
        # xacro answers $(cwd) itself, before any substitution hook, with the folder it runs in
        if text.replace(" ", "") == "$(cwd)":
            raise _Refused(
                "$(cwd) (the folder apply runs in) would make the URDF depend on this machine",
                hint="pass the value in the entry's `args` instead",
                pattern=r"\$\(\s*cwd\s*\)",
            )
        return extension(text)

    def warning(*parts: object, **_: object) -> None:
        where = (xacro.filestack or [None])[-1] or "xacro"
        warnings.append(f"{where}: xacro warns: {' '.join(str(p) for p in parts)}")

    answers = {"find": hooks.find, "env": hooks.env_value, "optenv": hooks.optenv_value}
    # xacro 2.x offers no public hook for $(find), $(env), $(cwd) or its warnings: these are its
    # private names (the functions $(...) calls, and the table $(eval) and ${} see), reached on
    # purpose and by name (the xacro tests fail if a release moves them).
    table = vars(substitution_args)["_eval_dict"]
    saved = {name: getattr(substitution_args, f"_eval_{name}") for name in answers}
    saved_table = {key: table[key] for key in answers}
    saved_xacro = {"eval_extension": extension, "warning": vars(xacro)["warning"]}
    try:
        for name, answer in answers.items():
            setattr(substitution_args, f"_eval_{name}", answer)
        table.update(answers)
        xacro.eval_extension, xacro.warning = eval_extension, warning
        yield
    finally:
        for name, original in saved.items():
            setattr(substitution_args, f"_eval_{name}", original)
        table.update(saved_table)
        for name, original in saved_xacro.items():
            setattr(xacro, name, original)
        xacro.init_stacks(None)


def _raise_located(path: Path, stack: list[str | None], error: BaseException) -> NoReturn:
    cause: BaseException | None = error
    while cause is not None and not isinstance(cause, (_Refused, xml.parsers.expat.ExpatError)):
        cause = getattr(cause, "exc", None) or cause.__context__
    where = stack[-1] or str(path)
    if isinstance(cause, _Refused):
        location = _found(where, cause.pattern)
        raise LocatedError.at(location, str(cause), hint=cause.hint) from None
    if isinstance(cause, xml.parsers.expat.ExpatError):
        location = SourceLocation(where, cause.lineno, cause.offset + 1)
        reason = xml.parsers.expat.errors.messages.get(cause.code, "not well-formed")
        hint = "a xacro file is XML: check the tags and quotes around this place"
        raise LocatedError.at(location, f"not well-formed XML: {reason}", hint=hint) from None
    message = " ".join(str(error).split()) or type(error).__name__
    hint = "fix the xacro file"
    if "is not defined" in message:
        hint = "define it with <xacro:property> (in this file or one it includes) or fix its name"
    elif "Undefined substitution argument" in message:
        hint = "give the argument in the entry's `args`, or a default with <xacro:arg>"
    elif isinstance(error, OSError) or "No such file" in message:
        hint = "check the include's path (relative to the including file, or $(find pkg)/...)"
    where_from = f" (included from {stack[-2]})" if len(stack) > 1 and stack[-2] else ""
    raise LocatedError.at(
        SourceLocation(where), f"xacro: {message}{where_from}", hint=hint
    ) from None


def _found(path: str, pattern: str) -> SourceLocation:
    """Where ``pattern`` first matches in the file at ``path``; the file alone when it does not
    (the substitution came from a macro of another file, or from an argument's value)."""
    try:
        raw = Path(path).read_bytes()
    except OSError:
        return SourceLocation(path)
    match = re.search(pattern.encode(), raw)
    return SourceLocation.at_byte(path, raw, match.start()) if match else SourceLocation(path)
