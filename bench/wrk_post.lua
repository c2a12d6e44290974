-- wrk script for bench/http_bench.sh, bench/engine_compare.sh and bench/http_rootcause.sh: POSTs
-- a JSON body (Content-Type: application/json) to the URL's path, and prints one
-- machine-readable line at the end:
-- WRK_RESULT {"requests":..,"duration_us":..,"rps":..,"p50_us":..,"p99_us":..,"max_us":..,
--             "non2xx":..,"connect":..,"read":..,"write":..,"timeout":..}
--
-- usage: wrk [options] -s bench/wrk_post.lua http://HOST:PORT/PATH -- 'BODY'
--        or the body in the environment: WRK_POST_BODY='BODY' wrk [options] -s ... URL
-- The body is sent as given (no default here: each caller states its body once).
wrk.method = "POST"
wrk.headers["Content-Type"] = "application/json"

-- wrk formats the request after init, so the body set here is in every request.
function init(args)
  local body = args[1]
  if body == nil or body == "" then body = os.getenv("WRK_POST_BODY") end
  if body == nil or body == "" then
    io.stderr:write("wrk_post.lua: no body: pass it after -- or in WRK_POST_BODY\n")
    os.exit(2)
  end
  wrk.body = body
end

function done(summary, latency, requests)
  local e = summary.errors
  io.write(string.format(
    'WRK_RESULT {"requests":%d,"duration_us":%d,"rps":%.2f,"p50_us":%d,"p99_us":%d,' ..
    '"max_us":%d,"non2xx":%d,"connect":%d,"read":%d,"write":%d,"timeout":%d}\n',
    summary.requests, summary.duration, summary.requests / (summary.duration / 1e6),
    latency:percentile(50), latency:percentile(99), latency.max,
    e.status, e.connect, e.read, e.write, e.timeout))
end
