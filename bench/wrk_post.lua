-- wrk script for bench/http_bench.sh: POSTs the benchmark body to the URL's path, and prints one
-- machine-readable line at the end:
-- WRK_RESULT {"requests":..,"duration_us":..,"rps":..,"p50_us":..,"p99_us":..,"max_us":..,
--             "non2xx":..,"connect":..,"read":..,"write":..,"timeout":..}
wrk.method = "POST"
wrk.body = '{"cutter_diameter_mm": 20, "offset_mm": 0, "entry": {"contour": "straight", "width_mm": 60, "angle_deg": 90}}'
wrk.headers["Content-Type"] = "application/json"

function done(summary, latency, requests)
  local e = summary.errors
  io.write(string.format(
    'WRK_RESULT {"requests":%d,"duration_us":%d,"rps":%.2f,"p50_us":%d,"p99_us":%d,' ..
    '"max_us":%d,"non2xx":%d,"connect":%d,"read":%d,"write":%d,"timeout":%d}\n',
    summary.requests, summary.duration, summary.requests / (summary.duration / 1e6),
    latency:percentile(50), latency:percentile(99), latency.max,
    e.status, e.connect, e.read, e.write, e.timeout))
end
