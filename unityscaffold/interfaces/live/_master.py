"""ROS 1 without rosbridge: the master's XML-RPC API, then a TCPROS header from each node.

Topics and their types come from ``getTopicTypes`` and ``getSystemState``; each topic's md5sum
and full definition from a header exchange with one of its publishers (``lookupNode``, the
node's ``requestTopic``, then TCPROS). Services: ``lookupService`` and a probe header, which
gives the type and md5sum but never the ``.srv`` text. A node that does not answer within the
timeout is skipped with a warning, so one hung node cannot hang discovery.
"""

from __future__ import annotations

import http.client
import socket
import urllib.parse
import xmlrpc.client
from concurrent.futures import ThreadPoolExecutor, as_completed
from dataclasses import dataclass
from typing import Any
from xml.parsers.expat import ExpatError

from unityscaffold.errors import UserError
from unityscaffold.interfaces.live import _tcpros
from unityscaffold.interfaces.live.model import (
    Direction,
    DiscoveredService,
    DiscoveredTopic,
    Discovery,
    NameFilter,
    Progress,
    is_url,
)
from unityscaffold.interfaces.model import Dialect

__all__ = ["CALLER_ID", "discover_master", "list_master_types"]

CALLER_ID = "/scaffold_discover"
# Probes run in parallel so that N silent nodes cost one timeout, not N.
_WORKERS = 8


class _TimeoutTransport(xmlrpc.client.Transport):
    """xmlrpc's transport has no timeout; a hung node would block discovery forever."""

    def __init__(self, timeout: float) -> None:
        super().__init__()
        self._timeout = timeout

    def make_connection(self, host: Any) -> http.client.HTTPConnection:
        connection = super().make_connection(host)
        connection.timeout = self._timeout
        return connection


@dataclass(frozen=True, slots=True)
class _Graph:
    types: dict[str, str]
    publishers: dict[str, list[str]]
    subscribers: dict[str, list[str]]
    services: dict[str, list[str]]


class _Api:
    """One XML-RPC endpoint (master or node), with errors that say who did not answer."""

    def __init__(self, url: str, timeout: float, who: str) -> None:
        self.url, self.timeout, self.who = url, timeout, who

    def call(self, method: str, *args: Any) -> Any:
        # A proxy per call: ServerProxy keeps one HTTP connection and is not thread-safe.
        proxy = xmlrpc.client.ServerProxy(self.url, transport=_TimeoutTransport(self.timeout))
        try:
            reply = getattr(proxy, method)(CALLER_ID, *args)
        except ConnectionRefusedError:
            raise UserError(f"no {self.who} at {self.url} (connection refused)") from None
        except TimeoutError:
            raise UserError(
                f"{self.who} at {self.url} did not answer {method} within {self.timeout:g} s"
            ) from None
        except socket.gaierror as exc:
            raise UserError(f"no {self.who} at {self.url} (unknown host: {exc.strerror})") from None
        except xmlrpc.client.ProtocolError as exc:
            raise self._not_ros(f"it answered HTTP {exc.errcode} {exc.errmsg}") from None
        except xmlrpc.client.Fault as exc:
            raise self._not_ros(f"it answered fault {exc.faultCode}: {exc.faultString}") from None
        except (xmlrpc.client.Error, ExpatError, http.client.HTTPException, ValueError):
            raise self._not_ros("its reply is not XML-RPC") from None
        except OSError as exc:
            raise UserError(f"no {self.who} at {self.url} ({exc.strerror or exc})") from None
        if not (isinstance(reply, list) and len(reply) == 3 and isinstance(reply[0], int)):
            raise self.malformed(method)
        code, status, value = reply
        if code != 1:
            raise UserError(f"{self.who} at {self.url} refused {method}: {status}")
        return value

    def _not_ros(self, reason: str) -> UserError:
        return UserError(f"{self.who} at {self.url} is not a ROS XML-RPC API: {reason}")

    def malformed(self, method: str) -> UserError:
        return UserError(f"{self.who} at {self.url} sent a malformed reply to {method}")


def check_url(url: str) -> None:
    if not is_url(url, ("http",)):
        raise UserError(f"not a ROS master URL: {url!r}", hint="use http://HOST:11311")


def _graph(master: _Api) -> _Graph:
    try:
        types = {name: kind for name, kind in master.call("getTopicTypes")}
    except (TypeError, ValueError):
        raise master.malformed("getTopicTypes") from None
    try:
        publishers, subscribers, services = master.call("getSystemState")
        return _Graph(
            types,
            dict(map(tuple, publishers)),
            dict(map(tuple, subscribers)),
            dict(map(tuple, services)),
        )
    except (TypeError, ValueError):
        raise master.malformed("getSystemState") from None


