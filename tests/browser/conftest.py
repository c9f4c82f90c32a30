"""Skips the browser test as a whole, with exit status 77 (ctest's
SKIP_RETURN_CODE for it), when what it drives is not installed."""

import shutil

import pytest


def missing():
    try:
        import selenium  # noqa: F401
    except ImportError:
        return "python3-selenium is not installed (Debian: python3-selenium)"
    if not (shutil.which("chromium") or shutil.which("chromium-browser")):
        return "chromium is not installed (Debian: chromium)"
    if not shutil.which("chromedriver"):
        return "chromedriver is not installed (Debian: chromium-driver)"
    return None


def pytest_sessionstart(session):
    reason = missing()
    if reason:
        pytest.exit("skipped: " + reason, returncode=77)
