"""Stage 3 of the reader: the office's words → readings, with what is still in doubt.

The lexicon's mentions are read in their sentence: an item word used as a verb ("book me a
taxi") is a plain word, a task word after a possessive ("Fang's seal") is the item, and a
later sentence that names one of the people an ambiguous name may mean ("... Zhnag's stapler.
Zhang Wei") settles it. What is still in doubt after that is kept as the question to ask
before anything is read as a task: a name that may be an ordinary word ("Do you mean Grace
Huang, or the grace period talk?"), a name several people share, a capitalized name nobody
here has, a facility whose services the assistant cannot run.
"""

from __future__ import annotations

from collections.abc import Collection, Sequence
from dataclasses import dataclass, replace

from assistantx.agents.symbolic.reading.carried_to import carried_to
from assistantx.agents.symbolic.reading.codes import code_of_a_thing
from assistantx.agents.symbolic.reading.described_outsider import named_things, outsider_origin
from assistantx.agents.symbolic.reading.described_owner import described_role
from assistantx.agents.symbolic.reading.destination import (
    Outside,
    find_outside,
    means_modifiers,
    means_words,
    verb_phrases,
)
from assistantx.agents.symbolic.reading.destination_detail import naming_words
from assistantx.agents.symbolic.reading.errand import errand_verbs, facility_pronouns
from assistantx.agents.symbolic.reading.event_clause import in_later_event
from assistantx.agents.symbolic.reading.given_name_meant import GivenNameMeant
from assistantx.agents.symbolic.reading.lexicon import (
    COMMON,
    PRONOUNS,
    Lexed,
    Lexicon,
    Mention,
    describing_participles,
    key_of,
)
from assistantx.agents.symbolic.reading.made_for_outsider import made_for_outsider
from assistantx.agents.symbolic.reading.occasion import occasion_people
from assistantx.agents.symbolic.reading.outside_name import as_outside_words, outside_names
from assistantx.agents.symbolic.reading.outsider_owner import (
    clause_opening_owner,
    common_noun_owner,
    described_before,
    office_people_words,
    titled_outsider,
)
from assistantx.agents.symbolic.reading.own_papers import kind_of_people
from assistantx.agents.symbolic.reading.owned_facility import runs_into_a_noun
from assistantx.agents.symbolic.reading.paper_topic import about_a_name
from assistantx.agents.symbolic.reading.possessed_thing import possessed
from assistantx.agents.symbolic.reading.possessive_choice import theirs_or_any
from assistantx.agents.symbolic.reading.result_form import INTO_WORDS, products, result_form
from assistantx.agents.symbolic.reading.said_of import without_states
from assistantx.agents.symbolic.reading.send_off import sent_off
from assistantx.agents.symbolic.reading.team_source import TeamSources, unknown_team
from assistantx.agents.symbolic.reading.title_words import inside_a_title
from assistantx.agents.symbolic.reading.titled_stranger import titled_stranger
from assistantx.agents.symbolic.reading.tokens import Token, gaps, prev_word
from assistantx.core import english, language, task_kinds
from assistantx.core.office import Office
from assistantx.core.task_schema import SHAPE_KIND
from assistantx.core.wording import verb_alone, verb_it

# Words that may stand before an item word used as a verb ("can u book ...", "pls water ...").
_BEFORE_VERB = english.words("before_verb") | {""}  # "": the start of the text
_DETERMINERS = english.words("determiners")
# Words of time that may follow a name ("for Kowalski tomorrow"), never a noun it describes.
_WHEN = (
    english.words("later_times")
    | english.words("past_times")
    | {
        "today",
        "morning",
        "afternoon",
        "evening",
        "night",
        "weekend",
        "asap",
    }
)
_ARTICLES = frozenset({"a", "an", "the", "some", "any"})
_A = frozenset({"a", "an", "another"})
# words after which a service's word may be a noun ("a courier bag", "their courier")
_DETERMINERS = _ARTICLES | _A | {"my", "your", "his", "her", "our", "their", "this", "that"}
_PLACE_PREPOSITIONS = english.words("to_facility_prepositions") | english.words(
    "from_facility_prepositions"
)
_LOCATION_PREPOSITIONS = english.words("location_prepositions")
# Where a thing is wanted may also be a surface or a floor of a room ("paper on the studio
# floor", "on the deck"): said of a facility nobody's service is asked of, "on" names a place
_WANTED_AT = _LOCATION_PREPOSITIONS | {"on"}
_TITLE_WORDS = frozenset({"dr", "mr", "mrs", "ms", "prof", "professor", "doctor"})
# The question when a send-out service's destination is a place or group of the office; the
# answer names the place outside instead (``InstructionParser.parse_with_answers``).
HERE_NOT_OUTSIDE = " is here in the office, and I "


