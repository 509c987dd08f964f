"""The server under test: `locus serve` started by .ci/steps/40-server.sh, its URL in
LOCUS_SERVER_URL."""
import os

import compute_rhino3d.Util
import pytest


@pytest.fixture(scope="session")
def server_url():
    url = os.environ.get("LOCUS_SERVER_URL")
    if not url:
        pytest.fail("LOCUS_SERVER_URL is not set: run .ci/steps/40-server.sh")
    compute_rhino3d.Util.url = url.rstrip("/") + "/"
    return url.rstrip("/")
