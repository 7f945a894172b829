from dataclasses import dataclass, field

@dataclass(frozen=True)
class Step:
    shape: str
    color: str = 'yellow'
    cell: tuple = (0, 0)

@dataclass
class Plan:
    steps: list = field(default_factory=list)

plan = Plan()
plan.steps.append(Step('washer', cell=(1, 2)))
plan.steps.append(Step('nut', 'red', (1, 2)))
for step in plan.steps:
    put(board, step.shape, step.color, *step.cell)