@dataclass(frozen=True)
class Readings:
    """What the readings stage hands on: the mentions as read in their sentences, the
    punctuation before each token, the first doubt to ask about (or None), and where a
    send-out service sends the item (``destination``)."""

    text: str
    tokens: tuple[Token, ...]
    mentions: tuple[Mention, ...]
    gaps: tuple[str, ...]
    doubt: str | None
    outside: Outside | None = None  # a send-out service's verb phrase and destination
    # the hurrying verbs of errands carried across the office ("run it over to Will"): plain
    # words, never a service's verb (``errand.errand_verbs``)
    errands: frozenset[int] = frozenset()
    # the tokens of places outside said by their proper names ("to the Leeds *Print* Works"):
    # never a service's verb (``outside_name``)
    proper: frozenset[int] = frozenset()


class MentionReader:
    """Reads the lexicon's mentions of one office in their sentences."""

    def __init__(self, office: Office, lex: Lexicon) -> None:
        self.office = office
        self.lex = lex
        self._given_name = GivenNameMeant(office, key_of, lex.family, lex.bare)
        # the words of what the office's services make and of the services' names ("PDF" of
        # "scanned PDF", "scan to PDF"): said after "to"/"into"/"as", the form of a result
        # ("scan my waybill to PDF"), never someone to look up
        self._result_words = _result_words(office)
        # every word of the office's names for its people: "the judge's" where someone is
        # "the Judge's Clerk" is one of them, never an outsider by a common noun
        self._people_words = office_people_words(office)
        # short names of facilities and places said after "from" ("from QA")
        self._teams = TeamSources(office)
        self._service_verbs = frozenset(v.lower() for op in office.operations for v in op.verbs)
        # the verb phrases of services that send an item out of the office (a fax, a
        # courier), first word in any form: what follows their "to" is a destination outside,
        # not a colleague to look up. A phrase counts whole ("send out", never plain "send").
        self._sends_out = tuple(
            vp
            for op in office.operations
            if op.sends_out
            for vp in verb_phrases(
                op.id, (*op.verbs, op.name, *means_words(op.name)), means_modifiers(op.name)
            )
        )
        # the words that name how each one's place is reached ("the fax number": number)
        self._details = {
            op.id: naming_words(op.destination_asked) for op in office.operations if op.sends_out
        }
        self._send_inputs = {op.id: op.input for op in office.operations if op.sends_out}
        self._send_forms = {
            op.id: frozenset(
                f
                for v in (*op.verbs, *means_words(op.name))
                for f in _phrase_forms(language.fold(v))
            )
            for op in office.operations
            if op.sends_out
        }
        self._products = products(office)  # "scan to PDF ...": what the work makes
        self._kind_of = {
            op.id: kind
            for op in office.operations
            if (kind := SHAPE_KIND.get(op.shape(office))) is not None
        }

    def read(self, lexed: Lexed, requester: str | None = None) -> Readings:
        tokens = lexed.tokens
        mentions = verb_uses(tokens, self._owned_cue_items(lexed.mentions, tokens), self._products)
        if requester is not None:
            mentions = not_the_writer(mentions, requester)
        mentions = participle_adjectives(tokens, mentions)
        mentions = without_states(tokens, mentions)  # "a torque wrench going spare"
        mentions = self._noun_uses(tokens, mentions)
        mentions = self._teams.read(tokens, mentions)  # "from QA": the QA lab's store
        spaces = gaps(lexed.text, tokens)
        # "to the Leeds Print Works", "at the Birmingham Assay Office": a place's proper name
        # outside; its words name no service, colleague or thing of the office
        places_outside = outside_names(tokens, spaces, mentions)
        mentions = as_outside_words(tokens, mentions, places_outside)
        proper = {k for start, end in places_outside for k in range(start, end)}
        # "run it over to them": an errand carried across the office, to the one desk named
        mentions, errands = errand_verbs(tokens, spaces, mentions)
        mentions = facility_pronouns(tokens, mentions)
        # a word of a place's or a person's name ("the post room") is never the verb, nor a
        # hurrying verb of an errand
        names = {
            k for m in mentions if m.kind in ("place", "person") for k in range(m.start, m.end)
        } | errands
        # nor a participle that describes the item ("bring me my *couriered* contract")
        names |= describing_participles(tokens, mentions)
        outside = find_outside(tokens, spaces, self._sends_out, names, self._details, proper)
        plain = None
        if (outside is None or outside.start is None) and self._send_inputs:
            # "need sending off to Edexcel", "send it to Parkside Laundry to be laundered"
            plain = sent_off(tokens, spaces, mentions, self._send_inputs, self._send_forms, names)
            if plain is not None and outside is not None and plain.operation != outside.operation:
                plain = None
        if plain is not None:
            outside = plain  # "sending" said in plain English: the service's verb here
        elif (
            outside is not None
            and _after_a_determiner(tokens, outside.verb_start)
            and not any(
                m.start == outside.verb_start
                and (
                    m.kind == "cue"
                    or (m.kind == "facility" and outside.means)
                    or (m.kind == "word" and outside.means and _phrase_ends(tokens, spaces, m.end))
                )
                for m in mentions
            )
        ):
            # "a courier bag": the service's word used as a noun (after a determiner), not its
            # verb ("need sending off to AQA" is the verb); but "by
            # courier", "with the courier" name the service as the means (also where a
            # facility is so called), the noun ending its phrase (never "the courier bag")
            outside = None
        inside = self._inside(tokens, mentions, outside) if outside is not None else None
        if outside is not None:
            mentions = self._sent_out(tokens, mentions, outside)
        settled = _settled_by_later_sentence(mentions, spaces)
        settled = self._given_name.settle(tokens, settled)  # "need frank to sign ..."
        doubts = ([inside] if inside else []) + self._doubts(tokens, settled, outside, proper)
        doubts += self._possessive_doubts(lexed.text)
        return Readings(
            lexed.text,
            tokens,
            tuple(settled),
            spaces,
            doubts[0] if doubts else None,
            outside,
            errands,
            frozenset(proper),
        )

    def _inside(
        self, tokens: Sequence[Token], mentions: Sequence[Mention], outside: Outside
    ) -> str | None:
        """ "fax my contract to the green room", "courier it to the Company": a destination
        that is a place, a facility or a group of this office is no place outside; the
        service sends things out, so ask where (a colleague's name is asked about apart)."""
        if outside.start is None or outside.end is None:
            return None
        said = [t.word for t in tokens[outside.start : outside.end]]
        while said and said[0] in _ARTICLES | {"our"}:
            said = said[1:]
        phrase = " ".join(said)
        groups = {language.fold(g.name): g.name for g in self.office.groups}
        if phrase in groups:
            name = f"the {groups[phrase]} group"
        else:
            here = [
                m
                for m in mentions
                if m.kind in ("place", "facility") and outside.holds(m.start)
                if m.end == outside.end and m.end - m.start == len(said)
            ]
            if not here:
                return None
            said_name = here[0].text
            if here[0].kind == "facility" and said_name.lower() in PRONOUNS:
                said_name = self.office.facility(here[0].id).name  # "them": the desk meant
            name = f"the {said_name}"
        op = self.office.operation(outside.operation)
        return (
            f"{name[:1].upper()}{name[1:]}{HERE_NOT_OUTSIDE}{verb_alone(op)} things to "
            f"places outside it. Where should I {verb_it(op, bare=True)} to?"
        )

    def _sent_out(
        self, tokens: Sequence[Token], mentions: Sequence[Mention], outside: Outside
    ) -> list[Mention]:
        """The send-out verb phrase read whole as its service's task word ("send out" is
        the courier, not a plain "send"), and the destination's words as plain words (a
        firm, "the client": never a colleague to find or hand anything to)."""
        out: list[Mention] = []
        kind = self._kind_of.get(outside.operation)
        for m in mentions:
            if kind is not None and outside.verb_start <= m.start < outside.verb_end:
                if m.start == outside.verb_start:
                    words = tokens[outside.verb_start : outside.verb_end]
                    said = " ".join(t.text for t in words)
                    out.append(Mention("cue", m.start, outside.verb_end, (kind,), False, said))
                continue
            if outside.holds(m.start) and m.kind != "word":
                word = tokens[m.start].word
                m = Mention("word", m.start, m.end, (word,), False, m.text)
            out.append(m)
        return out

    def _owned_cue_items(
        self, mentions: Sequence[Mention], tokens: Sequence[Token]
    ) -> list[Mention]:
        """ "Fang's seal", "my stamp", "Ngozi's sworn stamp": a task word after a possessive
        (and up to two words that describe it) names an item."""
        out = list(mentions)
        for n in range(1, len(out)):
            m = out[n]
            word = tokens[m.start].word
            if m.kind != "cue" or word not in self.lex.items:
                continue
            k = n - 1
            while k > 0 and n - k <= 2 and _describes(out[k], tokens):
                k -= 1
            if out[k].possessive:
                out[n] = Mention("item", m.start, m.end, (self.lex.items[word],), False, m.text)
        return out

    def _noun_uses(self, tokens: Sequence[Token], mentions: Sequence[Mention]) -> list[Mention]:
        """ "bring me the couriers", "a courier bag": a service's verb right after an article
        is a noun (a plural, or the first noun of a compound), not a request for the service;
        "a scan of my form", "a print please" still name the service's work."""
        out = list(mentions)
        for n, m in enumerate(out):
            word = tokens[m.start].word
            if m.kind != "cue" or m.end - m.start != 1 or m.start == 0:
                continue
            if tokens[m.start - 1].word in _ARTICLES and self._made_from_nothing(word):
                # "make me a brew" where brewing makes tea, also called "a brew": the thing
                # made, asked for by its name, never a request with nothing to work on
                item = (self.lex.items[word],)
                out[n] = Mention("item", m.start, m.end, item, False, m.text)
                continue
            if word not in self.lex.operation_words or not language.is_noun(word):
                continue
            after = tokens[m.end].word if m.end < len(tokens) else ""
            plural = word not in language.lemmas(word)["NOUN"]  # "the couriers"
            compound = (
                bool(after)
                and after not in COMMON
                and language.is_noun(after)
                and not tokens[m.end].after_pause  # "a proofread, deal with it"
            )
            if tokens[m.start - 1].word in _ARTICLES and (plural or compound):
                out[n] = Mention("word", m.start, m.end, (word,), False, m.text)
        for n, m in enumerate(out):
            # "bring me a binder", "a printer cable": a thing asked for by a name a facility
            # also has, never the facility's service; "on a charging shelf" is the place
            if m.kind != "facility" or m.start < 1 or tokens[m.start - 1].word not in _A:
                continue
            if m.start < 2 or tokens[m.start - 2].word not in _PLACE_PREPOSITIONS:
                out[n] = Mention("word", m.start, m.end, (tokens[m.start].word,), False, m.text)
        return out

    def _paper_about(self, tokens: Sequence[Token], mentions: Sequence[Mention], n: int) -> bool:
        """ "the insurance form for Biscuit", "my claim for Rex", "the purchase order from
        Harlow Dairy": a name nobody in the office has, right after a personal paper and
        "for" or "from", says what the paper is about or where it came from (a patient, a
        supplier), not someone to hand it to or fetch it from; an ordinary thing "for Bob"
        still asks who Bob is. Only capitalised words that name nothing of the office. After
        "from", any thing whose owner is said by a possessive right before it ("Zhang's file
        from Berlin", "Miles's logs from Suzuka") is the same: its owner is known, so the
        unknown word is where it came from, not someone to fetch it from."""
        m = mentions[n]
        if not m.text[:1].isupper() or m.possessive:
            return False
        while (  # "Harlow Dairy": the name's first word
            n >= 1
            and mentions[n - 1].kind == "word"
            and mentions[n - 1].end == m.start
            and mentions[n - 1].text[:1].isupper()
            and not mentions[n - 1].possessive
        ):
            n -= 1
            m = mentions[n]
        at = m.start
        while at > 0 and tokens[at - 1].word in _TITLE_WORDS:
            at -= 1  # "the impression for Mrs Kaur": a title before the name
        if at < 2 or tokens[at - 1].word not in ("for", "from"):
            return False
        before = next((x for x in mentions if x.end == at - 1), None)  # the paper, "for"
        if before is not None and _unknown_thing(tokens, before):
            # "print the quote for Riverside House and give it to Wang": a thing the office
            # has no name for, about the name as a paper would be; what it is, asked after
            return tokens[at - 1].word == "for" and about_a_name(tokens, mentions, n, "personal")
        if before is None or before.kind != "item" or len(before.ids) != 1:
            return False
        if tokens[at - 1].word == "from" and _owned_by_possessive(mentions, before):
            # "Zhang's file from Berlin": the thing has its owner already, so "from" says
            # where it came from (a place outside), whatever kind of thing it is
            return True
        kind = self.office.item_type(before.id).kind
        if kind == "personal":
            return True
        # "the pre-plan for Kestrel Mills ... give it to Eilidh": a place's or firm's name,
        # or a name beside the colleague who gets it, says what the paper is about
        return tokens[at - 1].word == "for" and about_a_name(tokens, mentions, n, kind)

    def _result_form(self, tokens: Sequence[Token], m: Mention) -> bool:
        """Whether ``m`` is one word of a product or service name said after "to", "into"
        or "as" ("... to PDF"), in a message that names one of the office's services."""
        if m.end - m.start != 1 or m.start < 1 or tokens[m.start - 1].word not in INTO_WORDS:
            return False
        if tokens[m.start].word not in self._result_words:
            return False
        verbs = self._service_verbs
        # "scan it to PDF", and "I need my form scanned to PDF": a service's verb in any form
        return any(t.word in verbs or language.verb_lemmas(t.word) & verbs for t in tokens)

    def _made_from_nothing(self, word: str) -> bool:
        """Whether ``word`` names the product of a service that makes it from nothing."""
        item = self.lex.items.get(word)
        return item is not None and any(
            op.product == item and op.input is None for op in self.office.operations
        )

    def _doubts(
        self,
        tokens: Sequence[Token],
        mentions: Sequence[Mention],
        outside: Outside | None,
        proper: Collection[int] = (),
    ) -> list[str]:
        out: list[str] = []
        for n, m in enumerate(mentions):
            if outside is not None and outside.holds(m.start):
                continue  # "fax it to Harlow Ltd": a place outside, not someone to find
            if m.start in proper:
                continue  # "from Stapler House": a word of a place's name, nobody to find
            if m.kind == "person" and m.alternative and len(m.ids) == 1:
                name = self.office.person(m.id).name
                out.append(f"Do you mean {name}, or {m.alternative}?")
            if m.kind == "person" and len(m.ids) > 1:
                names = " or ".join(self.office.person(i).name for i in m.ids)
                said = m.text.replace("’", "'").removesuffix("'s").removesuffix("'")
                out.append(f"Who do you mean by {said!r}: {names}?")
            if m.kind == "word" and self._paper_about(tokens, mentions, n):
                continue  # "the insurance form for Biscuit": whom the paper is about
            if m.kind == "word" and in_later_event(tokens, m.start):
                continue  # "before it goes to Acme": when, by what happens to it later
            if m.kind == "word" and self._result_form(tokens, m):
                continue  # "scan my signed waybill to PDF": the result's form, not a person
            if m.kind == "word" and outsider_origin(tokens, m.start, named_things(mentions)):
                continue  # "a visitor from Shenzhen": where an outsider comes from, a place
            if m.kind == "word" and unknown_team(tokens, m):
                continue  # "from HR": a team, any one of the thing will do
            if m.kind == "word" and inside_a_title(tokens, mentions, n):
                continue  # "Notices to Mariners": a word of a thing's title, nobody's name
            if m.kind == "word" and made_for_outsider(
                self.office, tokens, mentions, n, self._people_words
            ):
                continue  # "chopped quail for Blaze please": made for the speaker's use
            if m.kind == "word" and _unknown_name(tokens, mentions, n, self._people_words):
                name = m.text.replace("’", "'").removesuffix("'s").removesuffix("'")
                out.append(f"I don't know anyone called {name!r} in this office. Who do you mean?")
            if m.kind == "facility" and _where_an_item_is_wanted(tokens, mentions, n):
                continue  # "a tape measure in the rehearsal room": the place, not its service
            if m.kind == "facility" and _where_an_occasion_is(tokens, mentions, n):
                continue  # "to the lounge for Mark's workshop": where it is, not its service
            if m.kind == "facility" and _modifies_a_thing(tokens, m):
                continue  # "print my hydro session plan": what the paper is about
            if m.kind == "facility" and carried_to(tokens, mentions, n):
                continue  # "take my stapler to the meeting room": where it goes
            if m.kind == "facility" and self._unsupported_facility(m.id):
                f = self.office.facility(m.id)
                out.append(
                    f"Sorry, I can't help with the {f.name}. I can fetch and deliver things, "
                    "pass on files, and run errands at the office machines. What would you "
                    "like me to do?"
                )
        return out

    def _possessive_doubts(self, text: str) -> list[str]:
        """ "grab bills ruler" where Bill keeps no ruler: Bill's (which he lacks) or any
        ruler are different errands, so ask which (``bare_possessives``)."""
        out: list[str] = []
        for word, item, _ in self.lex.doubted_possessives(text):
            ids = {*self.lex.people.get(word, ()), *self.lex.name_words.get(word, ())}
            if len(ids) != 1 or not self.office.is_person(next(iter(ids))):
                continue  # a name several people share is asked about as such
            name = self.office.person(next(iter(ids))).name
            out.append(theirs_or_any(name, item))
        return out

    def _unsupported_facility(self, facility_id: str) -> bool:
        """A facility whose operations are none the assistant can run (a meeting room)."""
        ops = self.office.facility(facility_id).operations
        return bool(ops) and not any(self.office.runnable(op) for op in ops)


