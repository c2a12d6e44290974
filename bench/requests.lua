-- wrk script for bench/http_bench.sh --endpoints and bench/soak.sh: sends the requests listed in
-- a file, round-robin (each wrk thread starts at a different line), and prints one
-- machine-readable line at the end (same format as bench/wrk_post.lua):
-- WRK_RESULT {"requests":..,"duration_us":..,"rps":..,"p50_us":..,"p99_us":..,"max_us":..,
--             "non2xx":..,"connect":..,"read":..,"write":..,"timeout":..}
--
-- usage: wrk [options] -s bench/requests.lua http://HOST:PORT -- REQUESTS_FILE
-- REQUESTS_FILE: one request per line, four tab-separated fields:
--   METHOD <tab> PATH <tab> ACCEPT (or -) <tab> BODY (one line; may be empty for GET)
-- A POST gets Content-Type: application/json.

local requests = {}
local next_index = 1
local thread_counter = 0

function setup(thread)
  thread_counter = thread_counter + 1
  thread:set("thread_number", thread_counter)
end

local function split_tabs(line)
  local fields = {}
  local start = 1
  for _ = 1, 3 do
    local tab = string.find(line, "\t", start, true)
    if tab == nil then return nil end
    fields[#fields + 1] = string.sub(line, start, tab - 1)
    start = tab + 1
  end
  fields[#fields + 1] = string.sub(line, start)
  return fields
end

function init(args)
  local path = args[1]
  if path == nil then
    error("requests.lua: pass the requests file after --")
  end
  local file = assert(io.open(path, "r"))
  for line in file:lines() do
    line = string.gsub(line, "\r$", "")
    if line ~= "" and string.sub(line, 1, 1) ~= "#" then
      local f = split_tabs(line)
      if f == nil then error("requests.lua: bad line in " .. path .. ": " .. line) end
      local headers = {}
      if f[3] ~= "-" and f[3] ~= "" then headers["Accept"] = f[3] end
      local body = nil
      if f[1] == "POST" or f[1] == "PUT" then
        headers["Content-Type"] = "application/json"
        body = f[4]
      end
      requests[#requests + 1] = wrk.format(f[1], f[2], headers, body)
    end
  end
  file:close()
  if #requests == 0 then error("requests.lua: no requests in " .. path) end
  next_index = ((thread_number or 1) - 1) % #requests + 1
end

function request()
  local r = requests[next_index]
  next_index = next_index % #requests + 1
  return r
end

function done(summary, latency, requests_done)
  local e = summary.errors
  io.write(string.format(
    'WRK_RESULT {"requests":%d,"duration_us":%d,"rps":%.2f,"p50_us":%d,"p99_us":%d,' ..
    '"max_us":%d,"non2xx":%d,"connect":%d,"read":%d,"write":%d,"timeout":%d}\n',
    summary.requests, summary.duration, summary.requests / (summary.duration / 1e6),
    latency:percentile(50), latency:percentile(99), latency.max,
    e.status, e.connect, e.read, e.write, e.timeout))
end
