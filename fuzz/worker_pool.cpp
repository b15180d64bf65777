#include "fuzz/worker_pool.h"

#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "core/demand.h"

namespace mg::fuzz {

void run_workers(int jobs, const std::function<void(int worker)>& work, const std::function<void()>& tick,
                 const std::function<void()>& on_failure) {
  MG_DEMAND(jobs >= 1);
  std::atomic<int> active{jobs};
  std::mutex mutex;
  std::exception_ptr error;
  std::vector<std::thread> threads;
  threads.reserve(static_cast<std::size_t>(jobs));
  for (int k = 0; k < jobs; ++k)
    threads.emplace_back([&, k] {
      try {
        work(k);
      } catch (...) {
        {
          const std::lock_guard lock(mutex);
          if (!error) error = std::current_exception();
        }
        if (on_failure) on_failure();
      }
      --active;
    });
  while (active.load() > 0) {
    if (tick) tick();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  for (std::thread& t : threads) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace mg::fuzz
