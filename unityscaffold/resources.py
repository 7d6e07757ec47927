"""The package's data files: the jinja2 templates, the manifest's JSON Schema, ROS#'s catalog.

They live inside the package (``unityscaffold/templates/``, ``unityscaffold/schema/``), so a
source checkout, an editable install and a wheel all read them the same way: templates through
jinja's ``PackageLoader``, other files through ``importlib.resources``.
"""

from __future__ import annotations

from functools import cache
from importlib.resources import files

import jinja2

__all__ = ["rossharp_catalog_text", "schema_text", "template_environment", "template_folder"]

_PACKAGE = "unityscaffold"
_TEMPLATES = "templates"


@cache
def template_environment() -> jinja2.Environment:
    """The one jinja2 environment for every template: generated C# and the ``init`` project."""
    return jinja2.Environment(
        loader=jinja2.PackageLoader(_PACKAGE, _TEMPLATES),
        undefined=jinja2.StrictUndefined,
        keep_trailing_newline=True,
        trim_blocks=True,
        lstrip_blocks=True,
        autoescape=False,
    )


def template_folder(folder: str) -> dict[str, bytes]:
    """Every file under ``templates/<folder>/``, by its ``/``-separated path there, in order.

    The same paths (prefixed with ``<folder>/``) name the files for ``template_environment``.
    """
    found: dict[str, bytes] = {}
    pending = [("", files(_PACKAGE) / _TEMPLATES / folder)]
    while pending:
        prefix, node = pending.pop()
        for child in node.iterdir():
            if child.is_dir():
                pending.append((f"{prefix}{child.name}/", child))
            else:
                found[prefix + child.name] = child.read_bytes()
    return {path: found[path] for path in sorted(found, key=lambda p: p.split("/"))}


def schema_text() -> str:
    """The shipped ``robot.schema.json`` (``manifest.schema.render_schema`` writes it)."""
    return (files(_PACKAGE) / "schema" / "robot.schema.json").read_text(encoding="utf-8")


def rossharp_catalog_text() -> str:
    """The shipped ``rossharp_catalog.json`` (``scripts/update_rossharp_catalog.py`` writes it)."""
    return (files(_PACKAGE) / "unity" / "rossharp_catalog.json").read_text(encoding="utf-8")
