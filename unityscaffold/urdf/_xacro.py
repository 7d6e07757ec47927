"""Expanding a ``.xacro`` robot into URDF bytes, in process, with PyPI's optional ``xacro``.

Determinism: ``$(find pkg)`` resolves only through the manifest entry's ``packages`` (never an
ament index or ROS_PACKAGE_PATH of the machine), and ``$(env)``, ``$(optenv)`` and ``$(cwd)``
(the folder apply runs in) are refused, so the URDF depends only on files in the repository and
the entry's ``args``. xacro opens every file it reads with ``open``, which apply's no-op record
observes like any other read.

xacro prints its warnings to stderr; they are caught and returned with the file xacro was
reading, for apply to report as notes like its own.

xacro keeps its state in module globals (the ``find`` function, the file stack); they are
swapped in and restored around one expansion, which is why this is the one module that knows
xacro's internals.
"""

from __future__ import annotations

import contextlib
import io
import xml.parsers.expat
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any, NoReturn

from unityscaffold.errors import LocatedError, SourceLocation, UserError

__all__ = ["Expanded", "expand_xacro", "is_xacro"]

_INSTALL = "install the extra that reads them: pip install 'unityscaffold[xacro]'"


class _Refused(Exception):
    """A substitution the project does not allow; its message is the user's error."""


@dataclass(frozen=True, slots=True)
class Expanded:
    """A xacro file's URDF, and xacro's warnings (``<file>: xacro warns: <text>``)."""

    urdf: bytes
    warnings: tuple[str, ...] = ()


def is_xacro(path: Path) -> bool:
    return path.suffix == ".xacro"


def expand_xacro(path: Path, *, packages: Mapping[str, Path], args: Mapping[str, str]) -> Expanded:
    """The URDF that ``path`` expands to with ``args``, with xacro's warnings; a xacro error
    names the file it is in (and the line, for XML errors), and nothing else of the machine is
    read."""
    try:
        import xacro
        from xacro import substitution_args
    except ImportError:
        raise UserError(
            f"{path} is a xacro file, and the xacro package is not installed", hint=_INSTALL
        ) from None
    warnings: list[str] = []
    stray = io.StringIO()
    with _hooked(xacro, substitution_args, packages, warnings), contextlib.redirect_stderr(stray):
        try:
            document = xacro.process_file(str(path), mappings=dict(args), verbosity=0)
        except (Exception, RecursionError) as error:  # xacro raises what it meets
            _raise_located(path, list(xacro.filestack or [str(path)]), error)
        finally:
            xacro.all_includes.clear()  # grows across runs otherwise
    warnings += [f"{path}: xacro says: {line}" for line in _stray_lines(stray.getvalue())]
    # laid out as the xacro command prints it, so a URDF error's line is that output's line
    urdf = bytes(document.toprettyxml(indent="  ", encoding="utf-8"))
    return Expanded(urdf, tuple(dict.fromkeys(warnings)))


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


@contextlib.contextmanager
def _hooked(
    xacro: Any, substitution_args: Any, packages: Mapping[str, Path], warnings: list[str]
) -> Iterator[None]:
    def find(package: str) -> str:
        folder = packages.get(package)
        if folder is None:
            listed = ", ".join(sorted(packages)) or "none"
            raise _Refused(
                f"$(find {package}): package '{package}' is not in this robot's `packages` "
                f"(listed: {listed})"
            )
        return str(folder)

    def refuse(call: str) -> Callable[..., NoReturn]:
        def refused(*_: object) -> NoReturn:
            raise _Refused(f"{call} would make the URDF depend on this machine")

        return refused

    extension = xacro.eval_extension

    def eval_extension(text: str) -> object:
        # xacro answers $(cwd) itself, before any substitution hook, with the folder it runs in
        if text.replace(" ", "") == "$(cwd)":
            refuse("$(cwd) (the folder apply runs in)")()
        return extension(text)

    def warning(*parts: object, **_: object) -> None:
        where = (xacro.filestack or [None])[-1] or "xacro"
        warnings.append(f"{where}: xacro warns: {' '.join(str(p) for p in parts)}")

    hooks = {
        "_eval_find": find,
        "_eval_env": refuse("$(env ...)"),
        "_eval_optenv": refuse("$(optenv ...)"),
    }
    # xacro 2.x offers no public hook for $(find), $(env), $(cwd) or its warnings: these are its
    # private names, reached on purpose and by name (the xacro tests fail if a release moves
    # them).
    table = vars(substitution_args)["_eval_dict"]
    saved = {name: getattr(substitution_args, name) for name in hooks}
    saved_table = {key: table[key] for key in ("find", "env", "optenv")}
    saved_xacro = {"eval_extension": extension, "warning": vars(xacro)["warning"]}
    try:
        for name, hook in hooks.items():
            setattr(substitution_args, name, hook)
        table.update(find=find, env=hooks["_eval_env"], optenv=hooks["_eval_optenv"])
        xacro.eval_extension, xacro.warning = eval_extension, warning
        yield
    finally:
        for name, original in saved.items():
            setattr(substitution_args, name, original)
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
        hint = "list the package under `packages`, or pass the value in `args`"
        raise LocatedError.at(SourceLocation(where), str(cause), hint=hint) from None
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
