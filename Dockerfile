# AssistantX on embedded defaults: `docker run -p 8000:8000 IMAGE`.
# Stage 1 builds a wheel (it carries the default office, map and prompts as package data);
# stage 2 installs it as a regular package, with no source tree in the image.
FROM python:3.11-slim AS build
WORKDIR /src
COPY pyproject.toml README.md ./
COPY src ./src
COPY dataset ./dataset
COPY maps ./maps
COPY prompts ./prompts
RUN pip wheel --no-cache-dir --no-deps -w /wheels .

FROM python:3.11-slim

ENV PYTHONDONTWRITEBYTECODE=1 \
    PYTHONUNBUFFERED=1 \
    PIP_NO_CACHE_DIR=1 \
    ASSISTANTX_DATA_DIR=/data \
    ASSISTANTX_HOST=0.0.0.0 \
    ASSISTANTX_PORT=8000

COPY --from=build /wheels /wheels
RUN pip install /wheels/*.whl \
    && rm -rf /wheels \
    && useradd --system --uid 10001 --home-dir /data --shell /usr/sbin/nologin assistantx \
    && mkdir -p /data && chown assistantx:assistantx /data

USER assistantx
WORKDIR /data
VOLUME ["/data"]
EXPOSE 8000
HEALTHCHECK --interval=30s --timeout=5s --start-period=20s --retries=3 \
    CMD ["python", "-c", "import urllib.request; urllib.request.urlopen('http://127.0.0.1:8000/healthz', timeout=4)"]
CMD ["assistantx", "serve", "--host", "0.0.0.0", "--port", "8000"]
