"""The two rosbridge 2.x faults after which the ROS 2 action tests run again
(tests/runtime/ros2_actions.py) are recognised only when nothing else went wrong."""

from __future__ import annotations

from tests.runtime.ros2_actions import DECIDED, lost_cancel, lost_goal


def test_a_last_goal_nothing_answered_is_lost_and_any_other_fault_is_not() -> None:
    assert lost_goal(["alpha", "cancel-me"], DECIDED[:1], {"alpha"}) == "cancel-me"
    assert lost_goal(["alpha", "cancel-me"], DECIDED[:1], {"alpha", "cancel-me"}) == ""
    assert lost_goal(["alpha", "cancel-me"], DECIDED[:2], {"alpha"}) == ""  # it did arrive
    assert lost_goal(["cancel-me"], [], set()) == ""  # not the client's order
    assert lost_goal([], [], set()) == ""


def test_a_cancel_the_server_never_saw_is_dropped_and_any_other_fault_is_not() -> None:
    dropped = "the cancel of cancel-me"
    assert lost_cancel(["alpha", "cancel-me"], DECIDED[:2], {"cancel-me"}, []) == dropped
    assert lost_cancel(["alpha", "cancel-me", "reject-me"], DECIDED, {"cancel-me"}, []) == dropped
    assert lost_cancel(["alpha", "cancel-me"], DECIDED[:2], {"cancel-me"}, ["cancel-me"]) == ""
    assert lost_cancel(["alpha", "cancel-me"], DECIDED[:2], set(), []) == ""  # never cancelled
    assert lost_cancel(["alpha", "cancel-me"], DECIDED[:1], {"cancel-me"}, []) == ""
    wrong = [["alpha", True], ["cancel-me", False]]
    assert lost_cancel(["alpha", "cancel-me"], wrong, {"cancel-me"}, []) == ""
    assert lost_cancel(["alpha"], DECIDED[:1], {"cancel-me"}, []) == ""
