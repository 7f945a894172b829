"""How the games' messages read in clemcore's transcripts (`clem transcribe` -> transcript.html).

clemcore renders a message either as escaped text with line breaks (leading spaces collapse, so a
loop body sits flush with its `for`) or, when the interactions record holds `"markdown": true`,
through Python-Markdown. Markdown alone does not help either: clemcore strips the backticks of a
message that is one fenced block (the most common answer), and an unfenced answer's lines run
together into one paragraph. So our game masters (the `MarkdownTranscript` base) set the key and
log every message in `display` form: fenced code as a code block, everything else as
preformatted text that keeps its line breaks and indentation and wraps long lines; all text is
HTML-escaped (model output is hostile input: no markup of a model reaches the reader's browser).
The texts themselves stay in each message action under `text` and in the players' requests files
(player_N.requests.json); the models never see the display form.

The mixin is also where a player's answer enters the game master (`step`): it is escaped there
once (sartco.text.escape: lone surrogates, control characters, bidi overrides as visible
escapes), so the parser, the sandbox, every record and every transcript see the same safe text;
when escaping changed it, the answer's action keeps the exact text as ASCII JSON under
`exact_json`. (The player escapes its own record the same way: sartco.clem.players.sourced.) Board pictures are `<img>` tags holding the SVG as a data: URL, each linked to its full-size file by a path relative to the episode folder
(`picture`), so a copied results folder still shows them.
"""
from __future__ import annotations

import base64
import html
import re

from sartco.episode import MARKDOWN_KEY  # the interactions.json key that switches clemcore's transcript to Markdown
from sartco.text import escape, exact_json

RAW_KEY = "text"           # a message action's text (its `content` is the display form)
EXACT_KEY = "exact_json"   # an answer's exact text as ASCII JSON, when escaping changed it
FENCE = re.compile(r"^[ \t]*```[^\n]*\n(.*?)^[ \t]*```[ \t]*$", re.M | re.S)  # a closed fenced block
PROSE_STYLE = "white-space: pre-wrap; margin: 0"  # the page's own (proportional) font
TEXT_STYLE = "white-space: pre-wrap; overflow-wrap: anywhere; margin: 0; font-family: monospace"  # grids line up
CODE_STYLE = ("white-space: pre-wrap; overflow-wrap: anywhere; margin: 4px 0; padding: 6px; background: #f6f8fa; "
              "border: 1px solid #d0d7de; border-radius: 4px; font-family: monospace")
# A line of grid or code inside plain text: a text grid's row ("[", "]"), an indented line, a
# call (lowercase, as Python's) or an assignment, a fence ("put(board, ...)", "x = 3"), a Python keyword line or a comment.
LITERAL = re.compile(r"^(\s|[\[\]#`]|[a-z_][\w.]*\(|[A-Za-z_]\w*\s*[-+*/]?=[^=]"
                     r"|(def|for|while|if|elif|else|return|import|from|with|try|except)\b)")


def text_block(text: str) -> str:
    """Plain text as HTML blocks that keep its line breaks and indentation: runs of grid or code
    lines (LITERAL; the describer's grid view, an unfenced answer's code) in monospace so that they
    line up, the prose between them in the page's proportional font."""
    runs: list[tuple[bool, list[str]]] = []
    for line in text.split("\n"):
        literal = bool(LITERAL.match(line)) if line.strip() else (runs[-1][0] if runs else False)
        if runs and runs[-1][0] == literal:
            runs[-1][1].append(line)
        else:
            runs.append((literal, [line]))
    return "\n".join(_run(literal, "\n".join(lines)) for literal, lines in runs) or _run(False, "")


def _run(literal: bool, text: str) -> str:
    kind, style = ("sartco-text", TEXT_STYLE) if literal else ("sartco-prose", PROSE_STYLE)
    return f'<div class="{kind}" style="{style}">{html.escape(text, quote=False)}</div>'


def code_block(code: str) -> str:
    """Code as a code block (monospace, indentation kept; long lines wrap rather than scroll)."""
    return (f'<pre class="sartco-code" style="{CODE_STYLE}"><code class="language-python">'
            f"{html.escape(code.rstrip(), quote=False)}</code></pre>")


def picture(svg: str, href: str, alt: str) -> str:
    """An SVG picture inside the page (a data: URL, so it needs no file beside the transcript),
    linked to its full-size file `href`, a path relative to the episode folder."""
    data = base64.b64encode(svg.encode("utf-8")).decode("ascii")
    return (f'<div class="sartco-picture"><a href="{html.escape(href)}" title="full size: {html.escape(href)}">'
            f'<img src="data:image/svg+xml;base64,{data}" alt="{html.escape(alt)}" style="max-width: 100%" /></a></div>')


def display(text: str) -> str:
    """A message in display form: closed ```-fenced blocks as code, the rest as preformatted text.
    An unclosed fence (an answer cut off at max tokens) stays text, verbatim."""
    blocks, pos = [], 0
    for match in FENCE.finditer(text):
        before = text[pos:match.start()].strip("\n")
        if before.strip():
            blocks.append(text_block(before))
        blocks.append(code_block(match.group(1)))
        pos = match.end()
    rest = text[pos:].strip("\n")
    if rest.strip() or not blocks:
        blocks.append(text_block(rest))
    return "\n\n".join(blocks)  # blank lines between HTML blocks: Markdown passes each through as is


class MarkdownTranscript:
    """BuildGameMaster's third base (sartco.clem.core.master), right before DialogueGameMaster,
    whose step and log methods it wraps: the transcript shows every
    message of the game in `display` form (the action's `content`, what clemcore renders), and the
    action keeps the text under `text` (RAW_KEY) for anyone who reads interactions.json.
    clemcore's `step` logs each exchange through these two methods (the same actions as clemcore's
    own, plus `text`); what the players receive and answer is unchanged."""

    def step(self, response):
        """clemcore's step with the answer escaped: the one entry of every answer, sequential or batched."""
        self._exact_answer = response
        return super().step(escape(response) if isinstance(response, str) else response)

    def log_gm_to_player(self, context, player):
        self.log_key(MARKDOWN_KEY, True)  # before the first message; the same value every time
        action = {"type": "send message", "content": display(context["content"]), "label": "context",
                  RAW_KEY: context["content"]}
        if "image" in context:
            action["image"] = context["image"]
        self.log_event(from_="GM", to=player.name, action=action)

    def log_player_to_gm(self, response, player):
        action = {"type": "get message", "content": display(response), "label": "response", RAW_KEY: response}
        exact = getattr(self, "_exact_answer", response)
        exact = exact_json(exact) if isinstance(exact, str) else None
        if exact:
            action[EXACT_KEY] = exact
        self.log_event(from_=player.name, to="GM", action=action)
