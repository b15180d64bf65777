// The threads of a campaign (fuzz/campaign.h) and of a league (league/league.h): `jobs` workers
// each run work(k), k = 0 .. jobs-1, while the calling thread calls tick() about every 20 ms
// (progress lines, checkpoints) until every worker has returned. What the workers share and how
// they take their runs is the caller's.
#pragma once

#include <functional>

namespace mg::fuzz {

// The first exception a worker throws is rethrown here once every worker has returned;
// on_failure() is called at once, on that worker's thread, so that the others can stop early.
void run_workers(int jobs, const std::function<void(int worker)>& work, const std::function<void()>& tick,
                 const std::function<void()>& on_failure);

}  // namespace mg::fuzz
