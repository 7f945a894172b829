"""One package per game: all of a game's own code (its game master and benchmark, its episodes,
its instance files, its players and dialogue), over what every game shares (sartco.clem.core,
sartco.clem.players). The two games never import each other (tests/architecture/test_layers.py,
docs/ARCHITECTURE.md); games/<game>/master.py and instancegenerator.py, the files clemcore loads by
path, only name their game's package.

Each game's files are named by role, as clembench's games are: master (the game master and its
benchmark), scorer (what `clem score` computes), players (where the game has players of its own),
instancegenerator (its instance files: the one generator module of the game; the functions of
`sartco instances`), then what the game alone has.

- instruct  cobot_instruct: master (CobotInstruct, CobotInstructBenchmark), scorer (InstructScorer),
            instancegenerator (instruct_episode, InstructGenerator, one function per file of
            `sartco instances instruct...`), fresh (the contamination file: fresh test boards),
            paper (the paper protocol's game glue: finish_paper), training (the gym env)
- describe  cobot_describe: master (CobotDescribe, CobotDescribeBenchmark), scorer (DescribeScorer,
            DialogueScorer), players (the Describer; the mock and rule-based describer and
            builder), instancegenerator (`sartco instances describe`), dialogue (the modes, reading
            every turn, the texts), turns (the dialogue's state machine), erring_dialogue (`-m erring`)
"""
