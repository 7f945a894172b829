"""The published SARTCo data (../shared/sartco-data: published/, gold_boards/), read where it lies.

    files.py     file names, reading a file, the one walk over a file's samples, gold boards
    samples.py   one published sample -> our board record (sartco.dataset.BoardRecord)
    defects.py   Defect and the rules that find the published data's defects
    importer.py  `sartco import SRC_DIR --out DIR`: the published files as a dataset
    gold.py      every gold program of the published files with its gold board (conformance, benches)

Layer: above sartco.instances (the dataset writer, the gold-code runner, the overlap check) and
sartco.program; below sartco.scores and sartco.paper.
"""
