"""A small reader of C# sources: type declarations, their bases and attributes, enum members
and fields with their written types and whether Unity serializes them.

Deliberately small: comments and string contents are blanked, only the first branch of each
``#if`` is kept, and declarations are split on braces and semicolons. It serves two readers:
``scripts/update_rossharp_catalog.py`` (ROS#'s package, into the shipped catalog) and apply
(a project's own MonoBehaviours, so that a manifest's values are checked against their fields).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

__all__ = [
    "NEVER_SERIALIZED",
    "PRIMITIVES",
    "UNITY_ASSETS",
    "UNITY_COMPONENTS",
    "UNITY_STRUCTS",
    "RawField",
    "SourceError",
    "TypeDecl",
    "element_type",
    "matching",
    "parse_file",
    "split_top",
    "strip_attributes",
]

# Unity's own classes a field may name, by what Unity stores for them.
PRIMITIVES = {
    "bool": "bool",
    "byte": "int",
    "sbyte": "int",
    "short": "int",
    "ushort": "int",
    "int": "int",
    "uint": "int",
    "long": "int",
    "ulong": "int",
    "float": "float",
    "double": "float",
    "char": "int",
    "string": "string",
}
UNITY_STRUCTS = frozenset(
    {"Vector2", "Vector3", "Vector4", "Quaternion", "Color", "Color32", "Rect", "Bounds"}
)
# UnityEngine.Object subclasses: a field of one of these holds a reference.
UNITY_COMPONENTS = frozenset(
    {
        "Transform",
        "RectTransform",
        "Rigidbody",
        "Camera",
        "Light",
        "Renderer",
        "MeshRenderer",
        "MeshFilter",
        "LineRenderer",
        "Joint",
        "HingeJoint",
        "ConfigurableJoint",
        "ArticulationBody",
        "Collider",
        "MonoBehaviour",
        "RawImage",
        "Image",
        "Text",
    }
)
UNITY_ASSETS = frozenset(
    {
        "GameObject",
        "Material",
        "Mesh",
        "Texture",
        "Texture2D",
        "RenderTexture",
        "Shader",
        "Sprite",
        "Font",
        "TextAsset",
    }
)
# Types Unity never serializes (the field is skipped, as Unity skips it).
NEVER_SERIALIZED = re.compile(
    r"^(?:System\.)?(?:Dictionary|HashSet|Queue|Stack|Action|Func|Thread|Task|"
    r"ManualResetEvent|DateTime|TimeSpan|object|dynamic|Exception)\b"
)

_MODIFIERS = frozenset(
    {
        "public",
        "private",
        "protected",
        "internal",
        "static",
        "readonly",
        "const",
        "new",
        "volatile",
        "unsafe",
        "override",
        "virtual",
        "abstract",
        "sealed",
        "extern",
        "partial",
    }
)
_TYPE_DECL = re.compile(r"\b(class|struct|interface|enum)\s+(\w+)")
_ATTRIBUTE = re.compile(r"^\s*\[")


class SourceError(Exception):
    """The checkout holds something this reader cannot classify."""


# --- lexing -----------------------------------------------------------------------------------


def clean(text: str) -> str:
    """Comments removed, string literals kept as hex (see ``_string_token``), char literal
    contents blanked, ``#else`` branches dropped."""
    out: list[str] = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            end = n if j < 0 else j + 2
            out.append(" " + "\n" * text.count("\n", i, end))
            i = end
        elif c == '"' or (c in "@$" and text[i + 1 : i + 3].lstrip("@$").startswith('"')):
            j = _string_end(text, i)
            out.append(_string_token(text[i:j]) + "\n" * text.count("\n", i, j))
            i = j
        elif c == "'":
            out.append("' '")
            i = _char_end(text, i)
        else:
            out.append(c)
            i += 1
    return _preprocess("".join(out))


_ESCAPES = {"n": "\n", "t": "\t", "r": "\r", "0": "\0", "a": "\a", "b": "\b", "f": "\f", "v": "\v"}
_ESCAPE = re.compile(r"\\(u[0-9a-fA-F]{4}|U[0-9a-fA-F]{8}|x[0-9a-fA-F]{1,4}|.)", re.S)


def _string_token(literal: str) -> str:
    """A string literal as the reader keeps it: ``"<hex of its UTF-8 bytes>"``, safe from the
    braces and semicolons the declarations are split on (``"$"`` when it is interpolated)."""
    prefix, _, rest = literal.partition('"')
    body = rest[:-1]
    if "$" in prefix:
        return '"$"'
    value = body.replace('""', '"') if "@" in prefix else _ESCAPE.sub(_unescape, body)
    return '"' + value.encode("utf-8", errors="surrogatepass").hex() + '"'


def _unescape(match: re.Match[str]) -> str:
    code = match.group(1)
    if code[0] in "uUx" and len(code) > 1:
        return chr(int(code[1:], 16))
    return _ESCAPES.get(code, code)


