"""Long double-quoted strings folded over lines, read and written as Unity 2022.3 does.

The golden file is real: ROS#'s four UrdfPlugin documents from its r2d2 tutorial scene
(tests/data/unity/ros-sharp/r2d2_plugins.documents.txt, saved by Unity 2022.3), whose
PluginText Unity folded 21 times. Reading keeps the spaces before each fold wherever the string
is (a field, a list item, a struct's field, a flow mapping); writing folds where Unity folds.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
import yaml

from unityscaffold.unity._emit import emit_field
from unityscaffold.unity._folds import fold_double_quoted, read_folds_unity_way
from unityscaffold.unity.scene import SceneDocument

DATA = Path(__file__).resolve().parents[1] / "data" / "unity" / "ros-sharp"
PROLOG = "%YAML 1.1\n%TAG !u! tag:unity3d.com,2011:\n"


def _plugins() -> list[tuple[int, str]]:
    """(fileID, the PluginText field's lines as Unity wrote them) of each UrdfPlugin."""
    text = (DATA / "r2d2_plugins.documents.txt").read_text(encoding="utf-8")
    found = []
    for doc in re.split(r"^(?=--- )", text, flags=re.M)[1:]:
        file_id = int(re.match(r"--- !u!114 &(\d+)", doc).group(1))  # type: ignore[union-attr]
        found.append((file_id, doc[doc.index("  PluginText: ") :]))
    return found


PLUGINS = _plugins()


def test_the_golden_file_holds_unitys_folds():
    assert len(PLUGINS) == 4
    assert sum(field.count("\n") - 1 for _, field in PLUGINS) == 21


@pytest.mark.parametrize(("file_id", "field"), PLUGINS, ids=[str(i) for i, _ in PLUGINS])
def test_a_long_string_is_folded_where_unity_folded_it(file_id, field):
    scene = SceneDocument.parse(
        PROLOG + (DATA / "r2d2_plugins.documents.txt").read_text(encoding="utf-8")
    )
    value = scene.field(file_id, "PluginText")
    assert isinstance(value, str) and "\r\n   \n" not in value
    assert "\n".join(emit_field("PluginText", value)) + "\n" == field


@pytest.mark.parametrize(("file_id", "field"), PLUGINS, ids=[str(i) for i, _ in PLUGINS])
def test_setting_the_value_unity_folded_changes_nothing(file_id, field):
    text = PROLOG + (DATA / "r2d2_plugins.documents.txt").read_text(encoding="utf-8")
    scene = SceneDocument.parse(text)
    value = scene.field(file_id, "PluginText")
    assert scene.set_fields(file_id, [("PluginText", value)]) is False
    assert scene.text() == text


# One text Unity folded inside a list, a struct, a list of structs and a flow mapping: a line
# that ends in spaces before a fold keeps them (YAML would read one space for all of them).
TEXT = "<plugin>\r\n    <joint>left</joint>\r\n  </plugin>"
NESTED = """\
  Lines:
  - "<plugin>\\r\\n···
    <joint>left</joint>\\r\\n·
    </plugin>"
  Entry:
    key: a
    text: "<plugin>\\r\\n···
      <joint>left</joint>\\r\\n·
      </plugin>"
  Entries:
  - key: a
    text: "<plugin>\\r\\n···
      <joint>left</joint>\\r\\n·
      </plugin>"
  Inline: {key: a, text: "<plugin>\\r\\n···
    <joint>left</joint>\\r\\n·
    </plugin>"}
""".replace("·", " ")  # the spaces Unity keeps at the end of a line before a fold


def test_a_folded_string_anywhere_in_a_field_reads_with_its_spaces():
    first = (DATA / "r2d2_plugins.documents.txt").read_text(encoding="utf-8").split("\n--- ")[0]
    scene = SceneDocument.parse(PROLOG + first.split("  PluginText:")[0] + NESTED)
    plugin = 1319294286
    assert scene.field(plugin, "Lines") == [TEXT]
    assert scene.field(plugin, "Entry") == {"key": "a", "text": TEXT}
    assert scene.field(plugin, "Entries") == [{"key": "a", "text": TEXT}]
    assert scene.field(plugin, "Inline") == {"key": "a", "text": TEXT}


def test_folding_then_reading_unitys_way_gives_the_text_back():
    for text in [TEXT * 5, "a" * 90 + "   b  c", "x" * 79 + " " + "y", "é " * 60]:
        escaped = text.replace("\r", "\\r").replace("\n", "\\n").replace("é", "\\u00E9")
        lines = "  k: " + fold_double_quoted(escaped, 5, 4) + "\n"
        assert all(len(line) < 200 for line in lines.split("\n"))
        assert yaml.load(read_folds_unity_way(lines), Loader=yaml.BaseLoader)["k"] == text


def test_text_without_a_folded_double_quoted_string_is_read_as_it_is():
    plain = "  k: 'a\n    b'\n  m: \"one line\"\n"
    assert read_folds_unity_way(plain) == plain
    assert read_folds_unity_way('  k: "unclosed\n    x\n') == '  k: "unclosed\n    x\n'