def _phrase_forms(verb: str) -> frozenset[str]:
    """Every form of a verb, a phrase's by its last word ("dry clean" → "dry cleaned"): a
    declared phrase is one token of the lexicon, its last word inflected."""
    *head, last = verb.split() or [""]
    return frozenset(language.verb_forms(verb)) | {
        " ".join([*head, form]) for form in language.verb_forms(last)
    }


def _where_an_item_is_wanted(tokens: Sequence[Token], mentions: Sequence[Mention], n: int) -> bool:
    """ "need a tape measure in the rehearsal room": a facility after a location preposition,
    in a sentence that names an item, says where the item is wanted, not which service is
    asked for; a room whose service nobody runs is then no reason to refuse."""
    start = mentions[n].start
    while start > 0 and tokens[start - 1].word in _ARTICLES:
        start -= 1
    if start == 0:
        return False
    before = tokens[start - 1].word
    # "bring my bass down from the tuning room lockers", "out of the cold store": where the
    # item is taken from is a place too
    taken_from = before == "from" or (
        before == "of" and start >= 2 and tokens[start - 2].word == "out"
    )
    if before not in _WANTED_AT and not taken_from:
        return False
    return any(m.kind == "item" for i, m in enumerate(mentions) if i != n)


def _where_an_occasion_is(tokens: Sequence[Token], mentions: Sequence[Mention], n: int) -> bool:
    """ "take a ruler to the lounge for Mark's workshop", "... to the lounge for Mark": a
    facility a thing is taken to, in a sentence that names the colleague (or their occasion)
    the thing is for, is where it goes for them, not which service is asked for
    (``occasion``)."""
    start = mentions[n].start
    while start > 0 and tokens[start - 1].word in _ARTICLES:
        start -= 1
    if start == 0 or tokens[start - 1].word not in ("to", "into", "at"):
        return False
    has_item = any(m.kind == "item" for i, m in enumerate(mentions) if i != n)
    return has_item and bool(occasion_people(tokens, mentions))


