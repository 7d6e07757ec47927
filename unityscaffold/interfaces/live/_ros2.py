"""``discover --ros2``: topics, services and actions straight from the ROS 2 graph.

Names and types come from the graph; a topic's direction from who publishes and subscribes;
an action's role from who publishes its status. Every RIHS01 hash the graph reports is kept
(a topic's, and for services and actions those of the hidden topics that carry their
requests and replies), so the definitions can be checked against them. A topic type no local
package defines is asked of a node that uses it, through its ``~/get_type_description``;
Jazzy answers only for a type named with its hash, which the graph gives for topics alone, so
a service or action type must be installed or in the manifest's interfaces.
"""

from __future__ import annotations

from collections.abc import Callable

from unityscaffold.errors import UserError
from unityscaffold.interfaces.live._graph import Endpoint, Graph, GraphSnapshot, ros2_graph
from unityscaffold.interfaces.live._typedesc import full_text_from_reply, is_message_name
from unityscaffold.interfaces.live.model import (
    Direction,
    DiscoveredAction,
    DiscoveredService,
    DiscoveredTopic,
    Discovery,
    NameFilter,
    Progress,
)
from unityscaffold.interfaces.model import Dialect

__all__ = ["discover_graph"]

ORIGIN = "the ROS 2 graph"
Known = Callable[[str], bool]  # whether a local package defines a type


def discover_graph(
    *,
    wait: float,
    timeout: float,
    names: NameFilter,
    known: Known,
    progress: Progress | None = None,
) -> Discovery:
    """What the graph shows after ``wait`` seconds at most; ``known`` tells which types need
    no type description from the nodes."""
    with ros2_graph() as graph:
        snapshot = graph.settle(wait)
        hashes: dict[tuple[str, str], str] = {}
        warnings: list[str] = []
        topics = _topics(snapshot, names, hashes, warnings)
        services = _services(snapshot, names, hashes, warnings)
        actions = _actions(snapshot, names, hashes)
        if not snapshot.nodes:
            warnings.append(f"no other ROS 2 node seen within {wait:g} s")
        described = []
        for done, topic in enumerate(topics, start=1):
            if not known(topic.type):
                topic = _described(graph, snapshot, topic, hashes, timeout, warnings)
            described.append(topic)
            if progress is not None:
                progress(done, len(topics), topic.name)
    return Discovery(
        Dialect.ROS2,
        ORIGIN,
        tuple(described),
        tuple(services),
        tuple(sorted(set(warnings))),
        tuple(actions),
        tuple(sorted((t, h, n) for (n, t), h in hashes.items())),
    )


def _hidden(name: str) -> bool:
    return any(token.startswith("_") for token in name.split("/"))


def _visible(name: str, snapshot: GraphSnapshot, names: NameFilter) -> bool:
    in_action = any(name.startswith(f"{a}/_action/") for a in snapshot.actions)
    if in_action or (_hidden(name) and not names.include_system):
        return False
    return names.accepts(name)


def _one_type(name: str, types: list[str], warnings: list[str]) -> str:
    if len(types) > 1:
        warnings.append(f"{name} has several types ({', '.join(types)}): {types[0]} is used")
    return types[0]


def _hash_of(
    endpoints: list[Endpoint], name: str, type_name: str, warnings: list[str]
) -> str | None:
    found = sorted({e.type_hash for e in endpoints if e.type_hash})
    if len(found) > 1:
        warnings.append(
            f"{name}: nodes use {type_name} with different definitions ({', '.join(found)}); "
            f"{found[0]} is checked"
        )
    return found[0] if found else None


