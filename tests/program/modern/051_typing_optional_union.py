from typing import Dict, List, Optional, Tuple, Union

Coord = Tuple[int, int]


def parse(spec: Union[str, Coord]) -> Optional[Coord]:
    if isinstance(spec, str):
        if "," not in spec:
            return None
        a, b = spec.split(",")
        return int(a), int(b)
    return spec


plan: Dict[str, List[Union[str, Coord]]] = {"red": ["1,2", (3, 4), "bad"], "blue": [(5, 5)]}
for color, specs in plan.items():
    for spec in specs:
        c = parse(spec)
        if c is not None:
            put(board, "washer", color, *c)