_OWN = ("my", "our")
# "the client's contract", "this customer's form": an outsider the speaker serves, named by a
# determiner, is as much the speaker's care as "my client's" (nobody of the office holds it)
_OUTSIDER_DETERMINERS = (*_OWN, "the", "this", "that", "a", "an")
# people named by what they are, nobody of the office ("client", "patient")
_OUTSIDERS = english.words("outsider_nouns")


def _unknown_name(
    tokens: Sequence[Token], mentions: Sequence[Mention], n: int, people_words: frozenset[str]
) -> bool:
    m = mentions[n]
    word = tokens[m.start].word
    if word in COMMON or word in PRONOUNS or word.isdigit() or len(word) < 2:
        return False
    if language.is_month(word) or language.is_weekday(word):
        return False  # "from March", "by Friday": a date
    if any(c.isdigit() for c in word):
        return False  # "down to A4", "for the Y9 trip": a size or a code, nobody's name
    following = mentions[n + 1] if n + 1 < len(mentions) else None
    if m.possessive:  # "Kit's *signed* statement": the thing past the words describing it
        following = possessed(tokens, mentions, n)
    prev = prev_word(tokens, m.start, skip_titles=False)
    if m.possessive and following is not None and following.kind == "item":
        # "Smith's stapler"; but "an editor's notebook": a kind of person, said in lower
        # case after "a", is an ordinary noun, no name to look up
        # "my client's certificate", "our patient's notes": the same for an outsider the
        # speaker serves, named by what they are to them (the thing is the speaker's, kept
        # for them); "my colleague's form" still asks who is meant
        lower = m.text[:1].islower()
        kind_of_person = lower and prev in ("a", "an") and language.is_noun(word)
        # "the trustees' file", "the governors' report doc": a plural of people in lower
        # case, its apostrophe after the s, after a determiner: a kind of paper, no name
        kind_of_person = kind_of_person or kind_of_people(tokens, m)
        # "client's laptop lost a key": the same with the article dropped where the owner
        # opens the message or a clause of it; an office's own word for its people asks
        bare = m.start == 0 or tokens[m.start].opens or tokens[m.start].after_pause
        outsider = lower and word in _OUTSIDERS and word not in people_words
        outsider = outsider and (prev in _OUTSIDER_DETERMINERS or bare)
        # "mr okafor's order is in my tray, ...": a title and a name nobody of the office has,
        # opening the message or a clause, is a stranger whose thing is told of, no colleague
        # to ask about ("bring me Mr Smith's stapler" asks for it: who is meant is asked)
        title = m.start - 1
        told = title == 0 or (title > 0 and (tokens[title].opens or tokens[title].after_pause))
        outsider = outsider or (titled_outsider(prev) and told)
        # "the chiropodist's invoice": any common noun names a kind of person, not a list
        # "... for the owner's file": a "for" before the determiner says what it is for
        purpose = prev_word(tokens, m.start - 1, skip_titles=False) == "for"
        outsider = outsider or common_noun_owner(word, m.text, prev, people_words, purpose=purpose)
        # "a new starter's pass", "our external contractor's badge": the same with words that
        # describe the person between the determiner and the noun
        described = described_before(tokens, m.start)
        if described is not None and not outsider:
            det, at = described
            purpose = prev_word(tokens, at, skip_titles=False) == "for"
            outsider = common_noun_owner(word, m.text, det, people_words, purpose=purpose)
        # "..., visitor's pen just ran out": the same with the article dropped, the owner
        # opening a later clause (a reason said after the request)
        opens_clause = m.start > 0 and (tokens[m.start].opens or tokens[m.start].after_pause)
        outsider = outsider or clause_opening_owner(word, m.text, opens_clause, people_words)
        # "the site engineer's report": a kind of person described after the determiner
        outsider = outsider or described_role(tokens, m, people_words)
        return not (kind_of_person or outsider)
    if m.possessive and titled_outsider(prev):
        return False  # "to check Mrs Baker's sats": an outsider said as context, no colleague
    capital = m.text[:1].isupper() and m.start > 0
    titled = prev in _TITLE_WORDS
    if titled_stranger(tokens, m.start, ()) and prev_word(tokens, m.start - 1) == "for":
        # "one for Mrs Jenkins", "book a slot for Mr Evans": whom the work is for, outside
        # the office; a "for" that hands a thing to them the screen has asked about already
        return False
    if prev == "for" and _modifies_next(tokens, m.end):
        return False  # "for PE cover", "for Year 9": what it is for, nobody's name
    if code_of_a_thing(tokens, mentions, n):
        return False  # "the bag for LIS": an airport's code, nobody's name
    return capital and (
        titled or prev in ("to", "for", "from", "by", "ask") or _given_to(tokens, m)
    )


