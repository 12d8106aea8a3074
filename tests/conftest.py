"""Test-session set-up: the verifier's result cache goes to a fresh temporary
folder, so the suite never reads a developer's ~/.cache/uwmr-symbolic (a stale
entry could mask a regression) and never writes there."""
import os
import shutil
import tempfile

_CACHE = tempfile.mkdtemp(prefix="uwmr-test-cache-")
os.environ["UWMR_CACHE_DIR"] = _CACHE


def pytest_unconfigure(config):
    shutil.rmtree(_CACHE, ignore_errors=True)
