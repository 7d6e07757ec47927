"""Compiled templates are cached in the user's cache folder, never in the project or package."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import jinja2
import pytest

from unityscaffold import __version__
from unityscaffold.resources import template_environment

TEMPLATE = "rossharp/Message.cs.jinja"


@pytest.fixture(autouse=True)
def _fresh_environment() -> Iterator[None]:
    template_environment.cache_clear()
    yield
    template_environment.cache_clear()


def _compiled_names(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.glob("*.jinja-cache"))


def test_compiled_templates_are_cached_per_version_and_reused(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    monkeypatch.delenv("UNITYSCAFFOLD_NO_CACHE", raising=False)
    first = template_environment().get_template(TEMPLATE)
    folder = tmp_path / "unityscaffold" / f"{__version__}-templates"
    cached = _compiled_names(folder)
    assert len(cached) == 1
    before = (folder / cached[0]).read_bytes()

    template_environment.cache_clear()
    again = template_environment().get_template(TEMPLATE)
    assert again is not first  # a new environment, loaded from the cache file
    assert (folder / cached[0]).read_bytes() == before
    code, fresh = again.root_render_func.__code__, first.root_render_func.__code__
    assert code.co_code == fresh.co_code and code.co_consts == fresh.co_consts
    assert [p.name for p in tmp_path.iterdir()] == ["unityscaffold"]


def test_an_unwritable_cache_folder_is_not_used(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    blocker = tmp_path / "not-a-folder"
    blocker.write_text("a file where the cache folder would go")
    monkeypatch.setenv("XDG_CACHE_HOME", str(blocker))
    monkeypatch.delenv("UNITYSCAFFOLD_NO_CACHE", raising=False)
    assert template_environment().get_template(TEMPLATE).render is not None
    assert blocker.read_text() == "a file where the cache folder would go"


def test_the_cache_can_be_turned_off(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    monkeypatch.setenv("UNITYSCAFFOLD_NO_CACHE", "1")
    template_environment().get_template(TEMPLATE)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("name", ["range", "dict", "namespace", "cycler", "joiner", "lipsum"])
def test_templates_see_only_their_view_not_jinja_globals(name: str) -> None:
    template = template_environment().from_string(f"{{{{ {name} }}}}")
    with pytest.raises(jinja2.UndefinedError, match=f"'{name}' is undefined"):
        template.render(view=None)
