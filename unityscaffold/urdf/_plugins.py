"""A plugin element's text exactly as ROS#'s importer stores it in ``UrdfPlugin.PluginText``.

ROS# loads the URDF with .NET's ``XDocument.Load`` (which drops text that is only whitespace)
and stores ``XElement.ToString()``: two-space indentation, one element or comment per line,
``<x />`` for an element written empty and ``<x></x>`` for one that had only whitespace inside,
an element holding text written on one line with its children inline, attributes in double
quotes. Newlines are ``\\n`` here; the importing machine's newline is the writer's choice.
"""

from __future__ import annotations

from unityscaffold.urdf._xml import Comment, Element, Text

__all__ = ["plugin_text"]

_INDENT = "  "
_TEXT_ESCAPES = str.maketrans({"&": "&amp;", "<": "&lt;", ">": "&gt;"})
_ATTRIBUTE_ESCAPES = str.maketrans(
    {
        "&": "&amp;",
        "<": "&lt;",
        ">": "&gt;",
        '"': "&quot;",
        "\t": "&#x9;",
        "\n": "&#xA;",
        "\r": "&#xD;",
    }
)


def plugin_text(element: Element) -> str:
    """``XElement.ToString()`` of ``element``, with ``\\n`` newlines."""
    out: list[str] = []
    _write(element, 0, out, inline=False)
    return "".join(out).lstrip("\n")


def _kept(element: Element) -> list[Element | Text | Comment]:
    """The content XDocument keeps: whitespace-only text is dropped when loading."""
    return [
        c
        for c in element.children
        if not (isinstance(c, Text) and not c.cdata and not c.text.strip(" \t\r\n"))
    ]


def _write(element: Element, depth: int, out: list[str], *, inline: bool) -> None:
    if not inline:
        out.append("\n" + _INDENT * depth)
    attributes = "".join(
        f' {key}="{value.translate(_ATTRIBUTE_ESCAPES)}"' for key, value in element.attributes
    )
    content = _kept(element)
    if not content:
        out.append(
            f"<{element.tag}{attributes} />"
            if element.empty_tag
            else f"<{element.tag}{attributes}></{element.tag}>"
        )
        return
    out.append(f"<{element.tag}{attributes}>")
    # .NET's writer stops indenting inside an element once text has been written in it
    mixed = inline
    for node in content:
        if isinstance(node, Text):
            mixed = True
            out.append(_text(node))
        elif isinstance(node, Comment):
            if not mixed:
                out.append("\n" + _INDENT * (depth + 1))
            out.append(f"<!--{node.text}-->")
        else:
            _write(node, depth + 1, out, inline=mixed)
    if not mixed:
        out.append("\n" + _INDENT * depth)
    out.append(f"</{element.tag}>")


def _text(node: Text) -> str:
    if node.cdata:
        return f"<![CDATA[{node.text}]]>"
    return node.text.translate(_TEXT_ESCAPES)
