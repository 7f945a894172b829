"""The oracle of the sandbox's honest-program tests: a program run as a script under plain `exec`
(`__name__ == "__main__"`, the real modules), with a reference `put` that takes any integer as the
authors' simulator did (numpy's too). tests/program's construct, wrapper and conformance tests
compare the sandbox against it."""
import operator

from sartco.world import Board, put


def reference_put(board, shape, color, x, y):
    """put as the authors' simulator took coordinates: any integer, numpy's too."""
    return put(board, shape, color, operator.index(x), operator.index(y))


def plain_run(source: str) -> tuple[dict, int]:
    """The cells of the board that counts (the global `board` if it is a Board, else the last
    init_board) and how many puts the program made."""
    last, puts = [Board(8, 8)], []

    def counted_put(*args):
        reference_put(*args)
        puts.append(args)

    def init_board(rows=8, cols=8):
        last[0] = Board(rows, cols)
        return last[0]

    env = {"__name__": "__main__", "board": last[0], "put": counted_put, "init_board": init_board}
    exec(compile(source, "<honest>", "exec"), env)
    result = env.get("board")
    return (result if type(result) is Board else last[0]).cells(), len(puts)


def plain_exec(source: str) -> dict:
    """The cells plain exec builds."""
    return plain_run(source)[0]
