"""Prompt templates: markdown files with declared variables, checked when they are loaded.

A template is a markdown file (``prompts/<name>.md``, sub-folders allowed, so a name may be
``baselines/react``) shaped like this::

    ---
    variables: [memory, instruction]
    description: what the prompt is for (optional; other keys are kept in ``meta``)
    ---
    ## system
    AGENT: perception
    You are ... $memory

    ## user
    ${instruction}

The ``## system`` and ``## user`` sections are optional; without either heading the whole
body is the user message. ``$name`` and ``${name}`` are replaced by the value of a declared
variable and ``$$`` is a literal dollar sign. Loading is strict so that a broken prompt fails
at start-up rather than in the middle of an instruction: a ``$`` that starts no valid
placeholder, a placeholder for an undeclared variable and a declared variable the body never
uses are all errors naming the file and line. Rendering needs every declared variable and
no other; substituted values are inserted literally and never scanned again.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from assistantx.core.errors import PromptError
from assistantx.core.ports.model import Message

DEFAULT_PROMPTS = Path(__file__).resolve().parents[2] / "data" / "prompts"
PROMPT_SUFFIX = ".md"

_IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")
_PLACEHOLDER = re.compile(
    r"\$(?:(?P<escaped>\$)|(?P<named>[A-Za-z_][A-Za-z0-9_]*)|\{(?P<braced>[A-Za-z_][A-Za-z0-9_]*)\}"
    r"|(?P<invalid>))"
)
_SECTION = re.compile(r"^##[ \t]+(system|user)[ \t]*$", re.IGNORECASE | re.MULTILINE)
_FRONT_MATTER_END = re.compile(r"^---[ \t]*$", re.MULTILINE)

Value = str | int | float


@dataclass(frozen=True)
class _Placeholder:
    name: str


_Part = str | _Placeholder


@dataclass(frozen=True)
class PromptTemplate:
    """A loaded, checked template; :meth:`render` turns it into chat messages."""

    name: str
    path: str
    variables: tuple[str, ...]
    system: tuple[_Part, ...] | None
    user: tuple[_Part, ...] | None
    description: str = ""
    meta: Mapping[str, Any] = field(default_factory=dict)

    @classmethod
    def from_text(cls, text: str, *, name: str, path: str = "<string>") -> PromptTemplate:
        return _parse(text, name=name, path=path)

    def render(
        self, values: Mapping[str, Value] | None = None, /, **kwargs: Value
    ) -> list[Message]:
        """The system message (if any) then the user message (if any), filled in."""
        given: dict[str, Value] = {**(values or {}), **kwargs}
        missing = [v for v in self.variables if v not in given]
        if missing:
            raise PromptError(self.path, f"missing value(s) for {', '.join(missing)}")
        unknown = sorted(set(given) - set(self.variables))
        if unknown:
            raise PromptError(
                self.path,
                f"unknown variable(s) {', '.join(unknown)}; declared: {', '.join(self.variables)}",
            )
        for key, value in given.items():
            if isinstance(value, bool) or not isinstance(value, (str, int, float)):
                raise PromptError(
                    self.path,
                    f"value for {key} must be text or a number, not {type(value).__name__}",
                )
        messages = []
        if self.system is not None:
            messages.append(Message(role="system", content=_fill(self.system, given)))
        if self.user is not None:
            messages.append(Message(role="user", content=_fill(self.user, given)))
        return messages


def _fill(parts: tuple[_Part, ...], values: Mapping[str, Value]) -> str:
    return "".join(p if isinstance(p, str) else str(values[p.name]) for p in parts)


def load_prompt(path: str | Path, *, name: str | None = None) -> PromptTemplate:
    """Load and check one template file."""
    file = Path(path)
    where = str(file)
    try:
        text = file.read_text(encoding="utf-8")
    except OSError as exc:
        raise PromptError(where, f"cannot be read: {exc.strerror or exc}") from exc
    except UnicodeDecodeError as exc:
        raise PromptError(where, f"is not UTF-8 text: {exc}") from exc
    return _parse(text, name=name or file.stem, path=where)


def load_prompts(
    directory: str | Path | None = None, names: Iterable[str] | None = None
) -> dict[str, PromptTemplate]:
    """Load a set of templates at start-up; every problem in every file is reported at once.

    ``names`` are paths below ``directory`` without the ``.md`` suffix (``"perception"``,
    ``"baselines/react"``); without ``names`` every ``.md`` file below it is loaded.
    """
    root = Path(directory) if directory is not None else DEFAULT_PROMPTS
    if not root.is_dir():
        raise PromptError(str(root), "is not a directory of prompt templates")
    if names is None:
        wanted = sorted(
            p.relative_to(root).with_suffix("").as_posix() for p in root.rglob(f"*{PROMPT_SUFFIX}")
        )
    else:
        wanted = list(dict.fromkeys(names))
    templates: dict[str, PromptTemplate] = {}
    problems: list[str] = []
    for name in wanted:
        try:
            templates[name] = load_prompt(root / f"{name}{PROMPT_SUFFIX}", name=name)
        except PromptError as exc:
            problems.append(str(exc))
    if problems:
        raise PromptError(str(root), "bad prompt template(s):\n  " + "\n  ".join(problems))
    return templates


def _parse(text: str, *, name: str, path: str) -> PromptTemplate:
    text = text.removeprefix("\ufeff").replace("\r\n", "\n")
    header, body, body_line = _split_front_matter(text, path)
    variables, description, meta = _read_header(header, path)
    sections = _split_sections(body, body_line, path)
    used: set[str] = set()
    compiled: dict[str, tuple[_Part, ...]] = {}
    for section, (content, first_line) in sections.items():
        parts = _compile(content, first_line, set(variables), path)
        used.update(p.name for p in parts if isinstance(p, _Placeholder))
        compiled[section] = parts
    unused = [v for v in variables if v not in used]
    if unused:
        raise PromptError(path, f"declared variable(s) never used: {', '.join(unused)}")
    return PromptTemplate(
        name=name,
        path=path,
        variables=tuple(variables),
        system=compiled.get("system"),
        user=compiled.get("user"),
        description=description,
        meta=meta,
    )


def _split_front_matter(text: str, path: str) -> tuple[str, str, int]:
    """(front matter, body, line number where the body starts)."""
    if not text.startswith("---"):
        raise PromptError(path, "must start with a '---' front-matter block declaring variables")
    first_newline = text.find("\n")
    if first_newline < 0 or text[:first_newline].strip() != "---":
        raise PromptError(path, "the first line must be exactly '---'")
    end = _FRONT_MATTER_END.search(text, first_newline + 1)
    if end is None:
        raise PromptError(path, "the front-matter block is not closed by a '---' line")
    header = text[first_newline + 1 : end.start()]
    body_start = end.end() + 1 if end.end() < len(text) else end.end()
    body_line = text.count("\n", 0, body_start) + 1
    return header, text[body_start:], body_line


def _read_header(header: str, path: str) -> tuple[list[str], str, dict[str, Any]]:
    try:
        data = yaml.safe_load(header)
    except yaml.YAMLError as exc:
        raise PromptError(path, f"front matter is not valid YAML: {exc}") from exc
    if not isinstance(data, dict):
        raise PromptError(path, "front matter must be a mapping with a 'variables' list")
    if "variables" not in data:
        raise PromptError(path, "front matter must declare 'variables' (use [] for none)")
    raw = data.pop("variables")
    raw = [] if raw is None else raw
    if not isinstance(raw, list) or not all(isinstance(v, str) for v in raw):
        raise PromptError(path, "'variables' must be a list of names")
    bad = [v for v in raw if not _IDENTIFIER.match(v)]
    if bad:
        raise PromptError(path, f"invalid variable name(s): {', '.join(map(repr, bad))}")
    duplicates = sorted({v for v in raw if raw.count(v) > 1})
    if duplicates:
        raise PromptError(path, f"variable(s) declared twice: {', '.join(duplicates)}")
    description = data.pop("description", "")
    if not isinstance(description, str):
        raise PromptError(path, "'description' must be text")
    return raw, description, {str(k): v for k, v in data.items()}


def _split_sections(body: str, body_line: int, path: str) -> dict[str, tuple[str, int]]:
    """Section name -> (text, line number of its first line)."""

    def content_from(start: int, end: int) -> tuple[str, int]:
        raw = body[start:end]
        offset = start + len(raw) - len(raw.lstrip("\n"))  # skip blank lines after heading
        return raw.strip("\n").rstrip(), body_line + body.count("\n", 0, offset)

    headings = list(_SECTION.finditer(body))
    if not headings:
        content, first_line = content_from(0, len(body))
        if not content.strip():
            raise PromptError(path, "the template has no text")
        return {"user": (content, first_line)}
    if body[: headings[0].start()].strip():
        _, line = content_from(0, headings[0].start())
        raise PromptError(
            path, f"line {line}: text before the first '## system' or '## user' heading"
        )
    sections: dict[str, tuple[str, int]] = {}
    for index, heading in enumerate(headings):
        section = heading.group(1).lower()
        line = body_line + body.count("\n", 0, heading.start())
        if section in sections:
            raise PromptError(path, f"line {line}: a second '## {section}' section")
        end = headings[index + 1].start() if index + 1 < len(headings) else len(body)
        content, first_line = content_from(heading.end(), end)
        if not content.strip():
            raise PromptError(path, f"line {line}: the '## {section}' section is empty")
        sections[section] = (content, first_line)
    return sections


def _compile(text: str, first_line: int, declared: set[str], path: str) -> tuple[_Part, ...]:
    parts: list[_Part] = []
    position = 0
    for match in _PLACEHOLDER.finditer(text):
        literal = text[position : match.start()]
        position = match.end()
        line = first_line + text.count("\n", 0, match.start())
        if match.group("escaped") is not None:
            parts.append(literal + "$")
            continue
        variable = match.group("named") or match.group("braced")
        if variable is None:
            raise PromptError(
                path,
                f"line {line}: '$' must start $name, ${{name}} or $$ (a literal dollar sign)",
            )
        if variable not in declared:
            raise PromptError(
                path,
                f"line {line}: ${variable} is not declared in 'variables' "
                f"({', '.join(sorted(declared)) or 'none declared'})",
            )
        parts.extend((literal, _Placeholder(variable)))
    parts.append(text[position:])
    merged: list[_Part] = []
    for part in parts:  # join adjacent literals so rendering is one pass over few parts
        if isinstance(part, str) and merged and isinstance(merged[-1], str):
            merged[-1] += part
        elif part != "":
            merged.append(part)
    return tuple(merged)
