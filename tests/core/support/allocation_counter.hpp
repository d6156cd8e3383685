#pragma once
// Counts heap allocations, for the tests that a step (or a scan's ray casting and ICP) never
// touches the heap. The program that links allocation_counter.cpp has the global
// operator new replaced by one that counts while counting is on; only that program may.

#include <utility>

namespace legofeup::testing {

/// Resets the count to 0 and counts every operator new / new[] from now on.
void start_counting_allocations();
/// Stops counting and returns the allocations since start_counting_allocations().
long stop_counting_allocations();

/// The allocations `work()` makes.
template <class Work>
long allocations_of(Work&& work) {
    start_counting_allocations();
    std::forward<Work>(work)();
    return stop_counting_allocations();
}

}  // namespace legofeup::testing
