// Tables spread over several buffers ("pages") where one would pass the device's limit: the
// paging rule, and upload and binding, a buffer a page, bound at the table's first binding and
// then at its consecutive page bindings (paged_table.glsl declares them in the shaders).
#pragma once
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/compute_program.h"

namespace wf {

// How a table of entries spreads over buffers: `count` pages of 2^shift entries (shift 31 and
// one page when it fits in one buffer).
struct TablePages {
    uint32_t count = 1;
    uint32_t shift = 31;
    uint64_t entriesPerPage() const { return uint64_t(1) << shift; }
    bool operator==(const TablePages&) const = default;
};

// The pages `entries` entries of `entryBytes` need where one buffer holds at most `pageBytes`;
// InputError naming the table and the limit past WF_MAX_TABLE_PAGES pages.
TablePages tablePaging(uint64_t entries, uint64_t entryBytes, uint64_t pageBytes,
                       const char* table);

// `values` cut into `pages`, a buffer each ("triangles", "triangles page 2", ...). A page past
// the end of `values` (a table shorter than the one whose paging it follows) gets one
// value-initialised entry, so that every page the shaders declare is bound.
template <typename T>
std::vector<Buffer> uploadPages(const Context& context, const std::string& name,
                                const std::vector<T>& values, const TablePages& pages) {
    std::vector<Buffer> buffers;
    for (uint32_t page = 0; page < pages.count; ++page) {
        const uint64_t first = uint64_t(page) * pages.entriesPerPage();
        const uint64_t count =
            first < values.size() ? std::min<uint64_t>(values.size() - first, pages.entriesPerPage())
                                  : 0;
        const std::string pageName = page == 0 ? name : name + " page " + std::to_string(page + 1);
        if (count == 0) {
            const std::vector<T> filler(1);
            buffers.emplace_back(context, pageName, sizeof(T));
            buffers.back().upload(filler.data(), sizeof(T));
            continue;
        }
        buffers.emplace_back(context, pageName, count * sizeof(T));
        buffers.back().upload(values.data() + first, count * sizeof(T));
    }
    return buffers;
}

// Page 0 at `firstBinding`, page k at `otherBindings` + k - 1.
void bindPages(DescriptorBindings& bindings, const std::vector<Buffer>& pages,
               uint32_t firstBinding, uint32_t otherBindings,
               BufferAccess access = BufferAccess::UintTexels);

} // namespace wf
