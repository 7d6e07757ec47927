"""Bad URDFs are refused with every problem located (``path:line:col``) and a hint."""

from __future__ import annotations

from pathlib import Path

import pytest

from unityscaffold.errors import LocatedError, UserError
from unityscaffold.urdf import parse_urdf, read_urdf
from unityscaffold.urdf._xml import MAX_DEPTH

LINK_AB = '<link name="a"/><link name="b"/>'


def joint(name: str, parent: str, child: str, kind: str = "fixed") -> str:
    return (
        f'<joint name="{name}" type="{kind}">'
        f'<parent link="{parent}"/><child link="{child}"/></joint>'
    )


def problems(body: str) -> list[str]:
    """The rendered diagnostics of a URDF whose <robot> holds ``body`` on its second line."""
    raw = f'<robot name="bot">\n{body}\n</robot>\n'.encode()
    with pytest.raises(LocatedError) as caught:
        parse_urdf(raw, "bot.urdf")
    return [d.render() for d in caught.value.diagnostics]


def only(body: str) -> str:
    found = problems(body)
    assert len(found) == 1, found
    return found[0]


def test_elements_nested_past_the_limit_are_located_at_the_first_too_deep() -> None:
    # a plugin's elements are written out recursively: thousands of levels raised
    # RecursionError (exit 3) where a located error belongs
    deep = "<a>" * 2000 + "</a>" * 2000
    text = only(f"<gazebo>{deep}</gazebo>")
    # <robot> and <gazebo> are two levels: the first too deep starts past them and MAX_DEPTH - 2
    column = len("<gazebo>") + 3 * (MAX_DEPTH - 2) + 1
    assert text.startswith(f"bot.urdf:2:{column}: error: elements nested more than {MAX_DEPTH}")
    assert "hint: a URDF's elements nest a few levels" in text


def test_malformed_xml_is_located_where_expat_stopped() -> None:
    with pytest.raises(LocatedError) as caught:
        parse_urdf(b'<robot name="r">\n  <link name="a">\n</robot>\n', "r.urdf")
    text = caught.value.render()
    assert text.startswith("r.urdf:3:3: error: malformed XML: mismatched tag")
    assert "hint:" in text


@pytest.mark.parametrize(
    ("body", "where", "what"),
    [
        ("<link/>", "bot.urdf:2:1:", '<link> has no name="…" attribute'),
        (
            '<link name="a"><inertial><mass value="1"/></inertial></link>',
            "bot.urdf:2:16:",
            "<inertial> has no <inertia> element",
        ),
        (
            '<link name="a"><visual><geometry><cylinder radius="1"/></geometry></visual></link>',
            "bot.urdf:2:34:",
            'no length="…"',
        ),
        (
            '<link name="a"><visual><geometry/></visual></link>',
            "bot.urdf:2:24:",
            "<geometry> has no shape",
        ),
        (
            '<link name="a"><visual><geometry><mesh/></geometry></visual></link>',
            "bot.urdf:2:34:",
            'no filename="…"',
        ),
        (
            LINK_AB + '<joint name="j" type="fixed"><child link="b"/></joint>',
            "bot.urdf:2:33:",
            "<joint> has no <parent> element",
        ),
        (
            LINK_AB + '<joint name="j" type="revolute"><parent link="a"/><child link="b"/>'
            '<limit lower="0"/></joint>',
            "bot.urdf:2:100:",
            'no effort="…"',
        ),
        (
            '<material><color rgba="1 1 1 1"/></material><link name="a"/>',
            "bot.urdf:2:1:",
            '<material> has no name="…"',
        ),
    ],
)
def test_a_missing_required_attribute_or_element_is_located(
    body: str, where: str, what: str
) -> None:
    found = only(body)
    assert found.startswith(where) and what in found, found
    assert "\n  hint: " in found


