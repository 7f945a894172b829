import heapq
from dataclasses import dataclass, field


@dataclass(order=True)
class Job:
    priority: int
    pos: tuple = field(compare=False)
    color: str = field(compare=False, default="red")


jobs = [Job(3, (0, 0), "blue"), Job(1, (2, 2)), Job(2, (4, 4), "green")]
heapq.heapify(jobs)
while jobs:
    job = heapq.heappop(jobs)
    put(board, "washer", job.color, *job.pos)
