"""Fixtures for the scene patcher tests: the real Unity files and an independent reader."""

from __future__ import annotations

from pathlib import Path

import pytest
from unityparser import UnityDocument

from unityscaffold.unity.scene import SceneDocument

# Real scenes and prefabs copied from public projects (tests/data/unity/ATTRIBUTION.md).
DATA = Path(__file__).resolve().parents[1] / "data" / "unity"


def corpus_files() -> list[Path]:
    found = sorted(p for p in DATA.rglob("*") if _is_unity(p))
    if not found:
        raise RuntimeError(f"no Unity files under {DATA}")
    return found


def _is_unity(path: Path) -> bool:
    return path.suffix in {".unity", ".prefab"} and path.is_file()


CORPUS = corpus_files()
CORPUS_IDS = [p.name for p in CORPUS]
SCENES_2022 = DATA / "ros-sharp"
SCENES_2020 = DATA / "unity-robotics-hub"


def read_with_unityparser(text: str, directory: Path) -> UnityDocument:
    """Load ``text`` with unityparser (an independent Unity YAML reader)."""
    path = directory / "unityparser-check.unity"
    path.write_bytes(text.encode("utf-8"))
    return UnityDocument.load_yaml(str(path))


def _assert_sound(scene: SceneDocument, directory: Path) -> None:
    assert scene.validate() == []
    text = scene.text()
    reread = SceneDocument.parse(text, scene.path)
    assert reread.text() == text
    other = read_with_unityparser(text, directory)
    assert [int(e.anchor) for e in other.entries] == [d.file_id for d in reread.documents()]


@pytest.fixture
def assert_sound(tmp_path: Path):  # type: ignore[no-untyped-def]
    """Check that a scene passes our reference checks and unityparser reads the same objects."""

    def check(scene: SceneDocument) -> None:
        _assert_sound(scene, tmp_path)

    return check


@pytest.fixture(params=CORPUS, ids=CORPUS_IDS)
def corpus_file(request: pytest.FixtureRequest) -> Path:
    path: Path = request.param
    return path


@pytest.fixture
def scene_2022() -> SceneDocument:
    return SceneDocument.load(SCENES_2022 / "ROSVersionSwitch.unity")


@pytest.fixture
def scene_2020() -> SceneDocument:
    return SceneDocument.load(SCENES_2020 / "DemoScene.unity")
