"""A rosbridge v2 WebSocket connection that calls services and waits for their answers.

Every call has a deadline, and every way a bridge can misbehave (silence, a dropped
connection, an error status, a malformed reply) becomes a ``UserError`` naming the bridge and
the call; ``try_call`` hands a failed call's text back instead, for calls that may fail.
"""

from __future__ import annotations

import contextlib
import itertools
import json
import time
from types import TracebackType
from typing import Any

from websockets.exceptions import ConnectionClosed, InvalidHandshake, InvalidURI
from websockets.sync.client import ClientConnection, connect

from unityscaffold.errors import UserError
from unityscaffold.interfaces.live.model import is_url

__all__ = ["CallFailed", "RosbridgeClient", "strings"]


class CallFailed(UserError):
    """The bridge answered that a call failed; ``text`` is what it said."""

    def __init__(self, message: str, text: str) -> None:
        super().__init__(message)
        self.text = text


class RosbridgeClient:
    """A rosbridge v2 connection that calls services and waits for their answers."""

    def __init__(self, url: str, *, timeout: float) -> None:
        if not is_url(url, ("ws", "wss")):
            raise UserError(f"not a rosbridge URL: {url!r}", hint="use ws://HOST:9090")
        self.url, self.timeout = url, timeout
        self._ids = itertools.count(1)
        self._socket: ClientConnection | None = None
        self._stack = contextlib.ExitStack()

    def __enter__(self) -> RosbridgeClient:
        try:
            # Entered as a context manager: websockets 16+ deprecates bare connect().
            self._socket = self._stack.enter_context(
                connect(
                    self.url,
                    open_timeout=self.timeout,
                    close_timeout=self.timeout,
                    max_size=64 * 1024 * 1024,
                )
            )
        except ConnectionRefusedError:
            raise UserError(f"no rosbridge at {self.url} (connection refused)") from None
        except TimeoutError:
            raise UserError(
                f"rosbridge at {self.url} did not accept a WebSocket connection "
                f"within {self.timeout:g} s"
            ) from None
        except (InvalidHandshake, InvalidURI) as exc:
            raise UserError(f"{self.url} is not a rosbridge WebSocket: {exc}") from None
        except OSError as exc:
            raise UserError(f"no rosbridge at {self.url} ({exc.strerror or exc})") from None
        return self

    def __exit__(
        self,
        kind: type[BaseException] | None,
        error: BaseException | None,
        trace: TracebackType | None,
    ) -> None:
        self._stack.close()

    def try_call(self, service: str, args: dict[str, Any] | None = None) -> dict[str, Any] | str:
        """Call ``service``: its response values, or the bridge's text when it answered that
        the call failed (an unknown service, arguments the request refuses, a server that
        raised); silence, a drop or a malformed reply still raise."""
        try:
            return self.call(service, args)
        except CallFailed as failed:
            return failed.text

    def call(self, service: str, args: dict[str, Any] | None = None) -> dict[str, Any]:
        """Call ``service`` and return its response values."""
        assert self._socket is not None, "use RosbridgeClient as a context manager"
        call_id = f"call_service:{service}:{next(self._ids)}"
        request = {"op": "call_service", "id": call_id, "service": service, "args": args or {}}
        deadline = time.monotonic() + self.timeout
        try:
            self._socket.send(json.dumps(request))
            while True:
                reply = self._receive(service, deadline)
                values = self._answer(reply, call_id, service)
                if values is not None:
                    return values
        except ConnectionClosed:
            raise UserError(
                f"rosbridge at {self.url} closed the connection while {service} was pending"
            ) from None

    def _receive(self, service: str, deadline: float) -> dict[str, Any]:
        assert self._socket is not None
        try:
            raw = self._socket.recv(timeout=max(0.0, deadline - time.monotonic()))
        except TimeoutError:
            raise UserError(
                f"rosbridge at {self.url} did not answer {service} within {self.timeout:g} s"
            ) from None
        try:
            reply = json.loads(raw)
        except (ValueError, TypeError):
            raise self.malformed(service, "not JSON") from None
        if not isinstance(reply, dict):
            raise self.malformed(service, "not a JSON object")
        return reply

    def _answer(self, reply: dict[str, Any], call_id: str, service: str) -> dict[str, Any] | None:
        """The values if ``reply`` answers this call; ``None`` for unrelated traffic."""
        if (
            reply.get("op") == "status"
            and reply.get("level") == "error"
            and reply.get("id") in (None, call_id)
        ):
            text = str(reply.get("msg", "(no message)"))
            raise CallFailed(
                f"rosbridge at {self.url} reported an error for {service}: {text}", text
            )
        if reply.get("op") != "service_response" or reply.get("id") != call_id:
            return None
        values = reply.get("values")
        if reply.get("result") is False:
            raise CallFailed(f"rosbridge at {self.url}: {service} failed: {values}", str(values))
        if not isinstance(values, dict):
            raise self.malformed(service, "values is not an object")
        return values

    def malformed(self, service: str, why: str) -> UserError:
        return UserError(f"rosbridge at {self.url} sent a malformed reply to {service}: {why}")


def strings(client: RosbridgeClient, values: dict[str, Any], key: str, service: str) -> list[str]:
    value = values.get(key)
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise client.malformed(service, f"{key} is not a list of strings")
    return value
