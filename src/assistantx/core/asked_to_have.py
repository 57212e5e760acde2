"""Asked to have: "could Nkechi have a pair of scissors?", "can Linh borrow a hole punch?",
"let Linh have the torch", "Linh could do with a hole punch". The person named is to be given
the thing, through the requester: they are its recipient, and whose thing it is stays open
(anyone's, its owner asked), never theirs. "Could I have Tomás's hole punch?" borrows Tomás's:
the requester is the one to have it, the possessive names the owner.

The reader (``agents.symbolic.reading._parties``, ``frames``) and the runtime's consent guard
(``runtime.recipients``) decide with this one function, so the guard lets the hand-over the
reader planned go to the person named. The words: a request modal ("could", "can", "may") or
"let" right before the name and a verb of having or borrowing right after it ("could Linh get
me ..." makes Linh the one who gets it for the requester, not a recipient; "let Linh get one"
and "could Linh get a coffee" do); or the name, then "could do with" or "should get" and the
thing ("Linh should get a copy of my notes"). A causative has the thing made for the one
named: "could Linh get my report printed", "can Zhang have his badge laminated" (``caused_for``).
"""

from __future__ import annotations

from collections.abc import Sequence

from assistantx.core import english, language

_ASKING = english.words("request_modals") | {"let"}
_HAVING = frozenset({"have", "borrow", "get"})
# "could Linh get a coffee": a thing right after "get" is what Linh is to have
_SOME = frozenset({"a", "an", "another", "some", "one"})
_DO_WITH = (["could", "do", "with"], ["can", "do", "with"])
# "Wang should get a copy": the name, then what they ought to receive ("should have" is a
# belief of where a thing is, "Wang should have one by now", never a receiving)
_SHOULD_GET = ["should", "get"]
# what opens the thing to be received ("should get me one" has Wang get it for the requester)
_THING_OPENERS = _SOME | {"the", "my", "our", "this", "these"}
# "could Marguerite have a look at my form": a preposition before the thing makes it what an
# activity is about, not what is given.
_ABOUT = frozenset({"at", "on", "over", "through", "about", "into", "for", "to"})


def asked_to_have(before: str, after: Sequence[str]) -> bool:
    """Whether the person named between the folded word ``before`` and the words ``after``
    (up to the thing asked for) is asked to be given it."""
    if list(after[:3]) in _DO_WITH:
        return True
    if list(after[:2]) == _SHOULD_GET and len(after) > 2 and after[2] in _THING_OPENERS:
        return True  # "Wang should get a copy of my report": who is to end up with it
    if before not in _ASKING or not after or after[0] not in _HAVING:
        return False
    if after[0] == "get" and before != "let" and (len(after) < 2 or after[1] not in _SOME):
        return False  # "could Linh get me one": Linh gets it for the requester
    return not any(w in _ABOUT for w in after[1:])


# "could Linh get/have my report printed": the verbs of a causative asked of a colleague
_CAUSING = frozenset({"get", "have"})
# what cannot open the thing the causative's work is done to ("could Linh get *me* one
# printed": Linh gets it for the requester); anything else may ("get *his* badge laminated",
# "get Ray Castillo's badge laminated", "get 5 copies made")
_NOT_THINGS = frozenset({"me", "us", "you", "him", "them", "it", "myself", "there", "here"})
# what ends the thing's noun phrase before any participle: the thing goes elsewhere, or a
# clause of its own follows ("could Linh get the report to me printed" is no causative of hers)
_CAUSED_ENDS = _ABOUT | {"me", "us", "and", "or", "from", "off", "then", "so", "if"}
# how many words the thing's noun phrase may run to before its participle ("a copy of my
# report made")
_CAUSED_SPAN = 6


def caused_for(before: str, after: Sequence[str]) -> bool:
    """Whether the person named between the folded word ``before`` (a request modal) and the
    words ``after`` is asked to have a thing made or worked on for them: "could Linh get my
    report printed", "can Zhang have his badge laminated", "can Lee get a copy of my report
    made" (the verb of having, the thing's noun phrase, then the work's past participle).
    The one named is whom the thing is for; "could Linh get me one printed" (Linh does it for
    the requester) and "could Linh get the signed form" (no work asked) are not."""
    if before not in english.words("request_modals") or len(after) < 4:
        return False
    if after[0] not in _CAUSING or after[1] in _NOT_THINGS or after[1] in _CAUSED_ENDS:
        return False
    for n, w in enumerate(after[2 : 2 + _CAUSED_SPAN], start=2):
        if w in _CAUSED_ENDS:
            return False
        if n > 2 and language.is_past_participle(w):
            return True  # a participle before the noun only describes it ("the signed form")
    return False
