"""The ROS 2 graph as rclpy sees it, read once into plain data (``GraphSnapshot``).

rclpy is an optional extra (``unityscaffold[ros2]``: PyPI's Jazzy wheels), so it is imported
here only, by name (it ships no type information). A node of our own joins the graph, waits for
discovery to settle, and records every topic, service and action with their types, each
endpoint's node and RIHS01 type hash, including the hidden ``rq/…Request`` and ``rr/…Reply``
topics that carry a service's halves (the only place Jazzy's graph reports a service's hashes).
"""

from __future__ import annotations

import contextlib
import importlib
import os
import time
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Any

from unityscaffold.errors import UserError
from unityscaffold.interfaces.live._optional import optional_extra

__all__ = ["Endpoint", "Graph", "GraphSnapshot", "TypeReply", "ros2_graph"]

# How often the graph is read while waiting, and how long it must stay the same to be settled.
_POLL = 0.2
_SETTLED = 1.0


@dataclass(frozen=True, slots=True)
class Endpoint:
    """A publisher or subscription of one node, with the type hash the graph reports."""

    node: str  # full name, e.g. /robot
    publishes: bool
    type: str
    type_hash: str | None


@dataclass(frozen=True, slots=True)
class TypeReply:
    """A node's answer to ``~/get_type_description``: each type's source file (``msg``,
    ``srv``, ``action``, or ``implicit`` with no text) and each type's fields as
    ``(name, type_id, capacity, string_capacity, nested_type_name)``."""

    sources: dict[str, tuple[str, str]]
    fields: dict[str, tuple[tuple[str, int, int, int, str], ...]]


@dataclass(slots=True)
class GraphSnapshot:
    """Names and types (hidden ones included), and endpoints by topic."""

    topics: dict[str, list[str]] = field(default_factory=dict)
    services: dict[str, list[str]] = field(default_factory=dict)
    actions: dict[str, list[str]] = field(default_factory=dict)
    endpoints: dict[str, list[Endpoint]] = field(default_factory=dict)
    nodes: list[str] = field(default_factory=list)


def _import_rclpy() -> Any:
    with optional_extra(
        ("rclpy", "rpyutils"),
        "reading the ROS 2 graph needs rclpy, which is not installed",
        hint="install unityscaffold with its `ros2` extra (PyPI's ROS 2 Jazzy wheels, for "
        "CPython 3.11 on Linux x86-64): python3 -m pip install 'unityscaffold[ros2]' (from a "
        "checkout: '.[ros2]'); or discover through a rosbridge with --rosbridge URL",
    ):
        return importlib.import_module("rclpy")


class Graph:
    """One rclpy context and node, for reading the graph and asking nodes for types."""

    def __init__(self, node: Any, executor: Any) -> None:
        self.node, self.executor = node, executor
        self.own = node.get_fully_qualified_name()

    def snapshot(self) -> GraphSnapshot:
        node = self.node
        graph = GraphSnapshot()
        graph.nodes = sorted(
            _full(name, ns)
            for name, ns in node.get_node_names_and_namespaces()
            if _full(name, ns) != self.own
        )
        graph.topics = {n: list(t) for n, t in node.get_topic_names_and_types()}
        graph.services = {
            n: list(t)
            for n, t in node.get_service_names_and_types()
            if not n.startswith(self.own + "/")
        }
        action_graph = importlib.import_module("rclpy.action.graph")
        graph.actions = {n: list(t) for n, t in action_graph.get_action_names_and_types(node)}
        for topic in graph.topics:
            graph.endpoints[topic] = self._endpoints(topic, mangled=False)
        for service in graph.services:
            for prefix, suffix in (("rq", "Request"), ("rr", "Reply")):
                name = f"{prefix}{service}{suffix}"
                graph.endpoints[name] = self._endpoints(name, mangled=True)
        return graph

    def _endpoints(self, topic: str, *, mangled: bool) -> list[Endpoint]:
        found = []
        for publishes, info in (
            (True, self.node.get_publishers_info_by_topic(topic, no_mangle=mangled)),
            (False, self.node.get_subscriptions_info_by_topic(topic, no_mangle=mangled)),
        ):
            for item in info:
                name = _full(item.node_name, item.node_namespace)
                if name == self.own:
                    continue
                hashed = str(item.topic_type_hash)
                known = hashed if hashed.startswith("RIHS01_") else None
                found.append(Endpoint(name, publishes, item.topic_type, known))
        return sorted(found, key=lambda e: (e.node, e.publishes, e.type, e.type_hash or ""))

    def settle(self, wait: float) -> GraphSnapshot:
        """The graph once it stopped changing for a while after another node appeared, or as
        it is after ``wait`` seconds (discovery on loopback takes one to three seconds)."""
        deadline = time.monotonic() + wait
        last, since = self.snapshot(), time.monotonic()
        while time.monotonic() < deadline:
            time.sleep(_POLL)
            current = self.snapshot()
            if current != last:
                last, since = current, time.monotonic()
            elif last.nodes and time.monotonic() - since >= _SETTLED:
                break
        return last

    def describe(self, provider: str, type_name: str, type_hash: str, timeout: float) -> TypeReply:
        """Ask ``provider`` (a node's full name) for ``type_name`` and its sources."""
        srv = importlib.import_module("type_description_interfaces.srv")
        service = f"{provider.rstrip('/')}/get_type_description"
        where = f"{service} ({type_name})"
        client = self.node.create_client(srv.GetTypeDescription, service)
        try:
            if not client.wait_for_service(timeout_sec=timeout):
                raise UserError(f"{where} did not come up within {timeout:g} s")
            request = srv.GetTypeDescription.Request(
                type_name=type_name, type_hash=type_hash, include_type_sources=True
            )
            future = client.call_async(request)
            self.executor.spin_until_future_complete(future, timeout_sec=timeout)
            if not future.done():
                raise UserError(f"{where} did not answer within {timeout:g} s")
            reply = future.result()
        finally:
            self.node.destroy_client(client)
        if not reply.successful:
            raise UserError(f"{where} failed: {reply.failure_reason or '(no reason given)'}")
        described = reply.type_description
        fields = {
            d.type_name: tuple(
                (
                    f.name,
                    f.type.type_id,
                    f.type.capacity,
                    f.type.string_capacity,
                    f.type.nested_type_name,
                )
                for f in d.fields
            )
            for d in (described.type_description, *described.referenced_type_descriptions)
        }
        sources = {s.type_name: (s.encoding, s.raw_file_contents) for s in reply.type_sources}
        return TypeReply(sources, fields)


def _full(name: str, namespace: str) -> str:
    return f"{namespace.rstrip('/')}/{name}"


@contextlib.contextmanager
def ros2_graph() -> Iterator[Graph]:
    """A context and node of our own (hidden, so other tools leave it out), shut down after."""
    rclpy = _import_rclpy()
    context = rclpy.context.Context()
    try:
        rclpy.init(context=context)
    except Exception as exc:  # rclpy raises its own RCLError types; all mean the same here
        raise UserError(f"cannot join the ROS 2 graph: {exc}") from None
    try:
        node = rclpy.create_node(
            f"_unityscaffold_discover_{os.getpid()}",
            context=context,
            start_parameter_services=False,
            enable_rosout=False,
        )
        executor = importlib.import_module("rclpy.executors").SingleThreadedExecutor(
            context=context
        )
        executor.add_node(node)
        try:
            yield Graph(node, executor)
        finally:
            executor.shutdown()
            node.destroy_node()
    finally:
        with contextlib.suppress(Exception):
            context.try_shutdown()
