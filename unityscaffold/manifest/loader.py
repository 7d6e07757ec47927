"""Load ``robot.yaml``: YAML with positions, every key checked, all errors reported at once."""

from __future__ import annotations

from pathlib import Path

from unityscaffold.errors import Diagnostic, DiagnosticSink, LocatedError, SourceLocation, UserError
from unityscaffold.fileout import real_path
from unityscaffold.interfaces.model import Dialect
from unityscaffold.manifest import _spec as spec
from unityscaffold.manifest._checks import check_across
from unityscaffold.manifest._connector import ConnectorPlace, read_connector
from unityscaffold.manifest._entries import (
    EXPECT_SCENE,
    Context,
    locations,
    read_action,
    read_component,
    read_service,
    read_topic,
)
from unityscaffold.manifest._objects import read_object
from unityscaffold.manifest._paths import folder_path, project_path
from unityscaffold.manifest._read import Reader
from unityscaffold.manifest._robots import read_robot
from unityscaffold.manifest._yaml import YEntry, YMap, YScalar, compose
from unityscaffold.manifest.model import MANIFEST_VERSION, Manifest, is_csharp_identifier
from unityscaffold.manifest.runtime import Runtime

__all__ = ["load_manifest", "parse_manifest"]


def load_manifest(path: Path) -> Manifest:
    """Read and validate the manifest at ``path``; raises ``LocatedError`` or ``UserError``.

    Messages name the file as ``path`` was given (``robot.yaml:3:7``); the model's paths are
    absolute.
    """
    try:
        raw = Path(path).read_bytes()
    except FileNotFoundError:
        raise UserError(
            f"manifest {path} does not exist",
            hint="create one with 'scaffold init', or pass its path (without one, scaffold "
            "looks for robot.yaml here and in the folders above, up to the repository's root)",
        ) from None
    except IsADirectoryError:
        raise UserError(
            f"{path} is a folder, not a manifest file",
            hint=f"pass the manifest inside it, e.g. {Path(path) / 'robot.yaml'}",
        ) from None
    except OSError as exc:
        raise UserError(f"cannot read manifest {path}: {exc.strerror or exc}") from None
    try:
        text = raw.decode("utf-8-sig")  # an editor's BOM is harmless
    except UnicodeDecodeError as exc:
        raise LocatedError.at(
            SourceLocation.at_byte(str(path), raw, exc.start),
            f"the manifest is not UTF-8 text (byte 0x{raw[exc.start]:02x})",
            hint="save it as UTF-8",
        ) from None
    return parse_manifest(text, Path(path))


def parse_manifest(text: str, path: Path) -> Manifest:
    """Validate manifest ``text`` as if read from ``path`` (which locates the project)."""
    shown = str(path)
    root = compose(text, shown)
    if root is None or (isinstance(root, YScalar) and root.value is None):
        first = next(iter(text.splitlines()), "")
        raise LocatedError.at(
            SourceLocation(shown, 1, 1, first),
            "the manifest is empty",
            expected="a mapping with at least 'version' and 'ros'",
            hint="start from the template that 'scaffold init' writes",
        )
    sink = DiagnosticSink()
    reader = Reader(sink)
    top = reader.mapping(root, spec.TOP)
    manifest = None if top is None else _build(reader, top, Path(path).absolute())
    if sink.errors or manifest is None:
        raise LocatedError(sorted(sink.errors, key=_position))
    return manifest


def _position(d: Diagnostic) -> tuple[int, int]:
    return (d.location.line, d.location.col)


