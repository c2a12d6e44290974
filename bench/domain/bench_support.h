#pragma once
// Helpers shared by the domain benchmarks.

#include <cstdlib>
#include <iostream>

#include "domain/common/result.h"

namespace cutcalc::bench {

// Aborts the benchmark program when a set-up calculation fails: a benchmark of an error path
// would measure the wrong thing.
template <class T>
void require_ok(const cutcalc::domain::Result<T>& result, const char* what) {
  if (!result.ok()) {
    std::cerr << what << ": unexpected error: " << result.error().detail << "\n";
    std::abort();
  }
}

}  // namespace cutcalc::bench
