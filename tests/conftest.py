"""Shared by every test folder: pytest puts this folder on sys.path (rootdir conftest, no
packages), so tests import the helpers beside it (play_helpers)."""
