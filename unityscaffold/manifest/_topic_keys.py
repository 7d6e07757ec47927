"""A topic's timing keys, which differ by direction and by runtime: ``rate`` (publishers),
``throttle`` (ROS# subscribers), ``queue`` (ROS# subscribers: rosbridge's queue;
ROS-TCP-Connector publishers: the ROS publisher's queue size) and ``latch``
(ROS-TCP-Connector publishers)."""

from __future__ import annotations

from dataclasses import dataclass

from unityscaffold.manifest._read import Reader
from unityscaffold.manifest._yaml import YMap
from unityscaffold.manifest.model import Direction
from unityscaffold.manifest.runtime import RUNTIME_ONLY, Runtime

__all__ = ["Rates", "read_rates"]


@dataclass(frozen=True, slots=True)
class Rates:
    rate: float | None = None
    throttle: int | None = None
    queue: int | None = None
    latch: bool | None = None


_RATE_HINT = "use 'rate' (messages per second) to set how often Unity publishes"


def _queue_side(runtime: Runtime) -> Direction:
    return Direction.PUBLISH if runtime is Runtime.TCP_CONNECTOR else Direction.SUBSCRIBE


def _misplaced(r: Reader, m: YMap, direction: Direction | None, runtime: Runtime) -> None:
    """Report keys of the other direction or of the other runtime, each once."""
    for key, (owner, why) in RUNTIME_ONLY.items():
        if owner is not runtime and (entry := m.get(key)) is not None:
            r.error(entry.key_location, f"'{key}' is not a {runtime.value} topic key", hint=why)
    if direction is Direction.SUBSCRIBE and (entry := m.get("rate")) is not None:
        slower = (
            "a subscriber gets messages at the publisher's rate"
            if runtime is Runtime.TCP_CONNECTOR
            else "a subscriber gets messages at the publisher's rate; use 'throttle' "
            "(milliseconds between messages) to slow them down"
        )
        r.error(
            entry.key_location, "'rate' applies only to topics with direction: publish", hint=slower
        )
    side = {"queue": _queue_side(runtime)}
    if runtime is Runtime.TCP_CONNECTOR:
        side["latch"] = Direction.PUBLISH
    else:
        side["throttle"] = Direction.SUBSCRIBE
    for key, wanted in side.items():
        if direction in (None, wanted) or (entry := m.get(key)) is None:
            continue
        hint = _RATE_HINT if wanted is Direction.SUBSCRIBE else None
        if key == "queue" and runtime is Runtime.TCP_CONNECTOR:
            hint = "ROS-TCP-Endpoint's subscriber queue is its own (10); queue sets a publisher's"
        r.error(
            entry.key_location,
            f"'{key}' applies only to topics with direction: {wanted.value}"
            + (f" under runtime: {runtime.value}" if key == "queue" else ""),
            hint=hint,
        )


def read_rates(r: Reader, m: YMap, direction: Direction | None, runtime: Runtime) -> Rates:
    _misplaced(r, m, direction, runtime)
    rate = throttle = queue = latch = None
    if direction is not Direction.SUBSCRIBE:
        rate = r.positive_number(m, "rate", "messages per second")
    if direction in (None, _queue_side(runtime)):
        queue = r.integer(m, "queue", 1)
    if runtime is Runtime.ROS_SHARP and direction is not Direction.PUBLISH:
        throttle = r.integer(m, "throttle", 0, "milliseconds")
    if runtime is Runtime.TCP_CONNECTOR and direction is not Direction.SUBSCRIBE:
        latch = r.boolean(m, "latch")
    return Rates(rate, throttle, queue, latch)