# "get Priya a coffee", "bring Tomasz the spare key": the verbs that take whom a thing is for
# before the thing, and what opens the thing (its determiner or count)
_GIVING = english.words("dative_verbs")
_THING_OPENERS = (
    english.words("object_starts")
    | english.words("object_quantifiers")
    | frozenset({"one", "another"})
)


def _given_to(tokens: Sequence[Token], m: Mention) -> bool:
    """Whether ``m`` stands between a verb of handing and the thing handed: whom it is for
    ("get Priya a coffee"), a name to look up like one after "for" is."""
    if m.start < 1 or m.end >= len(tokens) or tokens[m.start].possessive:
        return False
    return tokens[m.start - 1].word in _GIVING and tokens[m.end].word in _THING_OPENERS


def _modifies_next(tokens: Sequence[Token], at: int) -> bool:
    """Whether the word before ``at`` describes the next one, in one phrase: a common noun
    written in lower case ("PE *cover*", "Drama *club*") or a number ("Year *9*")."""
    if at >= len(tokens) or tokens[at].after_pause or tokens[at - 1].possessive:
        return False
    after = tokens[at]
    if after.word.isdigit():
        return True
    if not after.text.islower() or after.word in COMMON or after.word in PRONOUNS:
        return False
    if after.word in _WHEN or language.is_weekday(after.word) or language.is_month(after.word):
        return False  # "for Kowalski tomorrow": a time after a name, still someone to ask about
    return language.is_noun(after.word)


