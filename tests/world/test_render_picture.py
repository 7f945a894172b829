"""The board picture's content, without a browser (its look in Chromium at the transcript's real
width: tests/games/instruct/test_transcript_boards.py)."""
import re

from sartco.world.render import MIN_LABEL, MIN_WIDTH, diff_svg


def texts(svg: str) -> list[str]:
    return re.findall(r"<text[^>]*>([^<]*)</text>", svg)


def test_numbers_count_from_one_and_labels_read_at_the_narrowest_width():
    svg = diff_svg({"7:3": [["screw", "red"]]}, {})
    width = float(re.search(r'viewBox="0 0 ([\d.]+) ', svg).group(1))
    sizes = [float(s) for s in re.findall(r'font-size="([\d.]+)"', svg)]
    assert len(sizes) == len(texts(svg)) and min(sizes) * MIN_WIDTH / width >= MIN_LABEL  # every label
    numbers = [t for t in texts(svg) if t.isdigit()]
    assert numbers == [str(k) for k in range(1, 9)] * 4  # columns then rows, for each grid; no "0"


def test_a_stack_shows_each_piece_bottom_to_top_and_differing_cells_are_framed():
    stack = {"0:0": [["washer", "blue"], ["nut", "green"]]}
    svg = diff_svg(stack, {"0:0": [["nut", "green"], ["washer", "blue"]]})
    target = svg[:svg.index(">built<")]
    washer = re.search(r'<polygon points="[^"]*" fill="#1f77b4"', target).group(0)  # a diamond: 4 points
    nut = re.search(r'<polygon points="[^"]*" fill="#2ca02c"', target).group(0)     # a hexagon: 6 points
    assert washer.count(",") == 4 and nut.count(",") == 6
    def y(poly):
        return max(float(p.split(",")[1]) for p in re.search(r'points="([^"]*)"', poly).group(1).split())
    assert y(washer) > y(nut)  # the bottom piece lowest
    assert svg.count('stroke="#e0007a" stroke-width="3"') == 2 + 1  # the cell on both grids, the legend
    assert {"washer", "nut", "screw", "bridge", "red", "green", "blue", "yellow", "differs"} <= set(texts(svg))
