"""Atomic file writes: write to a temporary file beside the target, then rename.

:func:`atomic_write_many` writes several files all or none: every payload goes to a
temporary file first, and only when all are written are they renamed into place.
:func:`probe_writable` checks, before any work starts, that a target can be written
(it creates and removes the very temporary file a write would use). Files get the
mode a user's new file gets (``0o666`` less the umask), not ``mkstemp``'s ``0o600``.
"""

from __future__ import annotations

import os
import tempfile
from collections.abc import Sequence
from pathlib import Path

from .._errors import InputError

__all__ = ["atomic_write", "atomic_write_many", "probe_writable"]

# tempfile's random part is 8 characters: ".NAME." + 8 + ".tmp"
_TMP_EXTRA = len("..") + 8 + len(".tmp")


def _umask() -> int:
    try:  # Linux: read it without changing it (os.umask is process-wide, racy with threads)
        with open("/proc/self/status", encoding="ascii") as fh:
            for line in fh:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError, IndexError):
        pass
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def _why(exc: OSError) -> str:
    return exc.strerror or type(exc).__name__


def _check_target(target: Path, what: str) -> Path:
    parent = target.parent
    if not parent.exists():
        raise InputError(f"{what} {str(target)!r}: folder {str(parent)!r} does not exist")
    if not parent.is_dir():
        raise InputError(f"{what} {str(target)!r}: {str(parent)!r} is not a folder")
    if target.is_dir():
        raise InputError(f"{what} {str(target)!r}: is a folder, expected a file")
    if len(os.fsencode(target.name)) + _TMP_EXTRA > 255:
        raise InputError(f"{what} {str(target)!r}: file name too long ({len(os.fsencode(target.name))} bytes; at most {255 - _TMP_EXTRA})")
    return parent


def _mkstemp(target: Path, what: str) -> tuple[int, str]:
    parent = _check_target(target, what)
    try:
        return tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=parent)
    except OSError as exc:
        raise InputError(f"{what} {str(target)!r}: cannot write there ({_why(exc)})") from None


def probe_writable(path: str | os.PathLike[str], what: str = "--out") -> None:
    """Raise :class:`InputError` unless ``path`` can be written atomically.

    Creates the temporary file a write would create, beside the target, and removes it.
    """
    target = Path(path)
    fd, tmp = _mkstemp(target, what)
    os.close(fd)
    os.unlink(tmp)
    if target.exists() and not os.access(target, os.W_OK) and not os.access(target.parent, os.W_OK):
        raise InputError(f"{what} {str(target)!r}: cannot replace the existing file")


def atomic_write_many(items: Sequence[tuple[str | os.PathLike[str], bytes | str]], what: str = "--out") -> list[Path]:
    """Write every ``(path, data)`` so that either all targets are written or none is.

    Payloads are written to temporary files beside their targets; only when all are
    written are they renamed into place. On any error (including Ctrl-C) every
    temporary file is removed and no target is touched. Write errors become
    :class:`InputError` naming the path.
    """
    mode = 0o666 & ~_umask()
    staged: list[tuple[str, Path]] = []
    try:
        for path, data in items:
            target = Path(path)
            payload = data.encode("utf-8") if isinstance(data, str) else data
            fd, tmp = _mkstemp(target, what)
            staged.append((tmp, target))
            try:
                with os.fdopen(fd, "wb") as fh:
                    os.fchmod(fh.fileno(), mode)
                    fh.write(payload)
            except OSError as exc:
                raise InputError(f"{what} {str(target)!r}: cannot write ({_why(exc)})") from None
        # Rename into place; should a rename fail, undo the earlier ones: remove new files
        # and put back the old ones (kept as hard links until every rename succeeded).
        done: list[tuple[Path, str | None]] = []
        try:
            for tmp, target in staged:
                backup = None
                if target.exists():
                    backup = f"{tmp}.old"
                    try:
                        os.link(target, backup)
                    except OSError:
                        backup = None
                try:
                    os.replace(tmp, target)
                except OSError as exc:
                    if backup is not None:
                        os.unlink(backup)
                    raise InputError(f"{what} {str(target)!r}: cannot write ({_why(exc)})") from None
                done.append((target, backup))
        except BaseException:
            for target, backup in reversed(done):
                try:
                    if backup is not None:
                        os.replace(backup, target)
                    else:
                        os.unlink(target)
                except OSError:
                    pass
            raise
        for _, backup in done:
            if backup is not None:
                try:
                    os.unlink(backup)
                except OSError:
                    pass
        return [target for target, _ in done]
    except BaseException:
        for tmp, _ in staged:
            try:
                os.unlink(tmp)
            except FileNotFoundError:
                pass
        raise


def atomic_write(path: str | os.PathLike[str], data: bytes | str) -> Path:
    """Write ``data`` to ``path`` so that readers never see a partial file.

    On any error the target is left untouched and the temporary file is removed.
    """
    return atomic_write_many([(path, data)])[0]
