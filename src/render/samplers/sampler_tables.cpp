#include "render/samplers/sampler_tables.h"

#include <algorithm>

#include "render/samplers/blue_noise.h"
#include "shaders/sampling/sampler_tables.h"

namespace wf {

std::vector<uint32_t> firstPrimes(uint32_t count) {
    std::vector<uint32_t> primes;
    for (uint32_t candidate = 2; primes.size() < count; ++candidate) {
        bool prime = true;
        for (uint32_t p : primes) {
            if (p * p > candidate)
                break;
            if (candidate % p == 0) {
                prime = false;
                break;
            }
        }
        if (prime)
            primes.push_back(candidate);
    }
    return primes;
}

const std::vector<uint32_t>& samplerTableContents() {
    // A function-local static: built once, thread-safe, only by processes that need it.
    static const std::vector<uint32_t> table = [] {
        std::vector<uint32_t> values(WF_SAMPLER_TABLE_SIZE, 0u);
        const std::vector<uint32_t> primes = firstPrimes(WF_SAMPLER_PRIME_COUNT);
        std::copy(primes.begin(), primes.end(), values.begin() + WF_SAMPLER_TABLE_PRIMES);
        // Sigma 1.5 (Ulichney); the seed only picks the initial random pattern.
        const std::vector<uint32_t> mask = voidAndClusterMask(WF_BLUE_NOISE_SIZE, 1.5, 1);
        std::copy(mask.begin(), mask.end(), values.begin() + WF_SAMPLER_TABLE_BLUE_NOISE);
        return values;
    }();
    return table;
}

Buffer makeSamplerTableBuffer(const Context& context, uint32_t setSize) {
    Buffer table(context, "sampler table", WF_SAMPLER_TABLE_SIZE * sizeof(uint32_t));
    setSamplerSetSize(table, setSize);
    return table;
}

void setSamplerSetSize(Buffer& table, uint32_t setSize) {
    std::vector<uint32_t> values = samplerTableContents();
    values[WF_SAMPLER_TABLE_SET_SIZE] = setSize;
    table.upload(values);
}

namespace gpu_types {
uint samplerTable(uint index) { return samplerTableContents()[index]; }
} // namespace gpu_types

} // namespace wf
