#pragma once
// The time of a message between two ranks (dpdBenchmark -pingpong): rank 0 sends `bytes` to rank 1,
// which sends them back, `repeats` times; half the mean round trip is the one-way time, whose
// small-message limit is the latency and whose large-message slope the inverse bandwidth (the
// scaling model of docs/parallel.md section 5 takes both from here).
#include <cstddef>

namespace dpd {

class Communicator;

// One-way seconds per message of `bytes` between ranks 0 and 1 (the others wait); the same value on
// every rank. Throws std::invalid_argument on fewer than two ranks.
double oneWaySeconds(const Communicator& comm, std::size_t bytes, int repeats);

}  // namespace dpd
