"""Full definition texts split back into the files they were made of, byte for byte."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given
from hypothesis import strategies as st

from unityscaffold.errors import UserError
from unityscaffold.interfaces.live import DiscoveredTopic, Discovery
from unityscaffold.interfaces.live.definitions import split_full_text, stage_definitions
from unityscaffold.interfaces.model import Dialect

REFERENCE = Path(__file__).parent.parent / "interfaces" / "genmsg_reference.py"


@pytest.fixture(scope="module")
def every_debian_message(genmsg_python: Path, ros1_share: Path) -> dict[str, Any]:
    output = subprocess.run(
        [str(genmsg_python), str(REFERENCE), str(ros1_share)],
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    return {
        name: entry for name, entry in json.loads(output.stdout).items() if "definition" in entry
    }


def test_every_debian_message_splits_into_its_own_files(
    every_debian_message: dict[str, Any], ros1_share: Path
) -> None:
    assert len(every_debian_message) > 150
    for name, entry in every_debian_message.items():
        pieces = split_full_text(name, entry["definition"])
        assert f"{pieces[0].package}/{pieces[0].name}" == name
        for piece in pieces:
            path = ros1_share / piece.package / "msg" / f"{piece.name}.msg"
            assert piece.text == path.read_text(), f"{name}: {piece.package}/{piece.name}"


_line = st.text(st.sampled_from("abc XYZ_/#=[]0123456789\t"), max_size=30)
_body = st.lists(_line, max_size=5).map(lambda lines: "\n".join(lines) + "\n")


@given(root=_body, dependencies=st.lists(_body, max_size=4))
def test_splitting_inverts_genmsgs_joining(root: str, dependencies: list[str]) -> None:
    text = root + "\n"
    for index, body in enumerate(dependencies):
        text += "=" * 80 + f"\nMSG: pkg/Dep{index}\n" + body + "\n"
    pieces = split_full_text("pkg/Root", text[:-1])
    assert [p.text for p in pieces] == [root, *dependencies]
    assert [p.name for p in pieces] == ["Root", *(f"Dep{i}" for i in range(len(dependencies)))]


def test_ros2_names_with_msg_are_accepted() -> None:
    pieces = split_full_text("pkg/msg/A", "B b\n\n" + "=" * 80 + "\nMSG: pkg/msg/B\nint32 x")
    assert [(p.package, p.name, p.text) for p in pieces] == [
        ("pkg", "A", "B b\n"),
        ("pkg", "B", "int32 x"),
    ]


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("=" * 80 + "\nIDL: pkg/msg/A\nmodule pkg {};", "is in IDL form"),
        ("x\n" + "=" * 80 + "\nIDL: pkg/msg/B\nmodule", "embeds pkg/msg/B in IDL form"),
        ("x\n" + "=" * 80 + "\nMSG: not a type\nint32 x", "names a type 'not a type'"),
    ],
)
def test_unusable_definitions_are_refused(text: str, message: str) -> None:
    with pytest.raises(UserError, match=message):
        split_full_text("pkg/msg/A", text)


def test_an_unparsable_definition_names_its_type_and_leaves_nothing(tmp_path: Path) -> None:
    found = Discovery(
        Dialect.ROS1,
        "test",
        (DiscoveredTopic("/a", "pkg/A", md5="0" * 32, definition="int32[3][2] x\n"),),
    )
    with pytest.raises(
        UserError, match="the definition of pkg/A reported by test does not parse: line 1"
    ):
        stage_definitions(found, tmp_path / "cache")
    assert list(tmp_path.iterdir()) == []


def test_a_reconstruction_with_the_wrong_md5_is_refused(tmp_path: Path) -> None:
    found = Discovery(
        Dialect.ROS1,
        "test",
        (DiscoveredTopic("/a", "pkg/A", md5="0" * 32, definition="int32 x\n"),),
    )
    with pytest.raises(UserError, match="md5sum mismatch for pkg/A \\(used by /a\\)"):
        stage_definitions(found, tmp_path / "cache")
    assert list(tmp_path.iterdir()) == []
