-- wrk script for bench/redis-load.sh's warm figure: every request another view of one
-- draped outfit (the drape is cached; only staging and rendering are done).
local counter = 0

function init(args)
  counter = math.random(0, 3600)
end

function request()
  counter = counter + 1
  return wrk.format("GET", string.format("/api/render?stature=1.650&outfit=dress:M&size=400x300&view=%.1f,10",
                                         (counter % 3600) / 10))
end
