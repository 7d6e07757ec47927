"""The guard around an import that needs an optional extra: a clear error naming the extra
when the extra's package is missing, and any other missing module left to show as the bug it
is."""

from __future__ import annotations

import contextlib
from collections.abc import Iterator

from unityscaffold.errors import UserError

__all__ = ["optional_extra"]


@contextlib.contextmanager
def optional_extra(packages: tuple[str, ...], message: str, *, hint: str) -> Iterator[None]:
    """Imports in the block that miss one of ``packages`` (top-level names) raise a UserError
    with ``message`` and ``hint`` (how to install the extra)."""
    try:
        yield
    except ModuleNotFoundError as exc:
        if exc.name is None or exc.name.split(".")[0] not in packages:
            raise
        raise UserError(message, hint=hint) from None
