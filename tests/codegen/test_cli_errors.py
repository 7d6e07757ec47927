"""Bad input to ``scaffold msgs gen``: a clear message, exit 2, no traceback, nothing written."""

from __future__ import annotations

from pathlib import Path

import pytest
from codegen_helpers import DATA

from unityscaffold.cli import main

BAD = DATA / "bad" / "ros1"


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["nowhere_msgs/Nothing"], "unknown ROS 1 type 'nowhere_msgs/Nothing'"),
        (["no_such_package"], "unknown type or package 'no_such_package'"),
        (["cycle_msgs/A"], "cycle: cycle_msgs/A -> cycle_msgs/B -> cycle_msgs/A"),
        (["unknown_msgs/Uses"], "nowhere_msgs/Missing"),
        (["class_member_msgs/Speed"], "'Speed' has the same C# name as the class"),
        (["--namespace", "My.class.Ns", "class_member_msgs"], "not a C# namespace name"),
        ([], "no types given"),
        (
            ["clash_msgs/Thing", "clash_actions/Thing"],
            "would both become C# class RosSharp.RosBridgeClient.MessageTypes.Clash.Thing",
        ),
    ],
)
def test_bad_input_exits_2_with_a_message_and_writes_nothing(
    args: list[str], message: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "out"
    code = main(["msgs", "gen", "--ros", "1", "--path", str(BAD), "--out", str(out), *args])
    captured = capsys.readouterr()
    assert code == 2
    assert message in captured.err
    assert "Traceback" not in captured.err + captured.out
    assert not out.exists()


def test_output_folder_that_is_a_file_is_refused(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "out"
    out.write_text("not a folder")
    code = main(
        [
            "msgs",
            "gen",
            "--ros",
            "1",
            "--path",
            str(DATA / "ros1"),
            "--out",
            str(out),
            "scaffold_test_msgs/Range",
        ]
    )
    err = capsys.readouterr().err
    assert code == 2
    assert "exists and is not a folder" in err
    assert "Traceback" not in err
    assert out.read_text() == "not a folder"


def test_a_file_blocking_a_package_folder_leaves_nothing_half_written(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "out"
    out.mkdir()
    (out / "ScaffoldTest").write_text("in the way")
    code = main(
        [
            "msgs",
            "gen",
            "--ros",
            "1",
            "--path",
            str(DATA / "ros1"),
            "--out",
            str(out),
            "--include-shipped",
            "scaffold_test_msgs/Kitchen",
        ]
    )
    assert code == 2
    assert "is not a folder" in capsys.readouterr().err
    assert sorted(p.name for p in out.iterdir()) == ["ScaffoldTest"]


def test_second_run_writes_nothing_and_reports_skipped_types(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    args = [
        "msgs",
        "gen",
        "--ros",
        "1",
        "--path",
        str(DATA / "ros1"),
        "--out",
        str(tmp_path / "out"),
        "scaffold_test_msgs/Range",
        "geometry_msgs/PoseStamped",
    ]
    assert main(args) == 0
    first = capsys.readouterr().out
    assert "create    ScaffoldTest/msg/Range.cs" in first
    assert "skip      Geometry/msg/PoseStamped.cs (geometry_msgs/PoseStamped): ROS# ships" in first
    stamps = {p: p.stat().st_mtime_ns for p in (tmp_path / "out").rglob("*")}
    assert main(args) == 0
    second = capsys.readouterr().out
    assert "create    " not in second and "update    " not in second
    assert "0 created, 0 updated" in second
    assert stamps == {p: p.stat().st_mtime_ns for p in (tmp_path / "out").rglob("*")}


@pytest.mark.parametrize("namespace", [[], ["--namespace", "My.Ros"]])
def test_a_hyphenated_package_is_refused_with_a_hint_that_works(
    namespace: list[str], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """The hint names the fix (rename the package), not --namespace, which cannot help: the
    package still names a namespace segment under any root."""
    (tmp_path / "src/my-pkg/msg").mkdir(parents=True)
    (tmp_path / "src/my-pkg/msg/Foo.msg").write_text("int32 x\n")
    out = tmp_path / "out"
    args = ["--ros", "1", "--no-env", "--path", str(tmp_path / "src"), "--out", str(out)]
    code = main(["msgs", "gen", *args, *namespace, "my-pkg/Foo"])
    err = capsys.readouterr().err
    assert code == 2
    src = tmp_path / "src" / "my-pkg"
    assert f"{src}: error: package 'my-pkg' cannot become a C# namespace" in err
    assert "rename the package" in err
    assert "--namespace" not in err
    assert not out.exists()


def test_a_package_name_refused_is_shown_where_package_xml_writes_it(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    package = tmp_path / "src" / "pkg_folder"
    (package / "msg").mkdir(parents=True)
    (package / "msg/Foo.msg").write_text("int32 x\n")
    (package / "package.xml").write_text("<package>\n  <name>my-pkg</name>\n</package>\n")
    out = tmp_path / "out"
    args = ["--ros", "2", "--no-env", "--path", str(tmp_path / "src"), "--out", str(out)]
    assert main(["msgs", "gen", *args, "my-pkg/msg/Foo"]) == 2
    err = capsys.readouterr().err
    assert err.startswith(
        f"{package / 'package.xml'}:2:9: error: package 'my-pkg' cannot become a C# namespace"
    )
    assert "      <name>my-pkg</name>\n            ^\n" in err
    assert not out.exists()


def test_a_type_name_that_is_no_class_name_is_shown_at_its_file(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "src/pkg/msg").mkdir(parents=True)
    (tmp_path / "src/pkg/msg/Fo-o.msg").write_text("int32 x\n")
    out = tmp_path / "out"
    args = ["--ros", "1", "--no-env", "--path", str(tmp_path / "src"), "--out", str(out)]
    assert main(["msgs", "gen", *args, "pkg/Fo-o"]) == 2
    err = capsys.readouterr().err
    where = tmp_path / "src/pkg/msg/Fo-o.msg"
    assert err.startswith(f"{where}: error: type name 'Fo-o' cannot become a C# class name")
    assert "rename the file" in err
    assert not out.exists()
