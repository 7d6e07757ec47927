"""The package's data files: the jinja2 templates (and a few ``string.Template`` ones), the
manifest's JSON Schema, ROS#'s catalog, uGUI's fields.

They live inside the package (``unityscaffold/templates/``, ``unityscaffold/schema/``), so a
source checkout, an editable install and a wheel all read them the same way: templates through
jinja's ``PackageLoader``, other files through ``importlib.resources``.

Compiled templates are kept in the user's cache folder (``$XDG_CACHE_HOME`` or ``~/.cache``,
``%LOCALAPPDATA%`` on Windows, under ``unityscaffold/<version>-templates``), so a command does
not parse and compile them again. jinja checks each entry against the template's source and
the Python version; set ``UNITYSCAFFOLD_NO_CACHE`` to do without. A cache folder that cannot
be written is simply not used. Nothing is written into projects or the package.
"""

from __future__ import annotations

import contextlib
import os
from functools import cache
from importlib.abc import Traversable
from importlib.resources import files
from pathlib import Path
from typing import TYPE_CHECKING

from unityscaffold import __version__
from unityscaffold.usercache import cache_root, template_cache_folder

if TYPE_CHECKING:
    import jinja2
    from jinja2.bccache import BytecodeCache

__all__ = [
    "rossharp_catalog_text",
    "schema_text",
    "template_environment",
    "template_folder",
    "template_text",
    "ugui_fields_text",
]

_PACKAGE = "unityscaffold"
_TEMPLATES = "templates"


def _user_cache(folder: Path) -> BytecodeCache:
    """jinja's file cache in ``folder``, creating it on first use and never failing a command.

    Defined here rather than at the top: jinja2 is imported only by the commands that render
    a template (an apply that writes no script, such as a robot's, never loads it).
    """
    from jinja2.bccache import Bucket, FileSystemBytecodeCache

    class UserCache(FileSystemBytecodeCache):
        def load_bytecode(self, bucket: Bucket) -> None:
            with contextlib.suppress(OSError):  # an unreadable cache: compile
                super().load_bytecode(bucket)

        def dump_bytecode(self, bucket: Bucket) -> None:
            with contextlib.suppress(OSError):  # no cache this time: the next command compiles
                os.makedirs(self.directory, exist_ok=True)
                super().dump_bytecode(bucket)

    return UserCache(str(folder), "%s.jinja-cache")


def _cache_folder() -> Path | None:
    root = cache_root()
    return Path(template_cache_folder(root, __version__)) if root else None


@cache
def template_environment() -> jinja2.Environment:
    """The one jinja2 environment for every template: generated C# and the ``init`` project.

    Templates see only what ``render`` passes them (their view), no jinja globals.
    """
    import jinja2

    folder = _cache_folder()
    environment = jinja2.Environment(
        loader=jinja2.PackageLoader(_PACKAGE, _TEMPLATES),
        bytecode_cache=_user_cache(folder) if folder else None,
        undefined=jinja2.StrictUndefined,
        keep_trailing_newline=True,
        trim_blocks=True,
        lstrip_blocks=True,
        autoescape=False,
        # Templates ship inside the package and do not change while a command runs: no stat of
        # the template file each time one is fetched (a tenth of generating Debian's types).
        auto_reload=False,
    )
    # No globals (jinja offers range, dict, namespace, cycler, joiner and lipsum): every render
    # copies them into its context through a ChainMap, which was half the cost of rendering a
    # message class. Templates only lay out what their view computed; they need none of them.
    environment.globals.clear()
    return environment


def template_folder(folder: str) -> dict[str, bytes]:
    """Every file under ``templates/<folder>/``, by its ``/``-separated path there, in order.

    The same paths (prefixed with ``<folder>/``) name the files for ``template_environment``.
    """
    found: dict[str, bytes] = {}
    pending: list[tuple[str, Traversable]] = [("", files(_PACKAGE) / _TEMPLATES / folder)]
    while pending:
        prefix, node = pending.pop()
        for child in node.iterdir():
            if child.is_dir():
                pending.append((f"{prefix}{child.name}/", child))
            else:
                found[prefix + child.name] = child.read_bytes()
    return {path: found[path] for path in sorted(found, key=lambda p: p.split("/"))}


@cache
def template_text(path: str) -> str:
    """The text of ``templates/<path>``: a ``string.Template`` for text that must be written
    without loading jinja (a robot's apply, whose start-up time counts)."""
    return (files(_PACKAGE) / _TEMPLATES / path).read_text(encoding="utf-8")


def schema_text() -> str:
    """The shipped ``robot.schema.json`` (``manifest.schema.render_schema`` writes it)."""

    return (files(_PACKAGE) / "schema" / "robot.schema.json").read_text(encoding="utf-8")


def rossharp_catalog_text() -> str:
    """The shipped ``rossharp_catalog.json`` (``scripts/update_rossharp_catalog.py`` writes it)."""
    return (files(_PACKAGE) / "unity" / "rossharp_catalog.json").read_text(encoding="utf-8")


def ugui_fields_text() -> str:
    """The shipped ``ugui_fields.json`` (``scripts/update_ugui_fields.py`` writes it)."""
    return (files(_PACKAGE) / "unity" / "ugui_fields.json").read_text(encoding="utf-8")