def _settled_by_later_sentence(mentions: Sequence[Mention], spaces: Sequence[str]) -> list[Mention]:
    """ "Bring me Zhnag's stapler. Zhang Wei": a later sentence that names one of the people
    an ambiguous name may mean settles it (the answer to "who do you mean?"), and is used up."""
    out = list(mentions)
    used: set[int] = set()
    for n, m in enumerate(out):
        if m.kind != "person" or len(m.ids) < 2:
            continue
        for k in range(n + 1, len(out)):
            later = out[k]
            new_sentence = any(c in gap for gap in spaces[m.end : later.start + 1] for c in ".!?;")
            if later.kind == "person" and len(later.ids) == 1 and later.id in m.ids:
                if new_sentence:
                    out[n] = Mention("person", m.start, m.end, later.ids, m.possessive, m.text)
                    used.add(k)
                break
    return [m for k, m in enumerate(out) if k not in used]


def not_the_writer(mentions: Sequence[Mention], requester: str) -> list[Mention]:
    """ "send my spreadsheet to Yang", written by Liu Yang where Yang Lei works too: people
    say "me" and "my" of themselves, so a name they share with a colleague means the
    colleague; the writer is no candidate while another one is left."""
    out = list(mentions)
    for n, m in enumerate(out):
        if m.kind == "person" and len(m.ids) > 1 and requester in m.ids:
            out[n] = replace(m, ids=tuple(i for i in m.ids if i != requester))
    return out


