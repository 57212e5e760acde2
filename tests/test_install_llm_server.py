"""``.ci/install-llm-server`` says how long its quiet source build has run while it builds, on
stderr, and still prints the venv's python as its last stdout line (what
``tests/llm_server/llama_server.py`` reads). The build is played by a stand-in ``python`` in
the venv whose ``pip install`` of llama-cpp-python takes a few seconds, so nothing is built."""

from __future__ import annotations

import os
import re
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BUILD_S = 1  # a second of "build", with a progress line every quarter second

# The stand-in answers the script's three uses of the venv's python: the probe (`python -`),
# `-m pip install` (the llama.cpp build takes BUILD_S seconds) and nothing else.
STAND_IN = f"""#!/usr/bin/env bash
here="$(cd "$(dirname "$0")" && pwd)"
if [[ "$1" == "-" ]]; then
    cat >/dev/null
    [[ -e "$here/built" ]] || exit 1
    echo "0.3.16 0.1.2 $here/model.gguf"
    exit 0
fi
if [[ "$*" == *"--no-binary llama-cpp-python"* ]]; then
    sleep {BUILD_S}
    touch "$here/built"
fi
exit 0
"""


def test_the_build_prints_progress_and_the_python_path_last(tmp_path: Path) -> None:
    venv = tmp_path / "venv"
    (venv / "bin").mkdir(parents=True)
    python = venv / "bin" / "python"
    python.write_text(STAND_IN)
    python.chmod(0o755)
    env = {
        **os.environ,
        "LLM_SERVER_VENV": str(venv),
        "LLM_SERVER_HEARTBEAT_S": "0.25",
        "LLAMA_CPP_VERSION": "0.3.16",
        "SMOLLM2_VERSION": "0.1.2",
    }
    out = subprocess.run(
        ["bash", str(ROOT / ".ci" / "install-llm-server")],
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert out.returncode == 0, out.stderr
    assert out.stdout.splitlines()[-1] == str(python)
    assert "about 6 min on 2 quiet cores, up to 25 min" in out.stderr
    beats = re.findall(r"still building llama\.cpp, 0 min 0\d s so far", out.stderr)
    assert beats, out.stderr
    assert "still building" not in out.stderr.splitlines()[-1]  # it stopped with the build
