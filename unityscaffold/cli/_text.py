"""Help text as typer should show it."""

from __future__ import annotations

__all__ = ["one_line_paragraphs"]


def one_line_paragraphs(text: str) -> str:
    """``text`` with each prose paragraph on one line; indented lines (examples) kept as they are.

    typer keeps the line breaks of a docstring's later paragraphs and rich then wraps those
    lines again at the terminal's width, which left help texts ragged mid-sentence.
    """
    import inspect

    paragraphs = []
    for paragraph in inspect.cleandoc(text).split("\n\n"):
        lines: list[str] = []
        for line in paragraph.split("\n"):
            if lines and not line.startswith(" ") and not lines[-1].startswith(" "):
                lines[-1] += " " + line
            else:
                lines.append(line)
        paragraphs.append("\n".join(lines))
    return "\n\n".join(paragraphs)
