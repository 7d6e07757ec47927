"""What a misbehaving source, a bad URL or an unreadable manifest tells the user of ``discover``:
a message in the user's words, never Python's own exception text or an internal error."""

from __future__ import annotations

import http.server
import threading
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest
from helpers_live import run_cli, snapshot

from unityscaffold.errors import UserError
from unityscaffold.interfaces.live import discover
from unityscaffold.interfaces.live._tcpros import MalformedHeader, decode_header
from unityscaffold.interfaces.live._typedefs import full_text_from_typedefs

FAULT = (
    b"<?xml version='1.0'?><methodResponse><fault><value><struct>"
    b"<member><name>faultCode</name><value><int>4</int></value></member>"
    b"<member><name>faultString</name><value><string>boom</string></value></member>"
    b"</struct></value></fault></methodResponse>"
)
TOPIC_TYPES_NOT_PAIRS = (
    b"<?xml version='1.0'?><methodResponse><params><param><value><array><data>"
    b"<value><int>1</int></value><value><string>ok</string></value>"
    b"<value><array><data><value><int>7</int></value></data></array></value>"
    b"</data></array></value></param></params></methodResponse>"
)


@pytest.mark.parametrize(
    "url",
    ["http://127.0.0.1:abc", "http://[::1", "http://127.0.0.1:99999", "ftp://robot"],
)
def test_a_bad_master_url_is_refused(url: str) -> None:
    with pytest.raises(UserError) as caught:
        discover(master_url=url, timeout=0.5)
    assert (caught.value.message, caught.value.hint) == (
        f"not a ROS master URL: {url!r}",
        "use http://HOST:11311",
    )


@pytest.mark.parametrize(
    "url", ["ws://127.0.0.1:abc", "ws://[::1", "ws://127.0.0.1:99999", "http://robot"]
)
def test_a_bad_rosbridge_url_is_refused(url: str) -> None:
    with pytest.raises(UserError) as caught:
        discover(rosbridge_url=url, timeout=0.5)
    assert (caught.value.message, caught.value.hint) == (
        f"not a rosbridge URL: {url!r}",
        "use ws://HOST:9090",
    )


@dataclass
class HttpPeer:
    """An HTTP server on loopback answering every POST with ``status`` and ``body``."""

    url: str = ""
    status: int = 200
    body: bytes = b""


@pytest.fixture
def http_peer() -> Iterator[HttpPeer]:
    peer = HttpPeer()

    class Handler(http.server.BaseHTTPRequestHandler):
        def do_POST(self) -> None:
            self.rfile.read(int(self.headers.get("Content-Length", 0)))
            self.send_response(peer.status)
            self.send_header("Content-Type", "text/xml")
            self.send_header("Content-Length", str(len(peer.body)))
            self.end_headers()
            self.wfile.write(peer.body)

        def log_message(self, *args: object) -> None:
            pass

    server = http.server.HTTPServer(("127.0.0.1", 0), Handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    peer.url = f"http://127.0.0.1:{server.server_address[1]}"
    try:
        yield peer
    finally:
        server.shutdown()
        server.server_close()


@pytest.mark.parametrize(
    ("status", "body", "reason"),
    [
        (404, b"", "is not a ROS XML-RPC API: it answered HTTP 404 Not Found"),
        (200, b"<html>hello</html>", "is not a ROS XML-RPC API: its reply is not XML-RPC"),
        (200, b"not xml at all <", "is not a ROS XML-RPC API: its reply is not XML-RPC"),
        (200, b"", "is not a ROS XML-RPC API: its reply is not XML-RPC"),
        (200, FAULT, "is not a ROS XML-RPC API: it answered fault 4: boom"),
        (200, TOPIC_TYPES_NOT_PAIRS, "sent a malformed reply to getTopicTypes"),
    ],
)
def test_a_server_that_is_not_a_ros_master_is_described(
    http_peer: HttpPeer, status: int, body: bytes, reason: str
) -> None:
    http_peer.status, http_peer.body = status, body
    with pytest.raises(UserError) as caught:
        discover(master_url=http_peer.url, timeout=2)
    assert caught.value.message == f"ROS master at {http_peer.url} {reason}"


def test_a_tcpros_field_that_is_not_utf8_is_named() -> None:
    with pytest.raises(MalformedHeader) as caught:
        decode_header(b"\x07\x00\x00\x00type=\xff\xfe")
    assert str(caught.value) == "field b'type=\\xff\\xfe' is not UTF-8 text"


@pytest.mark.parametrize("lengths", [3, ["x"], [None], [True]])
def test_typedefs_with_bad_array_lengths_are_malformed(lengths: object) -> None:
    typedef = {"type": "pkg/Msg", "fieldnames": ["a"], "fieldtypes": ["int32"]}
    with pytest.raises(ValueError) as caught:
        full_text_from_typedefs("pkg/Msg", [{**typedef, "fieldarraylen": lengths}])
    assert str(caught.value) == "TypeDef field fieldarraylen is not a list of integers"


def test_a_manifest_that_is_not_utf8_stops_discover(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    manifest = tmp_path / "robot.yaml"
    manifest.write_bytes(b"version: 1\nros: 1\nscene: \xff\n")
    before = snapshot(tmp_path)
    run = run_cli(capsys, "discover", str(manifest), "--bag", str(tmp_path / "none.bag"))
    assert run.code == 2
    assert (
        run.err == f"error: the manifest {manifest} is not UTF-8 text\n  hint: save it as UTF-8\n"
    )
    assert snapshot(tmp_path) == before