def verb_uses(
    tokens: Sequence[Token], mentions: Sequence[Mention], made: frozenset[str] = frozenset()
) -> list[Mention]:
    """Mentions with one-word items used as verbs ("book me a taxi") turned into plain words;
    a product of ``made`` said as a service's result ("scan to PDF my form") stays the item."""
    out = list(mentions)
    for n, m in enumerate(out):
        if m.kind != "item" or m.end - m.start != 1 or m.possessive:
            continue
        if result_form(tokens, out, n, made):
            continue
        before = tokens[m.start - 1].word if m.start > 0 else ""
        after = tokens[m.end].word if m.end < len(tokens) else ""
        if before in _BEFORE_VERB and after in _DETERMINERS:
            out[n] = Mention("word", m.start, m.end, (tokens[m.start].word,), False, m.text)
    return out


def participle_adjectives(tokens: Sequence[Token], mentions: Sequence[Mention]) -> list[Mention]:
    """ "send the signed form to Kasia": a person-service's past participle between a
    determiner (or a possessive) and the item it describes is an adjective, a plain word; the
    request is the sentence's own verb, not that service. Plain words that also describe
    the item may stand between ("courier the signed *publishing* contract")."""
    out = list(mentions)
    for n, m in enumerate(out[:-1]):
        if m.kind != "cue" or m.end - m.start != 1:
            continue
        if not set(m.ids) <= set(task_kinds.person_kinds()):
            continue  # "the printed report": an office service's product, read as before
        k, at = n + 1, m.end
        while k < len(out) - 1 and out[k].start == at and _describes(out[k], tokens):
            k, at = k + 1, out[k].end  # "the signed publishing contract"
        if out[k].kind != "item" or out[k].start != at or m.start == 0:
            continue
        before = tokens[m.start - 1]
        if before.word not in _DETERMINERS and not before.possessive:
            continue
        if language.is_past_participle(tokens[m.start].word):
            out[n] = Mention("word", m.start, m.end, (tokens[m.start].word,), False, m.text)
    return out


