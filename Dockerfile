# AssistantX on embedded defaults: `docker run -p 8000:8000 IMAGE`.
FROM python:3.11-slim

ENV PYTHONDONTWRITEBYTECODE=1 \
    PYTHONUNBUFFERED=1 \
    PIP_NO_CACHE_DIR=1 \
    ASSISTANTX_DATA_DIR=/data \
    ASSISTANTX_HOST=0.0.0.0 \
    ASSISTANTX_PORT=8000

WORKDIR /app
COPY . /app
# An editable install keeps dataset/, maps/ and prompts/ next to the package, where it looks
# for the default office, map and prompts.
RUN pip install -e . \
    && useradd --system --uid 10001 --home-dir /app --shell /usr/sbin/nologin assistantx \
    && mkdir -p /data && chown assistantx:assistantx /data

USER assistantx
VOLUME ["/data"]
EXPOSE 8000
HEALTHCHECK --interval=30s --timeout=5s --start-period=20s --retries=3 \
    CMD ["python", "-c", "import urllib.request; urllib.request.urlopen('http://127.0.0.1:8000/healthz', timeout=4)"]
CMD ["assistantx", "serve", "--host", "0.0.0.0", "--port", "8000"]
