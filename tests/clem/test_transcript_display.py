"""Messages in clemcore's transcripts (sartco.clem.transcript.display): code as code with its
indentation, other text with its line breaks, model markup escaped."""
import markdown

from sartco.clem.transcript import display


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
    assert "Output:\nfor x in range(2):\n    put(board, 'nut', 'red', x, 0)\n\n# done" in html
    assert "white-space: pre-wrap" in html and "<p>" not in html  # not run together into a paragraph


def test_prose_around_blocks_and_an_unclosed_fence():
    html = rendered("Sure:\n```python\nput(board, 'nut', 'red', 0, 0)\n```\nThat is all.\n```python\nput(")
    assert html.count('class="sartco-code"') == 1  # the unclosed one stays text, verbatim
    assert "Sure:" in html and "That is all.\n```python\nput(" in html


def test_model_markup_is_escaped():
    html = rendered("<script>alert(1)</script> <img src=x onerror=alert(2)> *not emphasis* `x`")
    assert "<script>" not in html and "<img" not in html and "<em>" not in html
    assert "&lt;script&gt;" in html
