"""The screen's table: the rules tried on each piece in priority order; the first that
matches decides what the piece is (see the package's table)."""

from __future__ import annotations

from collections.abc import Callable

from assistantx.agents.symbolic.reading.screen.absent_owner import absent_owner
from assistantx.agents.symbolic.reading.screen.acknowledgement import acknowledgement
from assistantx.agents.symbolic.reading.screen.alternatives import alternatives
from assistantx.agents.symbolic.reading.screen.asked_doer import asked_doer
from assistantx.agents.symbolic.reading.screen.bare_fault import bare_fault
from assistantx.agents.symbolic.reading.screen.break_in import break_in
from assistantx.agents.symbolic.reading.screen.choices import choices
from assistantx.agents.symbolic.reading.screen.condition import condition
from assistantx.agents.symbolic.reading.screen.contrast import contrast
from assistantx.agents.symbolic.reading.screen.counted_reason import counted_reason
from assistantx.agents.symbolic.reading.screen.covert import covert
from assistantx.agents.symbolic.reading.screen.curious import asks_for_time, curious
from assistantx.agents.symbolic.reading.screen.cut_off import cut_off
from assistantx.agents.symbolic.reading.screen.dealing import dealing
from assistantx.agents.symbolic.reading.screen.destructive import destructive
from assistantx.agents.symbolic.reading.screen.doing_after import doing_after
from assistantx.agents.symbolic.reading.screen.elliptical import elliptical_reason
from assistantx.agents.symbolic.reading.screen.event_of import event_of
from assistantx.agents.symbolic.reading.screen.everyones import everyones
from assistantx.agents.symbolic.reading.screen.exclusion import exclusion
from assistantx.agents.symbolic.reading.screen.facility_report import facility_report
from assistantx.agents.symbolic.reading.screen.facility_state_asked import facility_state_asked
from assistantx.agents.symbolic.reading.screen.facility_variant import facility_variant
from assistantx.agents.symbolic.reading.screen.fact import back_when, fact
from assistantx.agents.symbolic.reading.screen.findings import Finding, Verdict
from assistantx.agents.symbolic.reading.screen.fyi import fyi
from assistantx.agents.symbolic.reading.screen.hope import hope
from assistantx.agents.symbolic.reading.screen.impersonation import impersonation
from assistantx.agents.symbolic.reading.screen.kept import several_kept
from assistantx.agents.symbolic.reading.screen.kept_where import kept_where
from assistantx.agents.symbolic.reading.screen.kind_of_product import kind_of_product
from assistantx.agents.symbolic.reading.screen.narrative import narrative_fragment, told_subject
from assistantx.agents.symbolic.reading.screen.need_to_know import need_to_know
from assistantx.agents.symbolic.reading.screen.negation import negated
from assistantx.agents.symbolic.reading.screen.note import note
from assistantx.agents.symbolic.reading.screen.nothing_follows import nothing_follows
from assistantx.agents.symbolic.reading.screen.on_a_thing import on_a_thing
from assistantx.agents.symbolic.reading.screen.one_of_several import several_of_theirs
from assistantx.agents.symbolic.reading.screen.opinion import opinion
from assistantx.agents.symbolic.reading.screen.ordering import ordering
from assistantx.agents.symbolic.reading.screen.others_doing import others_doing
from assistantx.agents.symbolic.reading.screen.others_plan import others_plan
from assistantx.agents.symbolic.reading.screen.others_send_out import others_send_out
from assistantx.agents.symbolic.reading.screen.outside_account import outside_account
from assistantx.agents.symbolic.reading.screen.outside_place import outside_place
from assistantx.agents.symbolic.reading.screen.outside_vehicle import outside_vehicle
from assistantx.agents.symbolic.reading.screen.outsider import outsider
from assistantx.agents.symbolic.reading.screen.own_doing import own_doing
from assistantx.agents.symbolic.reading.screen.own_intention import own_intention
from assistantx.agents.symbolic.reading.screen.own_need import own_need
from assistantx.agents.symbolic.reading.screen.own_use import own_use
from assistantx.agents.symbolic.reading.screen.owned_head import several_owned_heads
from assistantx.agents.symbolic.reading.screen.owner_leave import owner_leave
from assistantx.agents.symbolic.reading.screen.past_event import past_event
from assistantx.agents.symbolic.reading.screen.pieces import Message, Piece
from assistantx.agents.symbolic.reading.screen.placement import unplaced
from assistantx.agents.symbolic.reading.screen.private_spending import private_spending
from assistantx.agents.symbolic.reading.screen.problem import problem
from assistantx.agents.symbolic.reading.screen.pronoun_exclusion import pronoun_exclusion
from assistantx.agents.symbolic.reading.screen.pronoun_subject import unnamed_subject
from assistantx.agents.symbolic.reading.screen.purpose import (
    preamble,
    purpose,
    reason,
    tool_use,
)
from assistantx.agents.symbolic.reading.screen.question import question
from assistantx.agents.symbolic.reading.screen.recipients_doing import recipients_doing
from assistantx.agents.symbolic.reading.screen.recipients_reason import recipients_reason
from assistantx.agents.symbolic.reading.screen.ruled_out_place import ruled_out_place
from assistantx.agents.symbolic.reading.screen.running_machine import running_machine
from assistantx.agents.symbolic.reading.screen.service import unsupported
from assistantx.agents.symbolic.reading.screen.service_word_reason import service_word_reason
from assistantx.agents.symbolic.reading.screen.someones_job import someones_job
from assistantx.agents.symbolic.reading.screen.spite import spite
from assistantx.agents.symbolic.reading.screen.statement import statement
from assistantx.agents.symbolic.reading.screen.terms import Terms
from assistantx.agents.symbolic.reading.screen.thanks import thanks
from assistantx.agents.symbolic.reading.screen.timed_event import timed_event
from assistantx.agents.symbolic.reading.screen.unknown_test import unknown_test
from assistantx.agents.symbolic.reading.screen.unknown_work import unknown_work
from assistantx.agents.symbolic.reading.screen.unoffered_means import unoffered_means
from assistantx.agents.symbolic.reading.screen.unsafe import unsafe
from assistantx.agents.symbolic.reading.screen.variant import variant
from assistantx.agents.symbolic.reading.screen.whereabouts import whereabouts
from assistantx.agents.symbolic.reading.screen.whereabouts_reason import whereabouts_reason
from assistantx.agents.symbolic.reading.screen.wish import wish
from assistantx.agents.symbolic.reading.screen.withdrawal import withdrawn
from assistantx.agents.symbolic.reading.screen.wrong_input import wrong_input
from assistantx.agents.symbolic.reading.screen.wrong_instrument import wrong_instrument

