"""What pip users get: the wheel and sdist built by the real build backend (hatchling) carry
the licence, the metadata (one version, licence expression, classifiers, URLs) and the
package's data files."""

from __future__ import annotations

import email
import importlib.util
import subprocess
import sys
import tarfile
import zipfile
from pathlib import Path

import pytest
from helpers import require

import unityscaffold

REPO = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def built(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    require(importlib.util.find_spec("hatchling"), "hatchling (the build backend)")
    out = tmp_path_factory.mktemp("dist")
    subprocess.run(
        [sys.executable, "-m", "hatchling", "build", "-d", str(out)],
        cwd=REPO,
        check=True,
        capture_output=True,
    )
    [wheel] = out.glob("*.whl")
    [sdist] = out.glob("*.tar.gz")
    return wheel, sdist


def test_the_wheel_has_the_licence_the_metadata_and_the_data_files(built):
    wheel, _ = built
    with zipfile.ZipFile(wheel) as archive:
        names = set(archive.namelist())
        info = f"unityscaffold-{unityscaffold.__version__}.dist-info"
        assert archive.read(f"{info}/licenses/LICENSE") == (REPO / "LICENSE").read_bytes()
        metadata = email.message_from_bytes(archive.read(f"{info}/METADATA"))
    assert metadata["Version"] == unityscaffold.__version__  # the one version source
    assert metadata["License-Expression"] == "Apache-2.0"
    classifiers = metadata.get_all("Classifier")
    for minor in (10, 11, 12, 13):
        assert f"Programming Language :: Python :: 3.{minor}" in classifiers
    assert metadata.get_all("Project-URL")
    assert "unityscaffold/schema/robot.schema.json" in names
    assert "unityscaffold/templates/unity_project/Packages/manifest.json.jinja" in names
    builtin = [n for n in names if n.startswith("unityscaffold/interfaces/builtin/")]
    assert len(builtin) == len(list((REPO / "unityscaffold/interfaces/builtin").rglob("*.*")))


def test_the_sdist_has_the_licence(built):
    _, sdist = built
    with tarfile.open(sdist) as archive:
        member = archive.extractfile(f"unityscaffold-{unityscaffold.__version__}/LICENSE")
        assert member is not None
        assert member.read() == (REPO / "LICENSE").read_bytes()


def test_the_licence_is_the_apache_2_text_the_metadata_names():
    text = (REPO / "LICENSE").read_text()
    assert "Apache License" in text and "Version 2.0, January 2004" in text
    assert "END OF TERMS AND CONDITIONS" in text
