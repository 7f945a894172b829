"""Everything is declared in pyproject.toml; this file only copies what the package needs at run
time from the checkout into a wheel (sartco.settings reads them from the checkout in an editable
install): resources/ (generation templates and configs) as sartco/resources/, and the game
folders' files (clemgame.json, master.py, instancegenerator.py, README.md; not their instances) as
sartco/games/<game>/, which `sartco games DIR` copies to a folder of the user's."""
import sys
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
from sartco.settings import GAME_FILES, GAME_NAMES  # noqa: E402  (the one list of what ships)


def shipped() -> list[tuple[Path, str]]:
    """(file in the checkout, its path inside the package)."""
    files = [(path, str(Path("resources") / path.relative_to(HERE / "resources")))
             for path in sorted((HERE / "resources").rglob("*")) if path.is_file() and "__pycache__" not in path.parts]
    files += [(HERE / "games" / game / name, str(Path("games") / game / name)) for game in GAME_NAMES for name in GAME_FILES]
    return files


class build_py_with_data(build_py):
    def run(self):
        super().run()
        if not self.editable_mode:
            for source, inside in shipped():
                target = Path(self.build_lib) / "sartco" / inside
                self.mkpath(str(target.parent))
                self.copy_file(str(source), str(target), preserve_mode=False)

    def get_outputs(self, include_bytecode=True):
        extra = [] if self.editable_mode else [str(Path(self.build_lib) / "sartco" / inside) for _, inside in shipped()]
        return super().get_outputs(include_bytecode) + extra


setup(cmdclass={"build_py": build_py_with_data})
