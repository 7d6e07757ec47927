"""Which fileID each slot of a robot's import gets (``apply/robots/_slots.py``): derived from
the slot's identity (its link by name), whatever the link's position; kept from the lock; or,
for a robot an earlier version imported, the fileID that version derived from the position."""

from __future__ import annotations

from unityscaffold.apply.robots._slots import Slots
from unityscaffold.unity.owned import owned_file_id
from unityscaffold.urdf.objects import ImportedObject, LocalTransform, Role


def robot(*links: str) -> ImportedObject:
    """A robot whose root has ``links`` as children, in that order (``link[i]`` each)."""
    children = tuple(
        ImportedObject(name, Role.LINK, f"link[{i}]", LocalTransform(), ())
        for i, name in enumerate(links)
    )
    return ImportedObject("bot", Role.ROBOT, "robot", LocalTransform(), (), children)


def nothing_there(file_id: int) -> int | None:
    return None


def derived(*parts: str) -> int:
    """The first fileID ``candidate_file_ids`` gives ``parts`` (in an empty scene)."""
    return owned_file_id(parts, 1, nothing_there, set())


def test_a_link_is_known_by_its_name_at_any_position() -> None:
    first = Slots.of("bot", robot("base", "arm"), nothing_there)
    moved = Slots.of("bot", robot("tool", "base", "arm"), nothing_there)
    assert moved.identity("link[2]/visual[0]") == 'link "arm"/visual[0]'
    assert first.file_id("link[1]", "GameObject", 1) == moved.file_id("link[2]", "GameObject", 1)
    assert first.file_id("link[1]", "GameObject", 1) == derived(
        "robot", "bot", 'link "arm"', "GameObject"
    )
    assert moved.file_id("robot", "GameObject", 1) == derived("robot", "bot", "robot", "GameObject")


def test_a_name_with_quotes_or_slashes_is_one_identity() -> None:
    slots = Slots.of("bot", robot('a"/b'), nothing_there)
    assert slots.identity("link[0]/collision[1]/shape") == 'link "a\\"/b"/collision[1]/shape'


def test_a_kept_fileid_is_taken_again_and_recorded_by_identity() -> None:
    def a_gameobject(file_id: int) -> int | None:
        return 1 if file_id == 77 else None

    slots = Slots.of("bot", robot("base", "arm"), a_gameobject, {77}, {'link "arm" GameObject': 77})
    assert slots.file_id("link[1]", "GameObject", 1) == 77
    assert slots.recorded() == (('link "arm" GameObject', 77),)


def test_a_robot_of_the_earlier_scheme_keeps_the_fileids_it_has() -> None:
    """Before identities, fileIDs derived from the position (``link[1]``): a robot imported
    then keeps them, read against the URDF as it is, and the lock records them by identity."""
    earlier = derived("robot", "bot", "link[1]", "GameObject")
    slots = Slots.of("bot", robot("base", "arm"), lambda i: 1 if i == earlier else None, {earlier})
    assert slots.file_id("link[1]", "GameObject", 1) == earlier
    assert slots.recorded() == (('link "arm" GameObject', earlier),)
    # a slot the earlier robot did not have gets its derived fileID
    assert slots.file_id("link[0]", "GameObject", 1) == derived(
        "robot", "bot", 'link "base"', "GameObject"
    )


def test_a_fileid_kept_for_one_slot_is_never_given_to_another_by_position() -> None:
    """The earlier robot's ``link[0]`` fileID, now kept for ``base`` wherever it is, is not
    what a new link at position 0 takes, whichever slot asks first."""
    earlier = derived("robot", "bot", "link[0]", "GameObject")
    slots = Slots.of(
        "bot",
        robot("new", "base"),
        lambda i: 1 if i == earlier else None,
        {earlier},
        {'link "base" GameObject': earlier},
    )
    assert slots.file_id("link[0]", "GameObject", 1) != earlier
    assert slots.file_id("link[1]", "GameObject", 1) == earlier
