"""One package per game: all of a game's own code (its game master and benchmark, its episodes,
its instance files, its players and dialogue), over what every game shares (sartco.clem.core,
sartco.clem.players). The two games never import each other (tests/architecture/test_layers.py,
docs/ARCHITECTURE.md); games/<game>/master.py and instancegenerator.py, the files clemcore loads by
path, only name their game's package.

- instruct  cobot_instruct: master (CobotInstruct, CobotInstructBenchmark), episodes
            (instruct_episode), instruct_generator, instances (its instance files, `sartco
            instances instruct...`), fresh (fresh test boards), training (the gym env), paper
            (the paper protocol's game glue and scorer: finish_paper, PaperScorer)
- describe  cobot_describe: master (CobotDescribe, CobotDescribeBenchmark), describer, dialogue
            (the modes, the scorer), turns (the dialogue's state machine), dialogue_answers (mock
            and rule-based describer and builder), erring_dialogue, instances (its instance files,
            `sartco instances describe`)
"""
