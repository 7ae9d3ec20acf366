"""Progress and cancellation plumbing shared by the library, the CLI and the studio.

Long-running functions accept two optional keyword arguments:

``progress(done, total, message)``
    called now and then; ``total`` may be ``None`` when unknown.
``should_cancel()``
    polled now and then; when it returns True the function raises :class:`strew.Cancelled`.

:class:`Reporter` bundles both and throttles the callbacks so that hot loops can call
:meth:`Reporter.tick` freely.
"""

from __future__ import annotations

import time
from collections.abc import Callable

from ._errors import Cancelled

__all__ = ["ProgressCallback", "CancelCheck", "Reporter"]

ProgressCallback = Callable[[int, "int | None", str], None]
CancelCheck = Callable[[], bool]


class Reporter:
    """Throttled progress reporting and cancellation checks.

    Parameters
    ----------
    progress : callable, optional
        ``progress(done, total, message)``.
    should_cancel : callable, optional
        Returns True to request cancellation.
    total : int, optional
        Expected amount of work, if known.
    message : str
        Shown next to the bar.
    interval : float
        Minimum seconds between two callbacks.
    """

    def __init__(
        self,
        progress: ProgressCallback | None = None,
        should_cancel: CancelCheck | None = None,
        *,
        total: int | None = None,
        message: str = "",
        interval: float = 0.05,
    ) -> None:
        self._progress = progress
        self._cancel = should_cancel
        self.total = total
        self.message = message
        self.interval = interval
        self._last = float("-inf")

    def tick(self, done: int, *, total: int | None = None, message: str | None = None, force: bool = False) -> None:
        """Report ``done`` units of work and raise :class:`Cancelled` if asked to stop."""
        if self._progress is None and self._cancel is None:
            return
        now = time.perf_counter()
        if not force and now - self._last < self.interval:
            return
        self._last = now
        if total is not None:
            self.total = total
        if message is not None:
            self.message = message
        if self._cancel is not None and self._cancel():
            raise Cancelled("cancelled")
        if self._progress is not None:
            self._progress(int(done), self.total, self.message)

    def done(self, done: int | None = None) -> None:
        """Final report (always delivered)."""
        if self._progress is not None:
            n = done if done is not None else (self.total or 0)
            self._progress(int(n), self.total if self.total is not None else int(n), self.message)