# What may follow a service's noun that ends its phrase: "with the courier *please*".
_AFTER_MEANS = frozenset({"please", "pls", "thanks", "thank", "today", "asap", "now", "and"})


def _after_a_determiner(tokens: Sequence[Token], at: int | None) -> bool:
    """Whether the word at ``at`` follows a determiner ("a courier bag", "my courier
    bag"), where a service's word may be a noun."""
    return at is not None and at > 0 and tokens[at - 1].word in _DETERMINERS


def _phrase_ends(tokens: Sequence[Token], spaces: Sequence[str], k: int) -> bool:
    """Whether the phrase ends before token ``k``: the message's end, a clause mark, or a
    courtesy or joining word ("with the courier, please"; never "with the courier bag")."""
    if k >= len(tokens):
        return True
    return any(c in ".,;!?\n" for c in spaces[k]) or tokens[k].word in _AFTER_MEANS


def _describes(m: Mention, tokens: Sequence[Token]) -> bool:
    """A plain word between a possessive and its thing that only describes it ("sworn",
    "official"): lower case, in the same phrase, no function word."""
    t = tokens[m.start]
    if m.kind != "word" or t.opens or t.after_pause or t.possessive or t.corrected:
        return False
    return t.text.isalpha() and t.text[:1].islower() and t.word not in COMMON


_NOT_NAME_WORDS = frozenset({"a", "an", "the", "to", "of", "and", "for", "into", "as", "up"})


def _result_words(office: Office) -> frozenset[str]:
    """The words of the office's product names and synonyms and of its services' names."""
    phrases: list[str] = [op.name for op in office.operations]
    for op in office.operations:
        if op.product:
            t = office.item_type(op.product)
            phrases += [t.name, *t.synonyms]
    words = {w for p in phrases for w in p.lower().split() if w.isalpha()}
    return frozenset(words - _NOT_NAME_WORDS)


_POSSESSIVES = frozenset({"my", "your", "our", "his", "her", "their"})


def _modifies_a_thing(tokens: Sequence[Token], m: Mention) -> bool:
    """Whether a facility's name said after "my"/"your"/... runs on into a noun ("my hydro
    session plan"): it describes the thing owned, not a service asked."""
    return m.start >= 1 and tokens[m.start - 1].word in _POSSESSIVES and runs_into_a_noun(tokens, m)


def _unknown_thing(tokens: Sequence[Token], m: Mention) -> bool:
    """Whether ``m`` is a lower-case noun after an article or a possessive that names nothing
    of the office ("the *quote*", "my *pre-plan*")."""
    return (
        m.kind == "word"
        and m.end - m.start == 1
        and m.text[:1].islower()
        and m.start > 0
        and tokens[m.start - 1].word in ("the", "my", "our", "this", "that")
        and language.is_noun(tokens[m.start].word)
    )


def _owned_by_possessive(mentions: Sequence[Mention], thing: Mention) -> bool:
    """Whether a possessive right before ``thing`` says whose it is ("Zhang's file", "my
    file"), a word of describing between them allowed ("Zhang's budget file")."""
    before = [x for x in mentions if x.end <= thing.start]
    if not before:
        return False
    last = before[-1]
    if last.kind == "word" and thing.start - last.end == 0 and len(before) > 1:
        last = before[-2]  # "Zhang's *budget* file": the describing word passed over
    return last.possessive and last.kind in ("person", "pronoun")