def _string_end(text: str, start: int) -> int:
    """The index just past the string literal starting at ``start`` (``"``, ``@"``, ``$"``)."""
    prefix_end = text.index('"', start)
    prefix = text[start:prefix_end]
    verbatim, interpolated = "@" in prefix, "$" in prefix
    j = prefix_end + 1
    while j < len(text):
        c = text[j]
        if (c == "\\" and not verbatim) or (c == '"' and verbatim and text.startswith('""', j)):
            j += 2
        elif c == '"':
            return j + 1
        elif c == "{" and interpolated and text.startswith("{{", j):
            j += 2
        elif c == "{" and interpolated:
            j = _hole_end(text, j)
        else:
            j += 1
    raise SourceError("unterminated string literal")


def _char_end(text: str, start: int) -> int:
    """The index just past the char literal starting at ``start``."""
    j = start + 1
    while j < len(text) and text[j] != "'":
        j += 2 if text[j] == "\\" else 1
    return j + 1


def _hole_end(text: str, start: int) -> int:
    """The index just past the ``}`` closing an interpolation hole opened at ``start``."""
    depth, j = 0, start
    while j < len(text):
        c = text[j]
        if c == '"' or (c in "@$" and text[j + 1 : j + 3].lstrip("@$").startswith('"')):
            j = _string_end(text, j)
            continue
        if c == "'":
            j = _char_end(text, j)
            continue
        if c == "{":
            depth += 1
        elif c == "}":
            depth -= 1
            if depth == 0:
                return j + 1
        j += 1
    raise SourceError("unterminated interpolation")


def _preprocess(text: str) -> str:
    kept: list[str] = []
    skipping: list[bool] = []
    for line in text.split("\n"):
        directive = line.strip()
        if directive.startswith("#if"):
            skipping.append(False)
        elif directive.startswith(("#else", "#elif")):
            if skipping:
                skipping[-1] = True
        elif directive.startswith("#endif"):
            if skipping:
                skipping.pop()
        elif directive.startswith("#"):
            pass  # #region, #pragma ...
        elif not any(skipping):
            kept.append(line)
            continue
        kept.append("")
    return "\n".join(kept)


def matching(text: str, start: int, open_: str = "{", close: str = "}") -> int:
    """Index of the bracket closing the one at ``start``."""
    depth = 0
    for i in range(start, len(text)):
        if text[i] == open_:
            depth += 1
        elif text[i] == close:
            depth -= 1
            if depth == 0:
                return i
    raise SourceError(f"unbalanced {open_!r}")


def element_type(text: str) -> str | None:
    """The element type when Unity stores a field of type ``text`` as a list (``T[]`` or
    ``List<T>``, with ``System.``/``UnityEngine.`` already taken off), else None."""
    if text.endswith("[]"):
        return text[:-2]
    if text.startswith(("List<", "Collections.Generic.List<")) and text.endswith(">"):
        return text[text.index("<") + 1 : -1].strip()
    return None


def split_top(text: str, separator: str = ",") -> list[str]:
    """``text`` split on ``separator`` outside (), [], {} and <>."""
    parts: list[str] = []
    depth = 0
    current: list[str] = []
    for c in text:
        if c in "([{<":
            depth += 1
        elif c in ")]}>":
            depth -= 1
        if c == separator and depth == 0:
            parts.append("".join(current))
            current = []
        else:
            current.append(c)
    parts.append("".join(current))
    return [p.strip() for p in parts if p.strip()]


def strip_attributes(text: str) -> tuple[list[str], str]:
    attributes = []
    text = text.strip()
    while _ATTRIBUTE.match(text):
        end = matching(text, text.index("["), "[", "]")
        attributes.append(text[text.index("[") + 1 : end])
        text = text[end + 1 :].strip()
    return attributes, text


# --- declarations -----------------------------------------------------------------------------


@dataclass(slots=True)
class RawField:
    name: str
    type: str
    serialized: bool
    initializer: str | None = None  # the text after "=", string literals as hex


@dataclass(slots=True)
class TypeDecl:
    kind: str  # class, struct, interface, enum
    name: str
    namespace: str
    outer: tuple[str, ...]
    path: str
    generics: tuple[str, ...] = ()
    bases: tuple[str, ...] = ()
    attributes: tuple[str, ...] = ()
    modifiers: frozenset[str] = frozenset()
    fields: list[RawField] = field(default_factory=list)
    members: list[tuple[str, int]] = field(default_factory=list)  # enums

    @property
    def full_name(self) -> str:
        return ".".join(p for p in (self.namespace, *self.outer, self.name) if p)


def parse_file(text: str, path: str) -> list[TypeDecl]:
    found: list[TypeDecl] = []
    _parse_block(clean(text), "", (), path, found, None)
    return found


def _next_stop(text: str, pos: int) -> int:
    """The next ``;`` or ``{`` outside parentheses and brackets, or -1."""
    depth = 0
    for i in range(pos, len(text)):
        c = text[i]
        if c in "([":
            depth += 1
        elif c in ")]":
            depth -= 1
        elif depth == 0 and c in ";{":
            return i
    return -1


