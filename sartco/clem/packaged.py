"""Backends and model registry entries that ship with sartco, so that clemcore finds them wherever
sartco is installed, beside the user's own model_registry.json and <backend>_api.py files.

clemcore 3.7 looks for backends (`<name>_api.py`) and for `model_registry.json` only in the working
directory and in its own package folder. sartco adds a third place, the folder `backends/` beside
this module, with the same layout:

    sartco/clem/backends/<name>_api.py        one Backend subclass (the module is loaded by its
                                              file path, as clemcore loads a working-directory
                                              backend: absolute imports only)
    sartco/clem/backends/model_registry.json  the entries of the models those backends serve

Lookup order, as clemcore's: the working directory first (a user's own entry or backend file of
the same name wins), then clemcore's packaged ones, then sartco's (lookup source "sartco").
`clem list models` / `clem list backends` show them with "(sartco)".

How: the installed file `sartco_clemcore.pth` (top of site-packages, put there by setup.py for
wheel and editable installs) runs `install_hook()` at interpreter start. The hook only waits for
`clemcore.backends` to be imported (nothing else is imported at start) and then extends
`ModelRegistry.from_packaged_and_cwd_files` and `BackendRegistry.from_packaged_and_cwd_files`,
the two functions every clemcore command and `clemcore.backends.load_models` ask. Nothing is
written into the user's working directory.

To add a backend: put `<name>_api.py` into sartco/clem/backends/ and, for the models it serves by
name, their entries into sartco/clem/backends/model_registry.json (users may also register
models of that backend in their own model_registry.json with `"backend": "<name>"`).
"""
from __future__ import annotations

import os
import sys

# imported at every interpreter start (the .pth): only os and sys here, the rest when needed
FOLDER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "backends")
LOOKUP_SOURCE = "sartco"
_TARGET = "clemcore.backends"


def backend_files() -> list[dict]:
    """sartco's backend files in clemcore's BackendRegistry form."""
    return [{"backend": name[: -len("_api.py")], "file_name": name, "file_path": os.path.join(FOLDER, name),
             "lookup_source": LOOKUP_SOURCE} for name in sorted(os.listdir(FOLDER)) if name.endswith("_api.py")]


def model_entries() -> list[dict]:
    """sartco's model registry entries (each a fresh dict: clemcore adds lookup_source to it)."""
    import json
    with open(os.path.join(FOLDER, "model_registry.json"), encoding="utf-8") as f:
        return json.load(f)


def extend(backends) -> None:
    """Make clemcore's registries (of the module clemcore.backends) list sartco's entries last."""
    model_registry, backend_registry = backends.ModelRegistry, backends.BackendRegistry
    if getattr(model_registry, "_sartco_extended", False):
        return
    clem_models = model_registry.from_packaged_and_cwd_files.__func__
    clem_backends = backend_registry.from_packaged_and_cwd_files.__func__

    def models(cls):
        registry = clem_models(cls)
        return registry.register_from_list(model_entries(), lookup_source=LOOKUP_SOURCE)

    def backend_files_of(cls):
        registry = clem_backends(cls)
        # the constructor appends clemcore's two internal entries (human, mock) again
        return cls([entry for entry in registry if entry["file_path"] != "_internal"] + backend_files())

    model_registry.from_packaged_and_cwd_files = classmethod(models)
    backend_registry.from_packaged_and_cwd_files = classmethod(backend_files_of)
    model_registry._sartco_extended = True


class _ExtendOnImport:
    """A meta path finder (importlib.abc.MetaPathFinder's protocol): finds clemcore.backends as the
    other finders do and extends it right after it ran."""

    def find_spec(self, name, path=None, target=None):
        if name != _TARGET:
            return None
        sys.meta_path.remove(self)  # once: the other finders find the module
        spec = None
        for finder in sys.meta_path:
            find = getattr(finder, "find_spec", None)
            spec = find(name, path, target) if find else None
            if spec is not None:
                break
        if spec is None or spec.loader is None or not hasattr(spec.loader, "exec_module"):
            return spec
        run = spec.loader.exec_module

        def exec_module(module):
            run(module)
            extend(module)

        spec.loader.exec_module = exec_module
        return spec


def install_hook() -> None:
    """Called at interpreter start by sartco_clemcore.pth; cheap: imports nothing of clemcore."""
    if _TARGET in sys.modules:
        extend(sys.modules[_TARGET])
    elif not any(isinstance(f, _ExtendOnImport) for f in sys.meta_path):
        sys.meta_path.insert(0, _ExtendOnImport())