def list_master_types(url: str, *, timeout: float) -> list[tuple[str, str]]:
    """Active topics and their types, as rosapi lists them (registered by some node)."""
    check_url(url)
    graph = _graph(_Api(url, timeout, "ROS master"))
    active = graph.publishers.keys() | graph.subscribers.keys()
    return sorted((name, graph.types.get(name, "")) for name in active)


def discover_master(
    url: str, *, timeout: float, names: NameFilter, progress: Progress | None = None
) -> Discovery:
    """Topics (with definitions from their publishers) and services of a running ROS 1 system."""
    check_url(url)
    master = _Api(url, timeout, "ROS master")
    graph = _graph(master)
    topic_names = sorted(
        n for n in graph.publishers.keys() | graph.subscribers.keys() if names.accepts(n)
    )
    service_names = sorted(n for n in graph.services if names.accepts(n))
    jobs = {
        **{("topic", n): _topic_job(master, graph, n) for n in topic_names},
        **{("service", n): _service_job(master, n) for n in service_names},
    }
    results, warnings = _run(jobs, progress)
    topics = [r for r in results if isinstance(r, DiscoveredTopic)]
    services = [r for r in results if isinstance(r, DiscoveredService)]
    return Discovery(Dialect.ROS1, url, tuple(topics), tuple(services), tuple(sorted(warnings)))


def _run(
    jobs: dict[tuple[str, str], Any], progress: Progress | None
) -> tuple[list[DiscoveredTopic | DiscoveredService], list[str]]:
    results: list[DiscoveredTopic | DiscoveredService] = []
    warnings: list[str] = []
    # A topic or service whose type nobody could tell is left out, with a warning.
    with ThreadPoolExecutor(max_workers=_WORKERS) as pool:
        futures = {pool.submit(job): key for key, job in jobs.items()}
        for done, future in enumerate(as_completed(futures), start=1):
            result, warning = future.result()
            if result is not None and result.type:
                results.append(result)
            if warning:
                warnings.append(warning)
            if progress is not None:
                progress(done, len(futures), futures[future][1])
    return results, warnings


def _topic_job(master: _Api, graph: _Graph, topic: str) -> Any:
    def probe() -> tuple[DiscoveredTopic, str | None]:
        publishers = graph.publishers.get(topic, [])
        direction = Direction.from_graph(bool(publishers), bool(graph.subscribers.get(topic)))
        found = DiscoveredTopic(topic, graph.types.get(topic, ""), direction)
        problems: list[str] = []
        for node in sorted(publishers):
            try:
                header = _probe_publisher(master, node, topic)
            except UserError as error:
                problems.append(error.message)
                continue
            return DiscoveredTopic(
                topic,
                header.get("type") or found.type,
                direction,
                header.get("md5sum"),
                header.get("message_definition"),
            ), None
        if not found.type:
            return found, f"skipped {topic}: the master does not know its type"
        if problems:
            return found, f"skipped the definition of {topic}: " + "; ".join(problems)
        return found, None

    return probe


def _probe_publisher(master: _Api, node: str, topic: str) -> dict[str, str]:
    node_url = master.call("lookupNode", node)
    node_api = _Api(node_url, master.timeout, f"node {node}")
    protocol = node_api.call("requestTopic", topic, [["TCPROS"]])
    if not (isinstance(protocol, list) and len(protocol) == 3 and protocol[0] == "TCPROS"):
        raise UserError(f"node {node} offered no TCPROS connection for {topic}")
    _, host, port = protocol
    return _tcpros.exchange(
        host,
        int(port),
        {"callerid": CALLER_ID, "topic": topic, "md5sum": "*", "type": "*"},
        timeout=master.timeout,
        peer=f"publisher {node} of {topic}",
    )


def _service_job(master: _Api, service: str) -> Any:
    def probe() -> tuple[DiscoveredService | None, str | None]:
        try:
            uri = master.call("lookupService", service)
            valid = isinstance(uri, str) and is_url(uri, ("rosrpc",))
            parsed = urllib.parse.urlsplit(uri if valid else "")
            if not parsed.hostname or not parsed.port:
                raise UserError(f"the master gave {service} the address {uri!r}, not rosrpc://")
            header = _tcpros.exchange(
                parsed.hostname,
                parsed.port,
                {"callerid": CALLER_ID, "service": service, "md5sum": "*", "probe": "1"},
                timeout=master.timeout,
                peer=f"provider of {service}",
            )
        except UserError as error:
            return None, f"skipped service {service}: {error.message}"
        return DiscoveredService(service, header.get("type", ""), header.get("md5sum")), None

    return probe
