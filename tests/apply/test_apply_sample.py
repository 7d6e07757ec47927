"""``scaffold apply`` end to end on copies of the sample project: idempotence, drift, pruning,
hand edits, and the committed sample being in sync."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
from helpers import assert_same_tree, run_cli, snapshot

REPO = Path(__file__).resolve().parents[2]
SAMPLE = REPO / "sample_project"


@pytest.fixture
def sample(tmp_path: Path) -> Path:
    copy = tmp_path / "sample_project"
    shutil.copytree(SAMPLE, copy)
    return copy


def test_the_committed_sample_matches_its_manifest():
    before = snapshot(SAMPLE)
    run = run_cli("apply", "--check", str(SAMPLE / "robot.yaml"))
    assert run.code == 0, run.out + run.err
    assert "the project matches the manifest" in run.out
    assert snapshot(SAMPLE) == before


def test_apply_from_clean_writes_what_the_manifest_asks_and_a_second_run_writes_nothing(sample):
    shutil.rmtree(sample / "unity" / "Assets" / "RosGenerated")
    (sample / "unity" / "Assets" / "RosGenerated.meta").unlink()
    (sample / "robot.lock.json").unlink()
    shutil.copy(
        REPO / "unityscaffold" / "templates" / "unity_project" / "Assets" / "Scenes" / "Main.unity",
        sample / "unity" / "Assets" / "Scenes" / "Main.unity",
    )
    first = run_cli("apply", str(sample / "robot.yaml"))
    assert first.code == 0, first.err
    assert "add CmdVelPublisher to Robot" in first.out
    assert "add ScanSubscriber to Robot/Lidar" in first.out
    # The same bytes as the committed sample: apply is deterministic.
    assert_same_tree(sample, SAMPLE, hint="apply on a clean copy must rebuild the committed sample")
    after_first = snapshot(sample)
    second = run_cli("apply", str(sample / "robot.yaml"))
    assert second.code == 0
    assert "wrote 0 files, removed 0" in second.out
    assert snapshot(sample) == after_first


def test_check_reports_drift_after_a_manual_scene_edit_and_apply_repairs_it(sample):
    scene = sample / "unity" / "Assets" / "Scenes" / "Main.unity"
    text = scene.read_text()
    assert "  Topic: /odom\n" in text
    scene.write_text(text.replace("  Topic: /odom\n", "  Topic: /odometry\n"))
    check = run_cli("apply", "--check", str(sample / "robot.yaml"))
    assert check.code == 1
    assert "update  Assets/Scenes/Main.unity" in check.out
    assert "update OdomSubscriber on Robot" in check.out
    repaired = run_cli("apply", str(sample / "robot.yaml"))
    assert repaired.code == 0
    assert scene.read_text() == text


def test_check_reports_drift_after_a_manifest_change(sample):
    manifest = sample / "robot.yaml"
    manifest.write_text(manifest.read_text().replace("rate: 10", "rate: 20"))
    check = run_cli("apply", "--check", str(manifest))
    assert check.code == 1
    plan = run_cli("plan", str(manifest))
    assert "-  Rate: 10\n+  Rate: 20\n" in plan.out


def test_removing_a_topic_prunes_its_files_and_component_but_not_edited_user_code(sample):
    manifest = sample / "robot.yaml"
    scripts = sample / "unity" / "Assets" / "RosGenerated" / "Scripts"
    user_scan = scripts / "ScanSubscriber.User.cs"
    user_scan.write_text(
        user_scan.read_text().replace("// Runs on", "Debug.Log(message); // Runs on")
    )
    text = manifest.read_text()
    for topic in ("/scan", "/odom"):
        start = text.index(f"  - {{name: {topic},")
        end = text.index("\n  - ", start + 1)
        text = text[:start] + text[end + 1 :]
    manifest.write_text(text)
    run = run_cli("apply", str(manifest))
    assert run.code == 0, run.err
    assert not (scripts / "OdomSubscriber.cs").exists()
    assert not (scripts / "OdomSubscriber.User.cs").exists()  # untouched: removed with its script
    # Edited by the user: kept, with its generated half so that the project still compiles.
    assert user_scan.exists() and (scripts / "ScanSubscriber.cs").exists()
    assert "kept Assets/RosGenerated/Scripts/ScanSubscriber.User.cs (you edited it)" in run.out
    again = run_cli("apply", str(manifest))
    assert again.code == 0 and "kept " not in again.out  # said once, not on every run
    scene = (sample / "unity" / "Assets" / "Scenes" / "Main.unity").read_text()
    assert "Topic: /odom\n" not in scene and "Topic: /scan\n" not in scene
    assert "remove topic /odom from Robot" in run.out
    lock = json.loads((sample / "robot.lock.json").read_text())
    assert not any("Odom" in path for path in lock["files"])
    assert run_cli("apply", "--check", str(manifest)).code == 0


def test_an_edited_message_class_of_a_dropped_type_is_kept_and_said_so_once(sample):
    manifest = sample / "robot.yaml"
    messages = sample / "unity" / "Assets" / "RosGenerated" / "Messages" / "Diffbot" / "msg"
    status = messages / "BaseStatus.cs"
    status.write_text(status.read_text() + "// mine\n")
    text = manifest.read_text()
    without = "\n".join(line for line in text.split("\n") if "/base_status" not in line)
    manifest.write_text(without)
    note = "kept Assets/RosGenerated/Messages/Diffbot/msg/BaseStatus.cs: edited since apply"
    assert note in run_cli("plan", str(manifest)).out  # a plan writes nothing: said again
    first = run_cli("apply", str(manifest))
    assert first.code == 0 and note in first.out
    assert status.exists() and (messages / "BaseStatus.cs.meta").exists()
    assert not (messages / "WheelState.cs").exists()  # untouched: pruned
    again = run_cli("apply", str(manifest))
    assert again.code == 0 and "kept " not in again.out  # said once, not on every run
    assert run_cli("apply", "--check", str(manifest)).code == 0
    # Asked for again, then dropped again: a new decision, told again.
    manifest.write_text(text)
    assert run_cli("apply", "--force", str(manifest)).code == 0
    status.write_text(status.read_text() + "// mine\n")
    manifest.write_text(without)
    assert note in run_cli("apply", str(manifest)).out


def test_a_hand_edited_generated_file_stops_apply_until_forced(sample):
    plumbing = sample / "unity" / "Assets" / "RosGenerated" / "Scripts" / "CmdVelPublisher.cs"
    original = plumbing.read_text()
    plumbing.write_text(original.replace("Rate <= 0f", "Rate < 0f"))
    manifest = sample / "robot.yaml"
    manifest.write_text(manifest.read_text().replace("rate: 10", "rate: 20"))
    before = snapshot(sample)
    run = run_cli("apply", str(manifest))
    assert run.code == 2
    assert "edited by hand" in run.err and "CmdVelPublisher.cs" in run.err
    assert "move your code into the matching .User.cs" in run.err
    assert "message class" not in run.err
    assert "Traceback" not in run.err
    assert snapshot(sample) == before
    forced = run_cli("apply", "--force", str(manifest))
    assert forced.code == 0, forced.err
    assert "Rate <= 0f" in plumbing.read_text()


def test_a_hand_edited_message_class_gets_a_hint_that_fits_it(sample):
    # a message class has no .User.cs half: the hint must not send the user looking for one
    message = sample / "unity/Assets/RosGenerated/Messages/Diffbot/msg/BaseStatus.cs"
    message.write_text(message.read_text() + "// mine\n")
    run = run_cli("apply", str(sample / "robot.yaml"))
    assert run.code == 2 and "BaseStatus.cs" in run.err
    hint = run.err.split("hint: ", 1)[1]
    assert ".User.cs" not in hint and "through its .msg/.srv/.action definition" in hint


def test_dry_run_and_plan_write_nothing(sample):
    manifest = sample / "robot.yaml"
    manifest.write_text(
        manifest.read_text().replace("url: ws://localhost:9090", "url: ws://robot:9090")
    )
    before = snapshot(sample)
    for args in (("plan", str(manifest)), ("apply", "--dry-run", str(manifest))):
        run = run_cli(*args)
        assert run.code == 0
        assert "+  RosBridgeServerUrl: ws://robot:9090" in run.out
    assert snapshot(sample) == before


def test_json_output_for_scripts(sample):
    manifest = sample / "robot.yaml"
    manifest.write_text(manifest.read_text().replace("rate: 10", "rate: 5"))
    run = run_cli("apply", "--check", "--json", str(manifest))
    assert run.code == 1
    data = json.loads(run.out)
    assert data["in_sync"] is False
    assert {"path": "Assets/Scenes/Main.unity", "action": "update"} in data["files"]


def test_a_component_the_user_attached_is_adopted_but_never_pruned(sample):
    """A RosConnector the user put on a GameObject before the manifest named it stays theirs."""
    manifest = sample / "robot.yaml"
    scene = sample / "unity" / "Assets" / "Scenes" / "Main.unity"
    # Pretend the user made the connector: drop it from the lock (apply then sees it as theirs).
    lock = json.loads((sample / "robot.lock.json").read_text())
    lock["components"] = [c for c in lock["components"] if c["entry"] != "connector"]
    (sample / "robot.lock.json").write_text(json.dumps(lock, indent=2) + "\n")
    assert run_cli("apply", str(manifest)).code == 0
    manifest.write_text(
        manifest.read_text().replace("gameobject: RosConnector\n", "gameobject: Bridge\n")
    )
    run = run_cli("apply", str(manifest))
    assert run.code == 0, run.err
    assert "add RosConnector to Bridge" in run.out
    assert "remove RosConnector" not in run.out and "remove connector" not in run.out
    assert scene.read_text().count("guid: ff98778ae051cfd40a6e4effdf851ebd") == 2


def test_an_untouched_user_half_follows_a_type_change_and_an_edited_one_gets_a_note(sample):
    manifest = sample / "robot.yaml"
    scripts = sample / "unity" / "Assets" / "RosGenerated" / "Scripts"
    edited = scripts / "BaseStatusSubscriber.User.cs"
    edited.write_text(edited.read_text().replace("// Runs on", "Debug.Log(message); // Runs on"))
    text = manifest.read_text().replace(
        "type: nav_msgs/Odometry", "type: geometry_msgs/PoseStamped"
    )
    manifest.write_text(
        text.replace("type: diffbot_msgs/BaseStatus", "type: diffbot_msgs/WheelState")
    )
    run = run_cli("apply", str(manifest))
    assert run.code == 0, run.err
    untouched = (scripts / "OdomSubscriber.User.cs").read_text()
    assert "Geometry.PoseStamped message" in untouched and "Nav.Odometry" not in untouched
    assert "Diffbot.BaseStatus message" in edited.read_text()  # the user's file is theirs
    assert (
        "BaseStatusSubscriber.User.cs was written for an earlier version of "
        "BaseStatusSubscriber, which is now generated for topic /base_status;" in run.out
    )
    second = run_cli("apply", str(manifest))
    assert second.out.endswith("wrote 0 files, removed 0\n")
    assert "written for an earlier version" not in second.out  # said once, when it changed


def test_a_connector_chosen_in_unity_for_a_script_is_kept(sample):
    # a scene with two RosConnectors: the user points /odom's script at the second one
    scene = sample / "unity" / "Assets" / "Scenes" / "Main.unity"
    connector_guid = "ff98778ae051cfd40a6e4effdf851ebd"
    second = run_cli(
        "scene", "attach", str(scene), "-g", "Second", "--create", "--guid", connector_guid
    )
    assert second.code == 0, second.err
    odom = sample / "unity" / "Assets" / "RosGenerated" / "Scripts" / "OdomSubscriber.cs"
    chosen = run_cli(
        "scene",
        "attach",
        str(scene),
        "-g",
        "Robot",
        "--script",
        str(odom),
        "--set",
        "Connector=@Second:RosConnector",
    )
    assert chosen.code == 0, chosen.err
    picked = scene.read_text()
    manifest = str(sample / "robot.yaml")
    run = run_cli("apply", manifest)
    assert run.code == 0, run.err
    assert scene.read_text() == picked  # was: Connector reset to the manifest's connector
    assert run_cli("apply", "--check", manifest).code == 0


def test_gameobjects_apply_made_go_with_their_entry_unless_something_else_is_on_them(sample):
    manifest = sample / "robot.yaml"
    scene = sample / "unity" / "Assets" / "Scenes" / "Main.unity"
    original_manifest, original_scene = manifest.read_text(), scene.read_bytes()
    entries = "".join(
        f"  - {{name: /{n.lower()}, type: sensor_msgs/{t}, direction: subscribe, "
        f"gameobject: Robot/Sensors/{n}}}\n"
        for n, t in (("Imu", "Imu"), ("Temp", "Temperature"))
    )
    manifest.write_text(original_manifest.replace("\nservices:", entries + "\nservices:"))
    assert run_cli("apply", str(manifest)).code == 0
    # the user puts a component of their own on Temp: that GameObject is theirs now
    user_script = "0123456789abcdef0123456789abcdef"
    added = run_cli(
        "scene", "attach", str(scene), "-g", "Robot/Sensors/Temp", "--guid", user_script
    )
    assert added.code == 0, added.err
    manifest.write_text(original_manifest)
    run = run_cli("apply", str(manifest))
    assert run.code == 0, run.err
    assert "remove GameObject Robot/Sensors/Imu (apply made it; nothing else is on it)" in run.out
    assert "remove GameObject Robot/Sensors/Temp" not in run.out
    assert "remove GameObject Robot/Sensors " not in run.out  # Temp is still under it
    text = scene.read_text()
    assert "m_Name: Imu\n" not in text and "m_Name: Temp\n" in text and user_script in text
    assert run_cli("apply", "--check", str(manifest)).code == 0
    # once the user's component goes, nothing brings the objects back or removes them: not ours
    scene.write_bytes(original_scene)
    assert run_cli("apply", "--check", str(manifest)).code == 0
