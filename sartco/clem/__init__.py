"""What the SARTCo games share in clemcore (installed, because clemcore unloads modules that live
inside a game folder; each game's own code is its package in sartco.games), one package per thing
it serves; lower packages never import higher ones (tests/architecture/test_layers.py,
docs/ARCHITECTURE.md):

- core      the game core any game whose player writes code reuses:
            master.BuildGameMaster and benchmark.BuildBenchmark (the two bases every game's
            master.py inherits; the benchmark checks the instance file up front and writes
            run.json), errors (the core's exceptions: ParseError, HarnessFault,
            InstanceFileError, ProvenanceError), parsing.parse_code (no code -> aborted;
            answer_lines: what one line is), outcomes (the one ErrorCode -> clemcore outcome
            translation), harness.HarnessGuard (harness faults -> harness_error, never the model's
            error), building (build_for, parse_failure_for, record_build (the one way to record a
            build), BuildRecord), feedback.feedback_for / max_attempts, scoring.BuildScorer, probes
            (function probes), card.ScoreCard, transcript.MarkdownTranscript, pictures.attach_all,
            instance_checks (an instance file's fields and values, checked before play; check:
            `sartco check-instances`), instance_files (what both games' instance files share:
            the generators' base, board_fields, written), provenance (run.json written), runs
            (run.json read back), sandbox (the one door into sartco.program)
- players   sourced.Builder / SourcedPlayer (a built-in player's answers come from one answer
            source chosen when it is made), answers (Scripted, GoldCode = mock, InstructFollower =
            rulebased), erring (seeded mistakes and repairs, `-m erring`)
- tooling   batching (`openai_batching`), rulebased (`-m rulebased`, `-m erring`), stub_server,
            benchrun (`sartco bench-run`), sampling, resume, completeness
- backends/  the backend files and model entries that `sartco register DIR` writes into DIR,
            where clemcore finds them (sartco.register)
"""
