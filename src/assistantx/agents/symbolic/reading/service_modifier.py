"""A thing said as what a service is done with: "my glove needs a virkon dip", "my bench needs
an oil wipe" where the office keeps virkon (or oil) as a thing of its own: after a need and its
article, a thing of the office right before the service's word describes the work (a dip *in
virkon*), it is not a second object the request leaves unexplained. It had asked "I'm not sure
what you want me to do with the disinfectant", where the service on the speaker's own thing
was asked. Only where the service's word follows the thing at once; "needs a virkon and a
dip" names two things."""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.agents.symbolic.reading.lexicon import Mention
from assistantx.agents.symbolic.reading.operation_nouns import NEEDING
from assistantx.agents.symbolic.reading.tokens import Token

_ARTICLES = frozenset({"a", "an", "another"})


def describes_work(tokens: Sequence[Token], mentions: Sequence[Mention], m: Mention) -> bool:
    """Whether item mention ``m`` stands between a need's article and a service's word."""
    if m.kind != "item" or m.start < 2:
        return False
    if not any(x.kind == "cue" and x.start == m.end for x in mentions):
        return False
    return tokens[m.start - 1].word in _ARTICLES and tokens[m.start - 2].word in NEEDING