def _parse_block(
    text: str,
    namespace: str,
    outer: tuple[str, ...],
    path: str,
    found: list[TypeDecl],
    owner: TypeDecl | None,
) -> None:
    pos = 0
    while True:
        stop = _next_stop(text, pos)
        if stop < 0:
            return
        start, head = pos, text[pos:stop].strip()
        if text[stop] == ";":
            if owner is not None and head:
                owner.fields.extend(_fields(head))
            pos = stop + 1
            continue
        end = matching(text, stop)
        body = text[stop + 1 : end]
        pos = end + 1
        attributes, bare = strip_attributes(head)
        declaration = _TYPE_DECL.search(bare)
        if bare.startswith("namespace "):
            inner = bare.split(None, 1)[1].strip()
            _parse_block(
                body, f"{namespace}.{inner}" if namespace else inner, (), path, found, None
            )
        elif declaration and "(" not in bare[: declaration.start()] and "=" not in bare:
            decl = _declaration(declaration, bare, attributes, namespace, outer, path)
            found.append(decl)
            if decl.kind == "enum":
                decl.members = _enum_members(body)
            else:
                _parse_block(body, namespace, (*outer, decl.name), path, found, decl)
        elif "=" in bare.split("(", 1)[0] and "=>" not in bare:
            # a field with a collection initializer: the whole declaration, braces and all
            pos = text.index(";", pos) + 1
            if owner is not None:
                owner.fields.extend(_fields(text[start : pos - 1].strip()))
        elif text[pos:].lstrip().startswith("="):
            pos = text.index(";", pos) + 1  # a property with an initializer


def _declaration(
    match: re.Match[str],
    bare: str,
    attributes: list[str],
    namespace: str,
    outer: tuple[str, ...],
    path: str,
) -> TypeDecl:
    modifiers = frozenset(bare[: match.start()].split())
    rest = bare[match.end() :].strip()
    generics: tuple[str, ...] = ()
    if rest.startswith("<"):
        close = matching(rest, 0, "<", ">")
        generics = tuple(split_top(rest[1:close]))
        rest = rest[close + 1 :].strip()
    bases: tuple[str, ...] = ()
    if rest.startswith(":"):
        bases = tuple(split_top(re.split(r"\bwhere\b", rest[1:])[0]))
    return TypeDecl(
        match.group(1),
        match.group(2),
        namespace,
        outer,
        path,
        generics,
        bases,
        tuple(attributes),
        modifiers,
    )


def _enum_members(body: str) -> list[tuple[str, int]]:
    members, value = [], -1
    for item in split_top(body):
        _, item = strip_attributes(item)
        name, _, explicit = item.partition("=")
        explicit = explicit.strip()
        value = int(explicit, 0) if explicit else value + 1
        members.append((name.strip(), value))
    return members


def _fields(head: str) -> list[RawField]:
    attributes, rest = strip_attributes(head)
    if not rest or rest.startswith(("using ", "delegate ")) or "=>" in rest:
        return []
    words = rest.split()
    modifiers = set()
    while words and words[0] in _MODIFIERS:
        modifiers.add(words.pop(0))
    rest = " ".join(words)
    if not rest or rest.startswith(("event ", "delegate ")):
        return []
    type_end = _type_end(rest)
    type_ = re.sub(r"\s+", "", rest[:type_end])
    declarators = split_top(rest[type_end:])
    if not type_ or not declarators or "(" in declarators[0].split("=", 1)[0]:
        return []  # a method declaration without a body (abstract, extern)
    attribute_names = {a.split("(")[0].strip().rsplit(".", 1)[-1] for a in attributes}
    attribute_names |= {
        p.split("(")[0].strip().rsplit(".", 1)[-1] for a in attributes for p in split_top(a)
    }
    serialized = (
        not modifiers & {"static", "const", "readonly"}
        and ("public" in modifiers or "SerializeField" in attribute_names)
        and not attribute_names & {"NonSerialized"}
    )
    found = []
    for declarator in declarators:
        name, equals, initializer = declarator.partition("=")
        name = name.strip()
        if re.fullmatch(r"@?\w+", name):
            found.append(RawField(name, type_, serialized, initializer.strip() if equals else None))
    return found


def _type_end(text: str) -> int:
    """Where a field's type ends: the first space at generic depth 0 before an identifier."""
    depth = 0
    i = 0
    while i < len(text):
        c = text[i]
        if c == "<":
            depth += 1
        elif c == ">":
            depth -= 1
        elif c == " " and depth == 0:
            after = text[i + 1 :].lstrip()
            if after and not after.startswith(("[", "<", ".", "?", ">", ",")):
                if text[:i].rstrip().endswith((",", ".")):
                    i += 1
                    continue
                return i
        i += 1
    return len(text)
