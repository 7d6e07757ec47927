"""Property: ``msgs show`` on a mutated real ``.msg``/``.srv``/``.action`` text exits 0 or 2
(never an internal error), and the ROS 1 grammar accepts and refuses what genmsg does.

Mutations are character level (insert a hostile token, cut a span, duplicate a line, add a
separator) on real definitions. genmsg is asked once, for every ROS 1 ``.msg`` and ``.srv``
text the run produced (``genmsg_accepts.py`` under Debian's Python). Where genmsg fails in a
way of its own (an IndexError rather than its errors) its behaviour is not defined and the text
is not compared. The differences docs/ros-rules.md states ("Where we are stricter") are allowed.
Budget: ``EXAMPLES`` texts per ROS version, about 7 s each; UNITYSCAFFOLD_FUZZ_TEXTS raises it.
"""

from __future__ import annotations

import json
import os
import subprocess
from dataclasses import dataclass
from pathlib import Path

import pytest
from helpers import run_cli
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from unityscaffold.errors import LocatedError
from unityscaffold.interfaces import ros1

EXAMPLES = int(os.environ.get("UNITYSCAFFOLD_FUZZ_TEXTS", "150"))
JUDGE = Path(__file__).with_name("genmsg_accepts.py")
HOSTILE = [
    " ",
    "\t",
    "#",
    "=",
    "[",
    "]",
    "[]",
    "[3]",
    "[<=3]",
    "<=",
    "<=5",
    "/",
    "//",
    "msg/",
    "\u00b2",
    "\u0663",
    "9" * 30,
    "'",
    '"',
    "\n",
    "---\n",
    "\r",
    "\x00",
    "\u00e9",
    "_",
    "__",
    "Header",
    "string",
    "int32",
    "-",
    "+",
    "0x",
    "1e400",
    "True",
    "\ufeff",
    "A" * 60,
    "a" * 600,
]
# Refusals of ours where genmsg accepts, each stated in docs/ros-rules.md.
STRICTER = (
    "duplicate constant name",
    "is not a legal constant name",
    "invalid array size",
    "is not a ROS 1 type name",
)


@dataclass(frozen=True)
class Case:
    kind: str
    text: str


def _sources(share: Path, count: int) -> list[Path]:
    files = sorted(
        [*share.glob("*/msg/*.msg"), *share.glob("*/srv/*.srv"), *share.glob("*/action/*.action")]
    )
    step = max(1, len(files) // count)
    return files[::step][:count]


@st.composite
def _mutated(draw: st.DrawFn, sources: list[Path]) -> Case:
    source = draw(st.sampled_from(sources))
    text = source.read_text(encoding="utf-8")
    for _ in range(draw(st.integers(1, 4))):
        at = draw(st.integers(0, len(text)))
        op = draw(st.sampled_from(("insert", "insert", "cut", "line")))
        if op == "insert":
            text = text[:at] + draw(st.sampled_from(HOSTILE)) + text[at:]
        elif op == "cut":
            text = text[:at] + text[at + draw(st.integers(1, 12)) :]
        else:
            lines = text.split("\n")
            line = draw(st.integers(0, len(lines) - 1))
            lines.insert(line, lines[line])
            text = "\n".join(lines)
    return Case(source.suffix[1:], text)


def _show(tmp: Path, ros: str, case: Case) -> int:
    folder = tmp / "ws" / "fuzz_msgs" / case.kind
    folder.mkdir(parents=True, exist_ok=True)
    (folder / f"Fuzz.{case.kind}").write_bytes(case.text.encode("utf-8", "surrogatepass"))
    name = "fuzz_msgs/Fuzz" if case.kind != "action" else "fuzz_msgs/action/Fuzz"
    run = run_cli("msgs", "show", name, "--ros", ros, "--no-env", "--path", str(tmp / "ws"))
    assert "Traceback" not in run.err and "internal error" not in run.err, (case, run.err)
    return run.code


def _ours(case: Case) -> str | None:
    """None when the ROS 1 grammar accepts ``case``, else the first refusal's message."""
    parse = ros1.parse_message if case.kind == "msg" else ros1.parse_service
    try:
        parse(case.text, "fuzz_msgs", "Fuzz", "Fuzz." + case.kind)
    except LocatedError as error:
        return error.diagnostics[0].message
    return None


@pytest.mark.parametrize("ros", ["1", "2"])
def test_mutated_definitions_exit_0_or_2_and_ros1_agrees_with_genmsg(
    ros: str,
    ros1_share: Path,
    ros2_share: Path,
    genmsg_python: Path,
    tmp_path_factory: pytest.TempPathFactory,
) -> None:
    sources = _sources(ros1_share if ros == "1" else ros2_share, 80)
    compared: list[Case] = []

    @given(_mutated(sources))
    @settings(
        max_examples=EXAMPLES,
        deadline=None,
        database=None,
        suppress_health_check=list(HealthCheck),
    )
    def check(case: Case) -> None:
        assert _show(tmp_path_factory.mktemp("text"), ros, case) in (0, 2)
        if ros == "1" and case.kind in ("msg", "srv"):
            compared.append(case)

    check()
    if ros != "1":
        return
    items = [
        {"kind": c.kind, "package": "fuzz_msgs", "name": "Fuzz", "text": c.text} for c in compared
    ]
    done = subprocess.run(
        [str(genmsg_python), str(JUDGE)],
        input=json.dumps(items),
        capture_output=True,
        text=True,
        check=True,
        timeout=300,
    )
    verdicts = json.loads(done.stdout)
    disagreements = []
    for case, verdict in zip(compared, verdicts, strict=True):
        ours = _ours(case)
        if verdict == "undefined" or (verdict == "refuse") == (ours is not None):
            continue
        if verdict == "accept" and ours is not None and any(s in ours for s in STRICTER):
            continue
        disagreements.append((verdict, ours, case.text))
    assert not disagreements, "\n\n".join(
        f"genmsg {v}, we {o!r}:\n{t}" for v, o, t in disagreements
    )
    assert len(compared) > EXAMPLES // 3  # most ROS 1 cases are .msg or .srv and were compared
