"""What a thing is to be made into, said after the verb: "print my slides *as a poster*",
"print my artwork *as a pull-up banner*", "run it off *into a* booklet", "print it *on a*
roll-up banner".

The product after "as"/"into"/"on" (an article or a quantity word between) names the
operation whose product it is, where one facility's operation makes it and another's verb
("print") is only the means. Which words are products is the office's own data; a word after
"on" that is no product of an operation on the item ("print it on the printer", "on A3")
chooses nothing (``operations.OperationChooser`` keeps only the products of operations that
take the item)."""

from __future__ import annotations

from assistantx.agents.symbolic.reading.lexicon import Lexed
from assistantx.core import english

# the words before what an item is made into: "as labels", "into a PDF", "on a banner"
_INTO = frozenset({"as", "into", "on", "onto"})
# what may stand between them and the product: "as *a* poster", "into *two* booklets"
_BETWEEN = english.words("determiners") | {"a", "an", "the", "one", "two", "some"}


def made_products(lexed: Lexed) -> set[str]:
    """The item types said as what the thing is made into."""
    words = [t.word for t in lexed.tokens]
    made: set[str] = set()
    for m in lexed.mentions:
        if m.kind != "item":
            continue
        k = m.start - 1
        while k >= 0 and words[k] in _BETWEEN and m.start - k <= 2:
            k -= 1
        if k >= 0 and words[k] in _INTO and not lexed.tokens[m.start].after_pause:
            made.update(m.ids)
    return made
