// What every fuzz target asserts beyond "no crash": a design the library returned writes with
// finite numbers. An Error there is a defect, not an input error, so the target aborts and
// libFuzzer keeps the input.
#pragma once

#include <cstdlib>

#include "trebuchet/error.hpp"

template <class Write>
void require_writes(Write write) {
  try {
    write();
  } catch (const trebuchet::Error&) {
    std::abort();
  }
}
