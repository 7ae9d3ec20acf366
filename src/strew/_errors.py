"""Exceptions shared by the library and the CLI."""

from __future__ import annotations

__all__ = ["InputError", "Cancelled"]


class InputError(ValueError):
    """Bad input: a malformed document, an invalid parameter, an unusable shape.

    The message names the offending field or value. The CLI turns this into a
    one-line message on stderr and exit code 2.
    """


class Cancelled(RuntimeError):
    """A long-running operation was cancelled through its ``should_cancel`` hook."""
