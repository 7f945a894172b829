"""Messages in clemcore's transcripts (sartco.clem.core.transcript.display): code as code with its
indentation, other text with its line breaks, model markup escaped."""
import markdown

from sartco.clem.core.transcript import display


def rendered(text: str) -> str:
    """What clemcore's transcript builder makes of a message in markdown mode."""
    return markdown.markdown(display(text).strip(), extensions=["fenced_code"])


def test_fenced_answer_is_code_with_its_indentation():
    html = rendered("```python\nfor x in range(2):\n    put(board, 'nut', 'red', x, 0)\n```")
    assert '<pre class="sartco-code"' in html
    assert "for x in range(2):\n    put(board, 'nut', 'red', x, 0)" in html


def test_unfenced_answer_keeps_lines_and_indentation():
    answer = "Output:\nfor x in range(2):\n    put(board, 'nut', 'red', x, 0)\n\n# done"
    html = rendered(answer)
    assert "for x in range(2):\n    put(board, 'nut', 'red', x, 0)\n\n# done</div>" in html
    assert "white-space: pre-wrap" in html and "<p>" not in html  # not run together into a paragraph
    # the code in monospace (it lines up), the prose before it in the page's own font
    assert html.index('<div class="sartco-prose"') < html.index("Output:") < html.index('<div class="sartco-text"')
    code = html[html.index('<div class="sartco-text"'):]
    assert "font-family: monospace" in code[:code.index(">")]


def test_grid_lines_are_monospace_and_prose_is_not():
    from sartco.world.render import grid_text
    grid = grid_text({"1:1": [["washer", "blue"]]}, 3, 3)
    html = rendered(f"The board you built:\n{grid}\n\nWrite the code again.")
    blocks = [(b.split('"')[0], b.split(">", 1)[1].split("</div>")[0]) for b in html.split('<div class="')[1:]]
    assert [kind for kind, _ in blocks] == ["sartco-prose", "sartco-text", "sartco-prose"]
    assert blocks[1][1].strip() == grid.replace("'", "&#x27;") or blocks[1][1].strip() == grid
    assert "monospace" not in html.split('<div class="sartco-prose"')[1].split(">")[0]


def test_prose_around_blocks_and_an_unclosed_fence():
    html = rendered("Sure:\n```python\nput(board, 'nut', 'red', 0, 0)\n```\nThat is all.\n```python\nput(")
    assert html.count('class="sartco-code"') == 1  # the unclosed one stays text, verbatim
    assert "Sure:" in html and "That is all." in html and "```python\nput(</div>" in html


def test_model_markup_is_escaped():
    html = rendered("<script>alert(1)</script> <img src=x onerror=alert(2)> *not emphasis* `x`")
    assert "<script>" not in html and "<img" not in html and "<em>" not in html
    assert "&lt;script&gt;" in html
