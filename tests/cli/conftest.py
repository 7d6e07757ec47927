"""Fixtures of the CLI's tests."""

from tests.cli.noop_support import planned, sample

__all__ = ["planned", "sample"]