@pytest.mark.parametrize(
    ("body", "col", "attribute"),
    [
        (
            '<link name="a"><visual><origin xyz="1 2"/>'
            '<geometry><sphere radius="1"/></geometry></visual></link>',
            32,
            "xyz",
        ),
        (
            '<link name="a"><visual><geometry><sphere radius="one"/></geometry></visual></link>',
            42,
            "radius",
        ),
        (
            '<link name="a"><visual><geometry><box size="1 2 nan"/></geometry></visual></link>',
            39,
            "size",
        ),
        (
            '<link name="a"><inertial><mass value="1,5"/>'
            '<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>',
            32,
            "value",
        ),
        ('<material name="m"><color rgba="1 1 1"/></material><link name="a"/>', 27, "rgba"),
        (
            '<link name="a"><visual><geometry><sphere radius="1e39"/></geometry></visual></link>',
            42,
            "radius",
        ),
    ],
)
def test_a_bad_number_is_located_at_its_attribute(body: str, col: int, attribute: str) -> None:
    found = only(body)
    assert found.startswith(f"bot.urdf:2:{col}: error: {attribute}="), found
    assert "decimal numbers" in found


def test_an_unsupported_joint_type_is_refused_with_the_known_ones() -> None:
    found = only(LINK_AB + joint("j", "a", "b", kind="ball"))
    assert found.startswith("bot.urdf:2:49: error: joint 'j' has the unknown type 'ball'")
    assert "revolute, continuous, prismatic, fixed, floating, planar" in found


def test_two_links_with_one_name_are_refused_at_the_second() -> None:
    found = only('<link name="a"/>\n<link name="a"/>')
    assert found.startswith("bot.urdf:3:1: error: a second link named 'a'")


def test_a_joint_naming_a_missing_link_is_refused() -> None:
    found = only(LINK_AB + joint("j", "a", "c") + joint("k", "a", "b"))
    assert "joint 'j' names the child link 'c', which the robot does not have" in found
    assert "hint: links: a, b" in found


def test_more_than_one_root_is_refused_with_the_roots_named() -> None:
    found = only('<link name="a"/>\n<link name="b"/>')
    assert found.startswith("bot.urdf:3:1: error: link 'b' is a second root")
    assert "roots: 'a', 'b'" in found


def test_a_cycle_in_the_joint_tree_is_refused_once_with_its_links() -> None:
    found = only(
        '<link name="r"/><link name="a"/><link name="b"/>'
        + joint("ab", "a", "b")
        + joint("ba", "b", "a")
    )
    assert "the joints form a cycle: a → b → a" in found or "b → a → b" in found, found


def test_a_link_with_two_parent_joints_is_refused() -> None:
    found = only(
        '<link name="a"/><link name="b"/><link name="c"/>'
        + joint("ac", "a", "c")
        + joint("bc", "b", "c")
        + joint("ab", "a", "b")
    )
    assert "link 'c' is the child of a second joint, 'bc'" in found


def test_every_problem_of_a_file_is_reported_not_just_the_first() -> None:
    found = problems(
        '<link name="a"><visual><geometry><sphere radius="x"/></geometry></visual></link>\n'
        '<link name="a"/>\n'
        + joint("j", "a", "nowhere", kind="hinge")
        + "\n"
        + joint("k", "a", "missing")
    )
    assert [text.split(": error: ")[0] for text in found] == [
        "bot.urdf:2:42",
        "bot.urdf:4:17",
        "bot.urdf:3:1",
        "bot.urdf:5:1",
    ]


def test_a_document_that_is_not_a_robot_is_refused() -> None:
    with pytest.raises(LocatedError, match="the document element is <sdf>"):
        parse_urdf(b"<sdf/>", "x.sdf")


def test_an_unreadable_file_is_a_user_error_naming_it(tmp_path: Path) -> None:
    with pytest.raises(UserError, match=r"cannot read the URDF .*nothing\.urdf"):
        read_urdf(tmp_path / "nothing.urdf")
