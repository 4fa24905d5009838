-- wrk script for bench/serve-load.sh's overload: every request a new body (a cold drape),
-- so the service is far past its capacity; counts the answers by status.
local counter = 0
statuses = {}  -- global: done() reads each thread's through thread:get

function init(args)
  counter = math.random(0, 1000000)
end

function request()
  counter = counter + 1
  local stature = 1.50 + (counter % 380) / 1000
  local hips = 0.85 + (math.floor(counter / 380) % 250) / 1000
  return wrk.format("GET", string.format("/api/render?stature=%.3f&hips=%.3f&outfit=dress:M", stature, hips))
end

function response(status, headers, body)
  statuses[status] = (statuses[status] or 0) + 1
end

local threads = {}

function setup(thread)
  table.insert(threads, thread)
end

function done(summary, latency, requests)
  local total = {}
  for _, thread in ipairs(threads) do
    local counts = thread:get("statuses")
    for status, n in pairs(counts) do total[status] = (total[status] or 0) + n end
  end
  for status, n in pairs(total) do io.write(string.format("status %d: %d\n", status, n)) end
end
