"""Everything is declared in pyproject.toml; this file only ships sartco_clemcore.pth at the top
of site-packages, in wheels and in editable installs (pip install -e), so that clemcore finds the
backends and models that come with sartco (sartco/clem/packaged.py explains the mechanism)."""
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py
from setuptools.command.editable_wheel import editable_wheel

PTH = "sartco_clemcore.pth"
HERE = Path(__file__).resolve().parent


class build_py_with_pth(build_py):
    """A wheel: the .pth beside the packages (the top of site-packages once installed)."""

    def run(self):
        super().run()
        if not self.editable_mode:
            self.copy_file(str(HERE / PTH), str(Path(self.build_lib) / PTH), preserve_mode=False)

    def get_outputs(self, include_bytecode=True):
        extra = [] if self.editable_mode else [str(Path(self.build_lib) / PTH)]
        return super().get_outputs(include_bytecode) + extra


class _WithPth:
    """An editable install's wheel holds only setuptools' finder: add the .pth to it."""

    def __init__(self, strategy):
        self.strategy = strategy

    def __call__(self, wheel, files, mapping):
        self.strategy(wheel, files, mapping)
        wheel.writestr(PTH, (HERE / PTH).read_bytes())

    def __enter__(self):
        self.strategy.__enter__()
        return self

    def __exit__(self, *exc):
        return self.strategy.__exit__(*exc)


class editable_wheel_with_pth(editable_wheel):
    def _select_strategy(self, *args, **kwargs):
        return _WithPth(super()._select_strategy(*args, **kwargs))


setup(cmdclass={"build_py": build_py_with_pth, "editable_wheel": editable_wheel_with_pth})
