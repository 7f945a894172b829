from typing import List, Tuple


def plan() -> List[Tuple[str, str, int, int]]:
    return [("washer", "red", 3, 3), ("nut", "blue", 3, 3), ("screw", "green", 3, 3)]


def main() -> None:
    for step in plan():
        put(board, *step)


if __name__ == "__main__":
    main()
