# cutcalc container: build stage compiles the release binary from Debian packages only; the
# runtime stage holds the binary and its shared libraries and runs as a non-root user.
FROM debian:bookworm-slim AS build
COPY scripts/debian-packages-service.txt /tmp/
RUN apt-get update \
 && apt-get install -y --no-install-recommends $(grep -v '^\s*#' /tmp/debian-packages-service.txt) \
 && rm -rf /var/lib/apt/lists/*
WORKDIR /src
COPY CMakeLists.txt CMakePresets.json openapi.yaml ./
COPY cmake cmake
COPY domain domain
COPY api api
COPY service service
COPY web web
ARG CUTCALC_GIT_COMMIT=unknown
RUN cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCUTCALC_BUILD_TESTS=OFF \
      -DCUTCALC_GIT_COMMIT="${CUTCALC_GIT_COMMIT}" \
 && cmake --build build --target cutcalc \
 && strip build/service/cutcalc

FROM debian:bookworm-slim
RUN apt-get update \
 && apt-get install -y --no-install-recommends libcpp-httplib0.11 libspdlog1.10 libfmt9 \
 && rm -rf /var/lib/apt/lists/* \
 && useradd --system --uid 10001 --no-create-home --shell /usr/sbin/nologin cutcalc
COPY --from=build /src/build/service/cutcalc /usr/local/bin/cutcalc
USER 10001:10001
ENV CUTCALC_HOST=0.0.0.0 CUTCALC_PORT=8080 CUTCALC_LOG_FORMAT=json
EXPOSE 8080
# bash's /dev/tcp keeps the image free of an HTTP client just for the health check.
HEALTHCHECK --interval=10s --timeout=3s --start-period=5s --retries=3 \
  CMD ["bash", "-c", "exec 3<>/dev/tcp/127.0.0.1/8080 && printf 'GET /healthz HTTP/1.1\\r\\nHost: localhost\\r\\nConnection: close\\r\\n\\r\\n' >&3 && head -n 1 <&3 | grep -q ' 200 '"]
STOPSIGNAL SIGTERM
ENTRYPOINT ["/usr/local/bin/cutcalc"]
