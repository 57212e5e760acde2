"""A bare alias that is another colleague's family name ("Morgan": Morgan Tallis's alias,
Priya Morgan's family name).

The office calls Morgan Tallis "Morgan", but English calls Priya Morgan so too: a family name
alone ("I'll ask Morgan", "to Morgan") is how colleagues speak of one another as often as a
given name is. So the bare word does not say which of the two is meant, and a hand-over to
the wrong one is a wrong physical act: the reader asks ("Who do you mean by 'Morgan': Morgan
Tallis or Priya Morgan?"). What does decide it is read as before: the full name, the other's
alias with its title ("Inspector Morgan") or a title of address ("Ms Morgan": a title goes
with a family name, ``surnames``), the given name with the family name's initial ("Morgan
T"), or the item only one of them owns.

An alias that is its own bearer's family name ("Lee" of Lee Ming, where the office writes the
family name first) doubts nothing, nor does a family name nobody is called by bare ("Wang":
Wang Fang alone)."""

from __future__ import annotations

from collections.abc import Mapping


def also_meant(word: str, bare: Mapping[str, set[str]], family: Mapping[str, set[str]]) -> set[str]:
    """The people a bare alias ``word`` may mean besides those the office calls so: everyone
    else whose family name it is (``family``: family name → people, ``surnames``)."""
    return family.get(word, set()) - bare.get(word, set())
