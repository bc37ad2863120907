// Host side of the sampler table (shaders/sampling/sampler_tables.h): its contents, generated at
// start-up (a prime sieve and the void-and-cluster mask, about 60 ms, once per
// process), and the GPU buffer that the table-driven samplers read.
#pragma once
#include <cstdint>
#include <vector>

#include "gpu/buffer.h"

namespace wf {

class Context;

// The first `count` primes, 2 first.
std::vector<uint32_t> firstPrimes(uint32_t count);

// The whole table with set size 0: built on first use, then shared (thread-safe).
const std::vector<uint32_t>& samplerTableContents();

// The table as a GPU buffer, with the given set size in its header.
Buffer makeSamplerTableBuffer(const Context& context, uint32_t setSize);
void setSamplerSetSize(Buffer& table, uint32_t setSize);

} // namespace wf