def _build(r: Reader, top: YMap, path: Path) -> Manifest | None:
    version = _version(r, top)
    ros = r.whole(top, "ros", "1 or 2")
    if ros is not None and ros not in (1, 2):
        r.invalid(top.get("ros"), "1 or 2")  # type: ignore[arg-type]
        ros = None
    runtime = _runtime(r, top)
    project_root = _project_root(r, top, path.parent)
    output_dir = _output(r, top, project_root)
    scene = _top_scene(r, top, project_root)
    create = r.boolean(top, "create_gameobjects")
    connector = read_connector(r, top, runtime, ConnectorPlace(project_root, scene))
    ctx = Context(
        project_root,
        scene,
        top.get("scene") is not None,
        True if create is None else create,
        connector.gameobject,
        ros,
        runtime,
    )
    topics = [read_topic(r, n, ctx) for n in r.items(top, "topics")]
    services = [read_service(r, n, ctx) for n in r.items(top, "services")]
    actions = [read_action(r, n, ctx) for n in r.items(top, "actions")]
    components = [read_component(r, n, ctx) for n in r.items(top, "components")]
    objects = [read_object(r, n, ctx) for n in r.items(top, "objects")]
    robots = [read_robot(r, n, ctx, path.parent) for n in r.items(top, "robots")]
    good_topics = tuple(t for t in topics if t is not None)
    good_services = tuple(s for s in services if s is not None)
    good_actions = tuple(a for a in actions if a is not None)
    good_components = tuple(c for c in components if c is not None)
    good_objects = tuple(o for o in objects if o is not None)
    check_across(
        r, good_topics, good_services, good_components, good_objects, good_actions, ros=ros
    )
    if version is None or ros is None:
        return None
    include = r.boolean(top, "include_shipped")
    if include and runtime is Runtime.TCP_CONNECTOR:
        r.error(
            top.get("include_shipped").value.location,  # type: ignore[union-attr]
            "include_shipped cannot be used with runtime: ros-tcp-connector: the connector "
            "registers one class per ROS name, so a second class for a type it ships would "
            "race its own",
            hint="drop the key (the connector's shipped classes are used); `namespace:` puts "
            "the generated classes under a root of your own",
        )
    return Manifest(
        path=path,
        version=version,
        ros=Dialect(ros),
        project_root=project_root,
        output_dir=output_dir,
        namespace=_namespace(r, top),
        include_shipped=bool(include),
        interfaces=_interfaces(r, top, path.parent),
        scene=scene,
        create_gameobjects=ctx.create,
        connector=connector,
        topics=good_topics,
        services=good_services,
        components=good_components,
        locations=locations(top),
        objects=good_objects,
        actions=good_actions,
        robots=tuple(robot for robot in robots if robot is not None),
        runtime=runtime,
    )


def _runtime(r: Reader, top: YMap) -> Runtime:
    choice = r.choice(top, "runtime", [x.value for x in Runtime])
    return Runtime(choice) if choice else Runtime.ROS_SHARP


def _version(r: Reader, top: YMap) -> int | None:
    entry = top.get("version")
    value = r.whole(top, "version", str(MANIFEST_VERSION))
    if entry is not None and isinstance(value, int) and value != MANIFEST_VERSION:
        r.error(
            entry.value.location,
            f"unsupported manifest version {value}",
            expected=str(MANIFEST_VERSION),
            hint=f"this scaffold reads manifest version {MANIFEST_VERSION}; "
            "upgrade unityscaffold for newer manifests",
        )
        return None
    return value if isinstance(value, int) else None


def _project_root(r: Reader, top: YMap, base: Path) -> Path:
    entry = top.get("project")
    value = r.text(top, "project", "a folder relative to the manifest")
    if entry is None or value is None:
        return real_path(base)
    return folder_path(r, entry, value, base, allow_absolute=False) or real_path(base)


def _output(r: Reader, top: YMap, project_root: Path) -> Path:
    default = spec.TOP.key("output").default
    assert isinstance(default, str)
    entry = top.get("output")
    expected = "a folder inside Assets/, relative to the project"
    value = r.text(top, "output", expected)
    if entry is None or value is None:
        return project_root / default
    rel = project_path(r, entry, value, project_root, expected=expected, under="Assets")
    return project_root / (rel or default)


def _top_scene(r: Reader, top: YMap, project_root: Path) -> str | None:
    entry = top.get("scene")
    value = r.text(top, "scene", EXPECT_SCENE, spec.SCENE, hint="a scene file ends in .unity")
    if entry is None or value is None:
        return None
    return project_path(r, entry, value, project_root, expected=EXPECT_SCENE)


def _namespace(r: Reader, top: YMap) -> str | None:
    value = r.text(top, "namespace", "a C# namespace such as MyRobot.Ros", spec.NAMESPACE)
    keywords = [p for p in (value or "").split(".") if p and not is_csharp_identifier(p)]
    entry = top.get("namespace")
    if keywords and entry is not None:
        hint = f"'{keywords[0]}' is a C# keyword"
        r.invalid(entry, "a C# namespace such as MyRobot.Ros", hint=hint)
        return None
    return value


def _interfaces(r: Reader, top: YMap, base: Path) -> tuple[Path, ...]:
    folders = []
    entry = top.get("interfaces")
    for node in r.items(top, "interfaces"):
        if not (isinstance(node, YScalar) and isinstance(node.value, str) and node.value):
            r.error(
                node.location,
                "invalid interfaces folder",
                expected="a folder path, relative to the manifest",
            )
            continue
        assert entry is not None
        folder = folder_path(
            r, YEntry(entry.key, entry.key_location, node), node.value, base, allow_absolute=True
        )
        if folder is not None:
            folders.append(folder)
    return tuple(folders)
