#include "trebuchet/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace trebuchet {

int thread_count(int requested, std::size_t items) {
  const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t cap = std::max<std::size_t>(1, std::min(cores, items));
  return static_cast<int>(std::clamp<std::size_t>(static_cast<std::size_t>(std::max(requested, 1)), 1, cap));
}

void for_each_index(std::size_t count, int threads, const std::function<void(std::size_t)>& work, const Progress& progress) {
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex lock_of_shared;  // the failure and the progress
  std::size_t done = 0;
  auto worker = [&] {
    for (std::size_t i = next++; i < count; i = next++) {
      try {
        work(i);
        if (progress) {
          const std::lock_guard<std::mutex> lock(lock_of_shared);
          progress(++done, count);
        }
      } catch (...) {
        const std::lock_guard<std::mutex> lock(lock_of_shared);
        if (!failure) failure = std::current_exception();
        next = count;  // stop claiming
      }
    }
  };
  std::vector<std::thread> helpers;
  for (int t = 1; t < thread_count(threads, count); ++t) helpers.emplace_back(worker);
  worker();
  for (std::thread& h : helpers) h.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace trebuchet
