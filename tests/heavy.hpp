// The heavy unit tests (Catch2 tag [heavy], CTest label heavy; docs/testing.md): tests of a
// second of CPU or more in Release, which the sanitizer pass runs in part. Each runs its cases
// one in every TREBUCHET_HEAVY_STRIDE (scripts/test.sh sets 4 under the sanitizers; 1, all of
// them, by default): the same code paths at a fraction of the cost under AddressSanitizer.
#pragma once

#include <algorithm>
#include <cstdlib>

/// Whether the heavy test's case number `index` (from 0) runs in this pass: every case by
/// default, one in every TREBUCHET_HEAVY_STRIDE where it is set. Case 0 always runs.
inline bool heavy_case_runs(int index) {
  const char* text = std::getenv("TREBUCHET_HEAVY_STRIDE");
  const int stride = text ? std::max(1, std::atoi(text)) : 1;
  return index % stride == 0;
}
