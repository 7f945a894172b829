"""The error every layer raises for a mistake in the user's input (config, dataset file, instance
file, command-line value). The `sartco` command prints it as one line, without a traceback, and
exits with code 2. Free of dependencies: the bottom layer, beside sartco.dataset."""


class UserError(Exception):
    """A mistake in the user's input: printed as one line, no traceback, exit code 2."""
