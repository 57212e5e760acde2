"""The prompt template loader: format, strict variables, clear errors naming the file."""

from __future__ import annotations

from pathlib import Path

import pytest

from assistantx.adapters.model import Message
from assistantx.agents.llm.prompts import DEFAULT_PROMPTS, PromptTemplate, load_prompt, load_prompts
from assistantx.core.errors import PromptError

HERE = Path(__file__).parent / "prompts"


def write(tmp_path: Path, name: str, text: str) -> Path:
    path = tmp_path / f"{name}.md"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


def test_example_template_renders_to_messages() -> None:
    template = load_prompt(HERE / "example.md")
    assert template.name == "example"
    assert template.variables == ("memory", "instruction", "step")
    assert template.description.startswith("A small example")
    assert template.meta == {"output": "Percept"}
    messages = template.render(memory="lee: at desk 3", instruction="Get Lee's file", step=2)
    assert messages == [
        Message(
            role="system",
            content="AGENT: perception\n"
            "You are the perception agent of an office assistant. Step 2.\n"
            "What the assistant remembers:\n"
            "lee: at desk 3\n\n"
            'Prices are written like $5; JSON examples use braces freely: {"people": []}.',
        ),
        Message(role="user", content="Instruction: Get Lee's file"),
    ]


def test_values_are_inserted_literally() -> None:
    template = PromptTemplate.from_text(
        "---\nvariables: [a, b]\n---\n$a|$b\n", name="t", path="t.md"
    )
    [message] = template.render({"a": "$b ${b} $$"}, b="B")
    assert message == Message(role="user", content="$b ${b} $$|B")


def test_load_prompts_by_name_and_all(tmp_path: Path) -> None:
    loaded = load_prompts(HERE, ["example", "baselines/direct"])
    assert set(loaded) == {"example", "baselines/direct"}
    assert loaded["baselines/direct"].render(instruction="x")[0].content == "Do this directly: x"
    assert set(load_prompts(HERE)) == {"example", "baselines/direct"}


def test_default_directory_is_the_repository_prompts_folder() -> None:
    assert DEFAULT_PROMPTS.resolve() == Path(__file__).resolve().parents[3] / "prompts"


@pytest.mark.parametrize(
    ("text", "problem"),
    [
        ("no front matter\n", "must start with a '---' front-matter block"),
        ("---\nvariables: [a]\n$a\n", "not closed"),
        ("---\nvariables: [a\n---\n$a\n", "not valid YAML"),
        ("---\n- a\n---\n$a\n", "must be a mapping"),
        ("---\nvariable: [a]\n---\n$a\n", "must declare 'variables'"),
        ("---\nvariables: a\n---\n$a\n", "must be a list of names"),
        ("---\nvariables: [a-b]\n---\nx\n", "invalid variable name"),
        ("---\nvariables: [a, a]\n---\n$a\n", "declared twice: a"),
        ("---\nvariables: [a]\n---\nhello\n\n$a and $c\n", r"line 6: \$c is not declared"),
        ("---\nvariables: [a]\n---\n${c}\n$a\n", r"line 4: \$c is not declared"),
        ("---\nvariables: [a, b]\n---\n$a\n", "never used: b"),
        ("---\nvariables: [a]\n---\n$a costs $5\n", r"line 4: '\$' must start"),
        ("---\nvariables: [a]\n---\n${a\n", r"line 4: '\$' must start"),
        ("---\nvariables: [a]\n---\nintro\n## user\n$a\n", "line 4: text before the first"),
        ("---\nvariables: [a]\n---\n## user\n$a\n## user\nx\n", "line 6: a second '## user'"),
        ("---\nvariables: []\n---\n## system\n\n## user\nhi\n", "'## system' section is empty"),
        ("---\nvariables: []\n---\n\n", "no text"),
    ],
)
def test_load_errors_name_the_file(tmp_path: Path, text: str, problem: str) -> None:
    path = write(tmp_path, "broken", text)
    with pytest.raises(PromptError, match=problem) as caught:
        load_prompt(path)
    assert caught.value.path == str(path)
    assert str(caught.value).startswith(f"{path}: ")
    assert isinstance(caught.value, ValueError)


def test_render_errors() -> None:
    template = load_prompt(HERE / "example.md")
    with pytest.raises(PromptError, match=r"missing value.*instruction, step"):
        template.render(memory="m")
    with pytest.raises(PromptError, match=r"unknown variable.*extra"):
        template.render(memory="m", instruction="i", step=1, extra="e")
    with pytest.raises(PromptError, match="step must be text or a number"):
        template.render(memory="m", instruction="i", step=[1])  # type: ignore[arg-type]


def test_load_prompts_reports_every_bad_file(tmp_path: Path) -> None:
    write(tmp_path, "good", "---\nvariables: []\n---\nfine\n")
    write(tmp_path, "bad1", "---\nvariables: [a]\n---\nno a here\n")
    write(tmp_path, "sub/bad2", "---\nvariables: []\n---\n$b\n")
    with pytest.raises(PromptError) as caught:
        load_prompts(tmp_path, ["good", "bad1", "sub/bad2", "missing"])
    message = str(caught.value)
    assert "bad1.md: declared variable(s) never used: a" in message
    assert "bad2.md: line 4: $b is not declared" in message
    assert "missing.md: cannot be read" in message
    assert "good" not in message.replace(str(tmp_path), "")


def test_load_prompts_needs_a_directory(tmp_path: Path) -> None:
    with pytest.raises(PromptError, match="not a directory"):
        load_prompts(tmp_path / "nowhere", ["x"])


def test_crlf_and_bom_are_accepted(tmp_path: Path) -> None:
    path = tmp_path / "win.md"
    path.write_bytes("\ufeff---\r\nvariables: [a]\r\n---\r\n## user\r\nhi $a\r\n".encode())
    assert load_prompt(path).render(a="x") == [Message(role="user", content="hi x")]
