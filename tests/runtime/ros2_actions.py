"""What the two ROS 2 action tests (test_action_scripts_run.py, test_actions_ros2.py) share about
the C# client's goals to rclpy's server (data/ros2/action_node.py), and the two failures of
rosbridge 2.x itself after which they run their scenario again: a lost goal (below) and a
dropped cancel (``lost_cancel``).

For each goal, rosbridge 2.x makes a new rclpy ActionClient, waits at most one second for it to
find the server (``SendGoal``'s ``server_timeout_time``, a constructor default rosbridge never
sets: no parameter or message field reaches it) and then sends the goal anyway; when DDS has not
matched the new client's endpoints with the server's by then (seen at a load average of 16), the
goal never reaches the server and nothing answers it (README, limitations). No public behaviour
of rosbridge lengthens that wait, so the tests recognise exactly this outcome and run once more
with a fresh bridge; a goal our code does not send, or sends wrongly, fails both runs."""

from __future__ import annotations

from collections.abc import Collection, Sequence

# The C# client's goals, in the order it sends them: each only once the previous one has ended
# (its result; "reject-me" gets none), so a goal lost on the way is the last one it sends.
GOALS = ("alpha", "cancel-me", "reject-me")
# What rclpy's server decides for each (data/ros2/action_node.py: [dock_id, accepted]).
DECIDED = [["alpha", True], ["cancel-me", True], ["reject-me", False]]


def lost_goal(sent: Sequence[str], decided: list[list[object]], answered: Collection[str]) -> str:
    """The goal rosbridge 2.x lost, when that is all that went wrong with the client's goals:
    ``sent`` (dock ids in the order the C# client sent them) is the start of GOALS, the server
    decided every one of them but the last as it should (``decided``, what it saw), and the
    last got neither feedback nor a result (``answered``: the dock ids that got either).
    Otherwise "" (whatever else is wrong is a failure of its own, never run again)."""
    if not sent or list(sent) != list(GOALS[: len(sent)]):
        return ""
    if decided != DECIDED[: len(sent) - 1] or sent[-1] in answered:
        return ""
    return sent[-1]


def lost_cancel(
    sent: Sequence[str],
    decided: list[list[object]],
    cancelled: Collection[str],
    server_cancel: Collection[str],
) -> str:
    """The cancel rosbridge 2.x dropped, when that is all that went wrong with the client's
    goals: the client sent "alpha" then "cancel-me" (then waited for cancel-me's end, or went on
    with "reject-me" once the server gave up waiting), the server decided each as it should, the
    client cancelled cancel-me at its first feedback (``cancelled``: the dock ids it sent a
    cancel for), and the server never saw a cancel (``server_cancel``). rosbridge 2.x ignores a
    cancel that comes before its action client holds the goal's handle, which it takes from the
    server's acceptance in a callback rclpy runs after that goal's feedback may have gone out
    (``SendGoal.cancel_goal``). Otherwise ""."""
    if list(sent) not in (list(GOALS[:2]), list(GOALS)) or decided != DECIDED[: len(sent)]:
        return ""
    if "cancel-me" not in cancelled or server_cancel:
        return ""
    return "the cancel of cancel-me"