def _topics(
    snapshot: GraphSnapshot,
    names: NameFilter,
    hashes: dict[tuple[str, str], str],
    warnings: list[str],
) -> list[DiscoveredTopic]:
    topics = []
    for name, types in sorted(snapshot.topics.items()):
        if not _visible(name, snapshot, names):
            continue
        kind = _one_type(name, types, warnings)
        endpoints = [e for e in snapshot.endpoints.get(name, []) if e.type == kind]
        direction = Direction.from_graph(
            any(e.publishes for e in endpoints), any(not e.publishes for e in endpoints)
        )
        found = _hash_of(endpoints, name, kind, warnings)
        if found:
            hashes[(name, kind)] = found
        topics.append(DiscoveredTopic(name, kind, direction))
    return topics


def _halves(snapshot: GraphSnapshot, service: str, kind: str) -> dict[str, str]:
    """The hashes of a service's request and response, from the topics that carry them."""
    found = {}
    for prefix, suffix, half in (("rq", "Request", "_Request"), ("rr", "Reply", "_Response")):
        endpoints = snapshot.endpoints.get(f"{prefix}{service}{suffix}", [])
        hashes = sorted({e.type_hash for e in endpoints if e.type_hash})
        if hashes:
            found[kind + half] = hashes[0]
    return found


def _services(
    snapshot: GraphSnapshot,
    names: NameFilter,
    hashes: dict[tuple[str, str], str],
    warnings: list[str],
) -> list[DiscoveredService]:
    services = []
    for name, types in sorted(snapshot.services.items()):
        if not _visible(name, snapshot, names):
            continue
        kind = _one_type(name, types, warnings)
        hashes.update({(name, half): h for half, h in _halves(snapshot, name, kind).items()})
        # a server reads the requests; a graph with callers only wants Unity to serve it
        requests = snapshot.endpoints.get(f"rq{name}Request", [])
        served = any(not e.publishes for e in requests) or not requests
        services.append(DiscoveredService(name, kind, role="client" if served else "server"))
    return services


def _actions(
    snapshot: GraphSnapshot, names: NameFilter, hashes: dict[tuple[str, str], str]
) -> list[DiscoveredAction]:
    actions = []
    for name, types in sorted(snapshot.actions.items()):
        if not names.accepts(name):
            continue
        kind = types[0]
        status = snapshot.endpoints.get(f"{name}/_action/status", [])
        # Unity's role: a client when the graph serves the action (its server publishes the
        # status), a server when the graph only has clients (they subscribe to it).
        role = "client" if any(e.publishes for e in status) else "server" if status else None
        feedback = snapshot.endpoints.get(f"{name}/_action/feedback", [])
        found = {f"{kind}_FeedbackMessage": h for h in {e.type_hash for e in feedback} if h}
        for service, part in (("send_goal", "_SendGoal"), ("get_result", "_GetResult")):
            found.update(_halves(snapshot, f"{name}/_action/{service}", kind + part))
        hashes.update({(name, t): h for t, h in found.items()})
        actions.append(DiscoveredAction(name, kind, role, ()))
    return actions


def _described(
    graph: Graph,
    snapshot: GraphSnapshot,
    topic: DiscoveredTopic,
    hashes: dict[tuple[str, str], str],
    timeout: float,
    warnings: list[str],
) -> DiscoveredTopic:
    """``topic`` with the definition a node that uses it describes, or as it was (warned)."""
    type_hash = hashes.get((topic.name, topic.type))
    providers = sorted({e.node for e in snapshot.endpoints.get(topic.name, [])})
    if type_hash is None or not providers or not is_message_name(topic.type):
        return topic
    try:
        reply = graph.describe(providers[0], topic.type, type_hash, timeout)
        text, lossy = full_text_from_reply(topic.type, reply)
    except (UserError, ValueError) as error:
        why = error.message if isinstance(error, UserError) else str(error)
        warnings.append(f"no definition of {topic.type} for {topic.name}: {why}")
        return topic
    if lossy:
        warnings.append(
            f"{providers[0]} sent no source for {', '.join(lossy)}: written from its field "
            "descriptions, without comments, constants or default values"
        )
    return DiscoveredTopic(topic.name, topic.type, topic.direction, None, text)