# A rule reads one piece of a message with the office's terms; None: not this kind of piece.
Rule = Callable[[Terms, Message, Piece, str], Finding | None]

RULES: tuple[tuple[Verdict, Rule], ...] = (
    ("withdrawn", withdrawn),
    ("note", note),
    ("exclusion", exclusion),
    ("exclusion", pronoun_exclusion),
    # "she needs the umbrella" with nobody named: whom "she" means is asked, never the speaker
    ("which", unnamed_subject),
    # "my lamp" where two of the speaker's things are lamps: asked which, never guessed
    ("which", several_owned_heads),
    # "the stapler? or the scissors, not sure which": one of two, asked which
    ("which", alternatives),
    # a purpose, an open offer or the reason for a request: context before any rule reads
    # what it names ("so he can book the courier", "if anyone needs it", "need it for ...")
    ("statement", purpose),
    ("statement", reason),
    # "..., need the laundry numbers": a reason naming a service only as its topic
    ("statement", service_word_reason),
    # "..., he needs it for his file": why the colleague the request names needs it
    ("statement", recipients_reason),
    # "..., she needs to check my results first": what the colleague given to will do
    ("statement", recipients_doing),
    # what someone else wants to know ("a visitor wants to know the coffee prices"): a topic,
    # never a thing asked for
    ("statement", need_to_know),
    # the things to use a tool asked for on ("..., I've a pile of letters to seal")
    ("statement", tool_use),
    # "..., like 20 letters going out today": a count of the speaker's things, why it is asked
    ("statement", counted_reason),
    # what already happened to the speaker's own thing beside a request ("mine went in the
    # compost"): before a service or waste container its words name is read as asked for
    ("statement", past_event),
    # "Blaze flew brilliantly today, 2 mins to the lure and back to the fist": news told,
    # its subject nobody of the office, its fragments where it went; nothing fetched
    ("statement", told_subject),
    ("statement", contrast),
    # "I reckon the report needs a full rewrite": a view of what a thing needs, with no
    # request in the message, told; before its need is read as a thing wanted or declined
    ("statement", opinion),
    ("wish", wish),
    ("wish", hope),
    ("thanks", thanks),
    # "crystal clear, thanks!", "will do": said back, before a word of it is read as a name
    ("thanks", acknowledgement),
    # "..., 2 mins to the lure and straight back to the fist": a fragment of the news told
    # (after an acknowledgement: "..., all good" is one)
    ("statement", narrative_fragment),
    ("statement", curious),
    ("statement", asks_for_time),
    # "..., ground run in 10": an event's name and its time after a request, never a
    # service asked for (a modifier on a service's verb would decline it below)
    ("statement", timed_event),
    # "might heat my soup a bit later", "think I'll print my slides tomorrow": the speaker's
    # own plan, told, before its verb is read as work asked of me
    ("statement", own_intention),
    ("condition", condition),
    # "printer's down till tomorrow, so no printing": what the state rules out, told
    ("statement", nothing_follows),
    ("negated", negated),
    ("destructive", unsafe),
    # "get my mug out of the coffee machine while it's still brewing": declined in words
    ("destructive", running_machine),
    # "..., need to eat it": what the speaker will do with the thing, before its verb is
    # read as a doing asked of me
    ("statement", own_use),
    # "shred my stapler in the printer": a facility asked for work it does not do
    ("unsupported", wrong_instrument),
    # "run an NMR on my sample" where the office has no NMR: never its one analysis run
    ("unsupported", unknown_test),
    # "shred my coffee": a service's verb said of a drink the office makes, never one made
    ("unsupported", wrong_input),
    ("destructive", destructive),
    # "take Pat's card and log into her account": acting as a colleague, whatever the thing
    ("unsupported", impersonation),
    # "get Kwame's fuel card, need to fill up my own car": the workplace's money on oneself
    ("unsupported", private_spending),
    ("unsupported", outside_account),
    ("unsupported", absent_owner),
    ("unsupported", covert),
    # "disable Pat's badge so she can't get in": a colleague's thing acted on against them
    ("unsupported", spite),
    # every one of a kind colleagues own ("wipe all the drives"): never the speaker's own one
    ("unsupported", everyones),
    ("unsupported", break_in),
    ("unsupported", outside_place),
    # "order us some sandwiches": buying from outside, never a colleague's thing fetched
    ("unsupported", ordering),
    # "..., need to check levels on L2": the speaker's own doing, why the request is made,
    # before its place ("on L2") or its thing ("levels") is read as a placement asked
    ("statement", own_doing),
    # "Priya needs to measure a carton. take her my tape measure": what a colleague will
    # work on with the thing asked for, never a thing to fetch
    ("statement", others_doing),
    # "give Will my letter, she'll frank it later": what a colleague will do themselves,
    # never a service asked of the robot
    ("statement", others_plan),
    # "where's Mark? need a word about the franking": why the question is asked, its topic
    # never a service asked for
    ("statement", whereabouts_reason),
    ("unplaced", unplaced),
    ("unplaced", cut_off),
    # "put Wang's stapler in my car": a vehicle or a home is outside, after "chuck it in
    # the van" is asked
    ("unsupported", outside_vehicle),
    ("statement", elliptical_reason),
    # "..., Wang is on it": who deals with a fault, before "is on" is read as a whereabouts
    ("statement", dealing),
    ("fact", fact),
    ("statement", back_when),
    ("statement", facility_report),
    # "printer jammed again": a fault told with its auxiliary dropped
    ("statement", bare_fault),
    # "Wang can keep my stapler for now": an owner's leave, told
    ("statement", owner_leave),
    # "..., need a copy of the new signing": a thing of an occasion, why it is asked
    ("statement", event_of),
    ("statement", doing_after),
    ("statement", own_need),
    # "Dev's contract needs couriering to Leeds": someone else's thing, never sent on it
    ("statement", others_send_out),
    ("question", facility_state_asked),
    ("question", kept_where),
    ("question", question),
    ("question", choices),
    ("statement", problem),
    ("statement", statement),
    ("statement", on_a_thing),  # "oil on the stapler again": told of the thing, not asked
    ("statement", whereabouts),
    ("statement", ruled_out_place),  # "where's X? not on his desk": where it was not
    ("statement", someones_job),  # "someone's gonna have to ring the engineer": a remark
    ("statement", fyi),  # after the statements that say more ("Thanks for telling me ...")
    ("statement", preamble),  # a told sentence no rule above read, before a request
    ("which", several_kept),
    # "one of Sunny's tools" where Sunny has a pump, a multitool and levers: which, asked
    ("which", several_of_theirs),
    ("unsupported", variant),
    # "a flat white" where the machine makes coffee: "Shall I get you a coffee instead?"
    ("instead", kind_of_product),
    # "fire my jug in the raku kiln" where the office has one plain kiln: asked, never run on
    # the office's one
    ("instead", facility_variant),
    # a service nothing here offers is declined before an outsider recipient is asked
    # about: "scan my drawings and email them to the client" where there is no scanner
    # cannot be done for anyone, so a question would only offer what was never asked
    ("unsupported", unsupported),
    # "can you polish my boots", "sort out my mug": work the reader has no verb for, or work
    # unnamed, on a thing: declined or asked, never a transfer of the thing
    ("unsupported", unknown_work),
    # "get Zhang to make me a copy" where Zhang does not run the copier: asked, not rerouted
    ("instead", asked_doer),
    # "can my contract go out with the courier" where only the post sends: offered, not swapped
    ("instead", unoffered_means),
    ("instead", outsider),
)
