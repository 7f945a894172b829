"""The template holds only what a program's process can reach (issue 46): every child is forked
from it, and each of its pages is a page table entry to copy at each fork and to tear down at each
exit. The parent's modules (the pool, the template handles, subprocess, threads, the filter's
compiler) stay in the parent: `sartco.program` imports them on first use."""
import json
import subprocess
import sys

import pytest

from sartco.program import handle

PARENTS = {"sartco.program.pool", "sartco.program.handle", "sartco.program.sandbox", "sartco.program.cluster",
           "sartco.program.compiled", "sartco.program.serve", "subprocess", "threading", "concurrent.futures",
           "tempfile", "pyseccomp"}


@pytest.mark.parametrize("entry", ["sartco.program.child.template", "sartco.program.child.stages"])
def test_the_template_imports_none_of_the_parents_modules(entry):
    # the template's own start (handle._BOOT) up to its frozen heap, with a filter it never applies;
    # also in a stage process of `sartco bench-execute --breakdown`, which must weigh what a template does
    probe = ("import json, sys; sys.path.insert(0, sys.argv[1]); "
             f"import {entry}; from sartco.program.child.template import Template; Template(bytes(8)); "
             "print(json.dumps(sorted(sys.modules)))")
    done = subprocess.run([sys.executable, *handle.ISOLATED, "-c", probe, handle._ROOT], env=handle.ENVIRONMENT,
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    modules = set(json.loads(done.stdout))
    assert "sartco.program.child.runtime" in modules   # what the children run is there
    assert modules & PARENTS == set()
