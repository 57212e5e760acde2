# AssistantX on embedded defaults: `docker run -p 8000:8000 IMAGE`.
#
# Two stages. `build` makes the app's wheel (it carries the default office, map and prompts as
# package data) and installs it with its dependencies into a virtualenv at /opt/venv; the final
# stage copies only that virtualenv onto a fresh slim Python: no source tree, no wheels, no
# pip cache, no compilers or build tools (every dependency installs from a binary wheel; if one
# ever needs compiling, the tools go into `build`, never below).
#
# HEALTHCHECK is part of Docker's image format only: `docker build` keeps it, while Podman and
# Buildah write OCI images by default and drop it with a warning. Build with
# `podman build --format docker -t assistantx .` (or `buildah bud --format docker`) to keep it,
# or let the orchestrator probe GET /healthz itself.
FROM python:3.11-slim AS build
ENV PIP_NO_CACHE_DIR=1 \
    PIP_DISABLE_PIP_VERSION_CHECK=1
WORKDIR /src
COPY pyproject.toml README.md ./
COPY src ./src
COPY dataset ./dataset
COPY maps ./maps
COPY prompts ./prompts
# Then what the service never runs goes: the libraries' own test suites, pip and setuptools.
# The bytecode pip compiled stays: the service's user cannot write it at run time.
RUN pip wheel --no-deps -w /wheels . \
    && python -m venv /opt/venv \
    && /opt/venv/bin/pip install --only-binary=:all: /wheels/*.whl \
    && rm -rf /opt/venv/lib/python3.11/site-packages/numpy/*/tests \
        /opt/venv/lib/python3.11/site-packages/numpy/tests \
        /opt/venv/lib/python3.11/site-packages/scipy/*/tests \
        /opt/venv/lib/python3.11/site-packages/scipy/*/*/tests \
        /opt/venv/lib/python3.11/site-packages/matplotlib/tests \
    && /opt/venv/bin/pip uninstall --yes pip setuptools

FROM python:3.11-slim

ENV PATH=/opt/venv/bin:/usr/local/bin:/usr/local/sbin:/usr/sbin:/usr/bin:/sbin:/bin \
    PYTHONDONTWRITEBYTECODE=1 \
    PYTHONUNBUFFERED=1 \
    ASSISTANTX_DATA_DIR=/data \
    ASSISTANTX_HOST=0.0.0.0 \
    ASSISTANTX_PORT=8000

COPY --from=build /opt/venv /opt/venv
RUN useradd --system --uid 10001 --home-dir /data --shell /usr/sbin/nologin assistantx \
    && mkdir -p /data && chown assistantx:assistantx /data

USER assistantx
WORKDIR /data
VOLUME ["/data"]
EXPOSE 8000
# Kept in Docker's image format only (see the top): `podman build --format docker`.
HEALTHCHECK --interval=30s --timeout=5s --start-period=20s --retries=3 \
    CMD ["python", "-c", "import urllib.request; urllib.request.urlopen('http://127.0.0.1:8000/healthz', timeout=4)"]
CMD ["assistantx", "serve", "--host", "0.0.0.0", "--port", "8000"]
