// Work on independent items spread over the cores, each result in its own slot, so that the
// output cannot depend on the order in which items finish (the sweep, arrays of designs).
#pragma once

#include <cstddef>
#include <functional>

namespace trebuchet {

/// The threads worth using for `items` items when `requested` are asked for: at least 1, at
/// most the cores and the items; more would only wait.
int thread_count(int requested, std::size_t items);

/// Told progress(done, total) after each item of long work, from one thread at a time.
using Progress = std::function<void(std::size_t done, std::size_t total)>;

/// Calls work(i) once for every i in [0, count), on thread_count(threads, count) threads, each
/// taking the next unclaimed index. `work` must write only to slot i. An exception thrown by
/// work is rethrown here, the first one, after every thread has stopped. `progress`, when
/// given, hears of every item done.
void for_each_index(std::size_t count, int threads, const std::function<void(std::size_t)>& work, const Progress& progress = {});

}  // namespace trebuchet
